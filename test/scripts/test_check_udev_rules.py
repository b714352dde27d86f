#!/usr/bin/python3
"""check_udev_rules.py on temporary rules files: the shipped shape passes; each mistake udev
would skip a rule for (or that loses a link the docs use) fails naming the line.

Usage: test_check_udev_rules.py PATH/TO/check_udev_rules.py
"""
import os
import tempfile
import unittest

from script_loader import load_script_from_argv

check = load_script_from_argv("check_udev_rules")

ROBOT = 'SUBSYSTEM=="tty", ATTRS{idVendor}=="0403", ATTRS{idProduct}=="6001", ATTRS{serial}=="A1B2", SYMLINK+="amigobot", MODE="0660"'
LASER = 'SUBSYSTEM=="tty", ATTRS{idVendor}=="10c4", ATTRS{idProduct}=="ea60", SYMLINK+="laser", GROUP="dialout"'


class CheckUdevRules(unittest.TestCase):
    def problems(self, *lines):
        with tempfile.NamedTemporaryFile("w", suffix=".rules", delete=False) as f:
            f.write("# a comment\n\n" + "\n".join(lines) + "\n")
        try:
            return check.check(f.name)
        finally:
            os.unlink(f.name)

    def assertFails(self, line, words, *others):
        found = self.problems(line, *others)
        self.assertTrue(any(":3: " in p and words in p for p in found), f"{found} should name line 3: {words}")

    def test_the_shipped_shape_passes(self):
        self.assertEqual(self.problems(ROBOT, LASER), [])

    def test_an_assigned_match_key_fails(self):
        self.assertFails(ROBOT.replace('ATTRS{serial}=="A1B2"', 'ATTRS{serial}="A1B2"'), "can only be matched", LASER)

    def test_symlink_set_instead_of_added_fails(self):
        self.assertFails(ROBOT.replace('SYMLINK+=', 'SYMLINK='), "use +=", LASER)

    def test_a_missing_comma_or_quote_fails(self):
        self.assertFails(ROBOT.replace('"0403", ', '"0403" '), "cannot parse", LASER)
        self.assertFails(ROBOT.replace('MODE="0660"', 'MODE=0660'), "cannot parse", LASER)

    def test_bad_mode_and_upper_case_ids_fail(self):
        self.assertFails(ROBOT.replace('"0660"', '"rw"'), "not octal", LASER)
        self.assertFails(LASER.replace('"ea60"', '"EA60"'), "hex digits", ROBOT)

    def test_a_rule_matching_nothing_fails(self):
        self.assertFails('SYMLINK+="laser", MODE="0660"', "matches nothing", ROBOT)

    def test_links_other_than_the_docs_fail(self):
        found = self.problems(ROBOT, LASER.replace('"laser"', '"rplidar"'))
        self.assertTrue(any("the docs use" in p for p in found), found)


if __name__ == "__main__":
    unittest.main()
