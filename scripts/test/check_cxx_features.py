#!/usr/bin/env python3
"""Fails on library features newer than the oldest toolchain the package supports.

The oldest target is ROS Noetic on Ubuntu 20.04: GCC 9.4 / libstdc++ 9, Eigen 3.3.7,
Python 3.8. Debian 12 (GCC 12, Eigen 3.4, Python 3.11) compiles all of these, so nothing here
would ever fail the Debian build: the list below is the only guard. The compiler check
(`make check-gcc11`, -std=c++17) catches the language; this catches the library.

  check_cxx_features.py ROOT            scan ROOT/src, ROOT/include, ROOT/test, ROOT/scripts
  check_cxx_features.py ROOT --list     print the forbidden features and the reason for each

A line may keep a match with a trailing comment `// noetic-ok: WHY` (e.g. an integer
std::to_chars, which libstdc++ 9 has). Exit 0: clean; 1: one line per finding
`path:line: feature: reason`.
"""
import argparse
import ast
import pathlib
import re
import sys

# (regular expression on code with comments and strings removed, feature, reason)
FORBIDDEN = [
    (r"\bstd::to_chars\b", "std::to_chars",
     "the floating-point overloads need libstdc++ 11 (GCC 9 has the integer ones only): use snprintf "
     "%.17g (core::formatValue); an integer use may say `// noetic-ok: integer`"),
    (r"\bstd::from_chars\b", "std::from_chars",
     "the floating-point overloads need libstdc++ 11: use strtod (core::parseValue)"),
    (r"#\s*include\s*<charconv>", "<charconv>", "only for to_chars/from_chars, see those"),
    (r"\bstd::hardware_(destructive|constructive)_interference_size\b", "hardware_interference_size",
     "libstdc++ 12"),
    (r"#\s*include\s*<numbers>|\bstd::numbers::", "<numbers>", "C++20, libstdc++ 10: use M_PI or a constexpr"),
    (r"#\s*include\s*<span>|\bstd::span\b", "std::span", "C++20, libstdc++ 10"),
    (r"\bstd::bit_cast\b", "std::bit_cast", "C++20, libstdc++ 11: use std::memcpy"),
    (r"#\s*include\s*<format>|\bstd::format\b", "std::format", "C++20, libstdc++ 13"),
    (r"#\s*include\s*<ranges>|\bstd::ranges::|\bstd::views::", "ranges", "C++20, libstdc++ 10"),
    (r"#\s*include\s*<concepts>", "<concepts>", "C++20, libstdc++ 10"),
    (r"#\s*include\s*<source_location>", "<source_location>", "C++20, libstdc++ 11"),
    (r"#\s*include\s*<(latch|barrier|semaphore|stop_token)>|\bstd::jthread\b", "C++20 threads",
     "libstdc++ 10/11"),
    (r"\bstd::ssize\b", "std::ssize", "C++20, libstdc++ 10"),
    (r"\bstd::erase_if\b", "std::erase_if", "C++20 (libstdc++ 9 only under std::experimental)"),
    (r"\.(starts_with|ends_with)\s*\(", "starts_with/ends_with", "C++20 std::string members: use compare/rfind"),
    (r"\bstd::midpoint\b|\bstd::lerp\b", "midpoint/lerp", "C++20: not in -std=c++17"),
    (r"\bEigen::(seq|seqN|lastN|all|placeholders)\b|\.reshaped\s*[<(]", "Eigen 3.4 slicing",
     "Eigen 3.4; Noetic's Ubuntu 20.04 has Eigen 3.3.7: use block()/segment()/head()/tail()"),
    (r"\bEigen::(Vector|RowVector)\s*<", "Eigen::Vector<T, N>", "an Eigen 3.4 alias: use Matrix<T, N, 1>"),
]
PYTHON_OLDEST = (3, 8)  # Noetic's python3 (Ubuntu 20.04)
# Standard-library uses ast can see (syntax is checked by ast.parse with feature_version).
PYTHON_ATTRIBUTES = {"removeprefix": "Python 3.9", "removesuffix": "Python 3.9"}
PYTHON_MODULES = {"tomllib": "Python 3.11", "zoneinfo": "Python 3.9", "graphlib": "Python 3.9"}
PYTHON_KEYWORDS = {("zip", "strict"): "Python 3.10"}
# list[int] and friends (PEP 585) raise TypeError on 3.8 wherever they are evaluated.
PYTHON_GENERICS = {"list", "dict", "tuple", "set", "frozenset", "type"}
CXX_SUFFIXES = {".cpp", ".h", ".hpp", ".cc"}
FOLDERS = ["src", "include", "test", "scripts"]
OK_MARK = "noetic-ok:"

