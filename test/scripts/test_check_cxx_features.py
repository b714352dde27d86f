#!/usr/bin/python3
"""check_cxx_features.py on temporary trees: a feature newer than Noetic's toolchain fails
naming the file, the line and the reason; comments, strings and `noetic-ok:` lines do not.

Usage: test_check_cxx_features.py PATH/TO/check_cxx_features.py
"""
import os
import pathlib
import tempfile
import unittest

from script_loader import load_script_from_argv

check = load_script_from_argv("check_cxx_features")


class CheckCxxFeatures(unittest.TestCase):
    def setUp(self):
        self.tmp = tempfile.TemporaryDirectory()
        self.root = pathlib.Path(self.tmp.name)
        self.write("src/core/clean.cpp", '#include <cstdio>\n// std::to_chars is not used here\n'
                   'const char* s = "std::span";\nint n = 0;\n')
        self.write("scripts/clean.py", "from typing import List\n\ndef f(x: List[int]):\n    return x\n")

    def tearDown(self):
        self.tmp.cleanup()

    def write(self, relative, text):
        path = self.root / relative
        os.makedirs(path.parent, exist_ok=True)
        path.write_text(text)

    def test_clean_tree_passes(self):
        self.assertEqual(check.scan(self.root), [])

    def test_floating_to_chars_fails_naming_line_and_reason(self):
        self.write("src/core/bad.cpp", "void f(char* b) {\n  std::to_chars(b, b + 32, 0.15);\n}\n")
        findings = check.scan(self.root)
        self.assertEqual(len(findings), 1, findings)
        self.assertTrue(findings[0].startswith("src/core/bad.cpp:2: std::to_chars:"), findings[0])
        self.assertIn("libstdc++ 11", findings[0])

    def test_marked_line_is_kept(self):
        self.write("src/core/int.cpp", "auto r = std::to_chars(b, e, 7);  // noetic-ok: integer\n")
        self.assertEqual(check.scan(self.root), [])

    def test_cxx20_header_and_eigen34_fail(self):
        self.write("include/x.h", "#include <numbers>\nauto v = m(Eigen::seq(0, 2), 0);\n")
        features = [f.split(": ")[1] for f in check.scan(self.root)]
        self.assertEqual(features, ["<numbers>", "Eigen 3.4 slicing"])

    def test_python_newer_than_38_fails(self):
        self.write("scripts/nodes/node", "#!/usr/bin/python3\nprint('a'.removeprefix('x'))\n")
        self.write("scripts/m.py", "match x:\n    case 1:\n        pass\n")
        self.write("scripts/g.py", "def f(x: dict[str, int]):\n    return x\n")
        findings = check.scan(self.root)
        self.assertEqual(len(findings), 3, findings)
        self.assertTrue(any(f.startswith("scripts/nodes/node:2: .removeprefix()") for f in findings), findings)
        self.assertTrue(any(f.startswith("scripts/m.py:") and "syntax newer than Python 3.8" in f for f in findings), findings)
        self.assertTrue(any(f.startswith("scripts/g.py:1: dict[...]") for f in findings), findings)


if __name__ == "__main__":
    unittest.main(argv=[__file__])
