#!/usr/bin/python3
"""Every case of a gtest executable that rostest files share (test_rostest, test_e2e) is run by
some .test file: each <test type="EXE" args="--gtest_filter=..."> selects its cases, so a case in
a new suite that no filter names would never run, silently. Fails naming each such case, and
each filter that selects nothing (a renamed suite or case).

Usage: check_gtest_filters.py EXECUTABLE TEST_FILE_OR_DIR...
"""
import fnmatch
import os
import subprocess
import sys
import xml.etree.ElementTree as ET


def listed_cases(executable):
    """The executable's cases as Suite.Case (gtest's --gtest_list_tests)."""
    out = subprocess.run([executable, "--gtest_list_tests"], capture_output=True, text=True, timeout=60, check=True).stdout
    cases, suite = [], None
    for line in out.splitlines():
        if not line.strip():
            continue
        name = line.split("#")[0].strip()
        if not line.startswith(" "):
            suite = name
        else:
            cases.append(suite + name)
    return cases


def selects(gtest_filter, case):
    """gtest's filter: positive patterns, then '-' and negative ones, ':'-separated, * and ?."""
    positive, _, negative = gtest_filter.partition("-")
    def any_match(patterns):
        return any(p and fnmatch.fnmatchcase(case, p) for p in patterns.split(":"))
    return any_match(positive or "*") and not any_match(negative)


def filters_of(paths, executable_name):
    """(file, filter) for each <test> of these .test files that runs the executable."""
    files = []
    for path in paths:
        if os.path.isdir(path):
            files += [os.path.join(path, f) for f in sorted(os.listdir(path)) if f.endswith(".test")]
        else:
            files.append(path)
    found = []
    for f in files:
        for test in ET.parse(f).getroot().iter("test"):
            if test.get("type") != executable_name:
                continue
            gtest_filter = "*"
            for arg in (test.get("args") or "").split():
                if arg.startswith("--gtest_filter="):
                    gtest_filter = arg.split("=", 1)[1]
            found.append((os.path.relpath(f), gtest_filter))
    return found


def main():
    if len(sys.argv) < 3:
        sys.exit(__doc__)
    executable, paths = sys.argv[1], sys.argv[2:]
    cases = listed_cases(executable)
    filters = filters_of(paths, os.path.basename(executable))
    problems = []
    for case in cases:
        if not any(selects(flt, case) for _, flt in filters):
            problems.append(f"{case}: no .test file's --gtest_filter selects it, so it never runs")
    for f, flt in filters:
        if not any(selects(flt, case) for case in cases):
            problems.append(f"{f}: --gtest_filter={flt} selects no case of {os.path.basename(executable)}")
    for p in problems:
        print(p)
    print(f"{os.path.basename(executable)}: {len(cases)} cases, {len(filters)} .test entries, {len(problems)} problems")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