_CODE_NOISE = re.compile(r'//[^\n]*|/\*.*?\*/|"(?:\\.|[^"\\\n])*"|\'(?:\\.|[^\'\\\n])\'', re.S)


def code_lines(text):
    """The text with comments and string literals blanked, line numbers kept."""
    def blank(m):
        kept = m.group(0)
        # An #include <...> is code; "..." includes are never forbidden here.
        return re.sub(r"[^\n]", " ", kept)
    return _CODE_NOISE.sub(blank, text).split("\n")


def scan_cxx(path, rel):
    text = path.read_text(errors="replace")
    raw = text.split("\n")
    found = []
    for number, line in enumerate(code_lines(text), 1):
        if OK_MARK in raw[number - 1]:
            continue
        for pattern, feature, reason in FORBIDDEN:
            if re.search(pattern, line):
                found.append(f"{rel}:{number}: {feature}: {reason}")
    return found


def scan_python(path, rel):
    text = path.read_text(errors="replace")
    raw = text.split("\n")
    try:
        tree = ast.parse(text, filename=str(rel), feature_version=PYTHON_OLDEST)
    except SyntaxError as e:
        return [f"{rel}:{e.lineno}: syntax newer than Python {PYTHON_OLDEST[0]}.{PYTHON_OLDEST[1]}: {e.msg}"]
    found = []
    for node in ast.walk(tree):
        what = None
        if isinstance(node, ast.Attribute) and node.attr in PYTHON_ATTRIBUTES:
            what = (f".{node.attr}()", PYTHON_ATTRIBUTES[node.attr])
        elif isinstance(node, (ast.Import, ast.ImportFrom)):
            names = [a.name for a in node.names] if isinstance(node, ast.Import) else [node.module or ""]
            for name in names:
                if name.split(".")[0] in PYTHON_MODULES:
                    what = (name, PYTHON_MODULES[name.split(".")[0]])
        elif isinstance(node, ast.Subscript) and isinstance(node.value, ast.Name) and node.value.id in PYTHON_GENERICS:
            what = (f"{node.value.id}[...]", "Python 3.9 (PEP 585): use typing.List etc.")
        elif isinstance(node, ast.Call) and isinstance(node.func, ast.Name):
            for k in node.keywords:
                if (node.func.id, k.arg) in PYTHON_KEYWORDS:
                    what = (f"{node.func.id}({k.arg}=)", PYTHON_KEYWORDS[(node.func.id, k.arg)])
        if what and OK_MARK not in raw[node.lineno - 1]:
            found.append(f"{rel}:{node.lineno}: {what[0]}: {what[1]}")
    return found


def is_python(path):
    if path.suffix == ".py":
        return True
    if path.suffix or not path.is_file():
        return False
    with path.open("rb") as f:
        first = f.readline(200)
    return first.startswith(b"#!") and b"python" in first


def scan(root):
    findings = []
    for folder in FOLDERS:
        base = root / folder
        if not base.is_dir():
            continue
        for path in sorted(base.rglob("*")):
            if not path.is_file():
                continue
            rel = path.relative_to(root)
            if path.suffix in CXX_SUFFIXES:
                findings += scan_cxx(path, rel)
            elif is_python(path):
                findings += scan_python(path, rel)
    return findings


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("root", type=pathlib.Path)
    parser.add_argument("--list", action="store_true", help="print the forbidden features and why")
    args = parser.parse_args()
    if args.list:
        for _, feature, reason in FORBIDDEN:
            print(f"{feature}: {reason}")
        for name, reason in {**PYTHON_ATTRIBUTES, **PYTHON_MODULES}.items():
            print(f"{name} (Python): {reason}")
        print(f"Python syntax newer than {PYTHON_OLDEST[0]}.{PYTHON_OLDEST[1]}: Noetic's python3")
        return 0
    findings = scan(args.root.resolve())
    for f in findings:
        print(f)
    if findings:
        print(f"{len(findings)} use(s) of features newer than Noetic's toolchain (GCC 9, Eigen 3.3, Python 3.8)")
        return 1
    print("no feature newer than GCC 9 / libstdc++ 9, Eigen 3.3, Python 3.8")
    return 0


if __name__ == "__main__":
    sys.exit(main())
