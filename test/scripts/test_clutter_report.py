#!/usr/bin/python3
"""scripts/reports/clutter.py --quick on two classes with the real simulator: the table has a
row per class and law, every column, sane values, and a law the simulator lacks is "missing".

Usage: test_clutter_report.py PATH/TO/clutter.py PATH/TO/amigobot_sim
"""
import os
import sys
import tempfile
import unittest

from script_loader import load_script_from_argv

if len(sys.argv) > 1:
    sys.path.insert(0, os.path.dirname(os.path.abspath(sys.argv[1])))  # its sibling markdown.py
clutter = load_script_from_argv("clutter")
SIM = sys.argv.pop(1) if len(sys.argv) > 1 else ""
CLASSES = ["pillar_park", "gap_pair"]


class QuickClutterReport(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.tmp = tempfile.TemporaryDirectory()
        laws = clutter.LAWS + ["no_such_law"]
        cls.results = clutter.main(SIM, os.path.join(cls.tmp.name, "out"), cls.tmp.name, runs=clutter.QUICK_RUNS,
                                   jobs=2, classes=CLASSES, quick=True, laws=laws)
        with open(os.path.join(cls.tmp.name, "clutter.md")) as f:
            cls.rows = clutter.markdown.table_rows(f.read())

    def test_every_column_and_a_row_per_class_and_law(self):
        self.assertEqual(self.rows[0], clutter.HEADINGS)
        body = self.rows[1:]
        self.assertEqual(len(body), len(CLASSES) * (len(clutter.LAWS) + 1))
        for row in body:
            self.assertEqual(len(row), len(clutter.HEADINGS), row)

    def test_unknown_law_is_marked_missing(self):
        missing = [row for row in self.rows[1:] if row[1] == "no_such_law"]
        self.assertEqual(len(missing), len(CLASSES))
        for row in missing:
            self.assertEqual(row[2], "missing")

    def test_sane_values_of_the_paper_law(self):
        for name, law, s in self.results:
            if law != "paper":
                continue
            self.assertEqual(s["runs"], clutter.QUICK_RUNS)
            self.assertGreaterEqual(s["worst_true_ase"], s["mean_true_ase"])
            self.assertGreater(s["mean_true_ase"], 0.0)
            self.assertGreaterEqual(s["worst_true_ise"], s["mean_true_ise"])
            self.assertGreaterEqual(s["worst_orbit_turns"], 0.0)
            self.assertLess(s["worst_orbit_turns"], 50.0)
            self.assertGreater(s["worst_min_clearance_body"], -1.0)
            self.assertEqual(s["runs_with_nan"], 0, name)
            self.assertEqual(s["diamond_violations"], 0, name)
            row = next(r for r in self.rows[1:] if r[0] == name and r[1] == law)
            self.assertEqual(row[2], str(clutter.QUICK_RUNS))
            for cell in row[3:]:
                self.assertNotIn(cell, ("", "—", "nan", "missing", "failed"), row)


if __name__ == "__main__":
    unittest.main()
