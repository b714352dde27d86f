#!/usr/bin/python3
"""scripts/reports/pedestrians.py --quick on three classes with the real simulator: a row per class
and law with every column, every run completed (none failed), no NaN, no command outside the
diamond, and the variants draw what the benchmark says (speeds in range, the encounter kept).

Usage: test_pedestrian_report.py PATH/TO/pedestrians.py PATH/TO/amigobot_sim
"""
import math
import os
import sys
import tempfile
import unittest

from script_loader import load_script_from_argv

if len(sys.argv) > 1:
    sys.path.insert(0, os.path.dirname(os.path.abspath(sys.argv[1])))  # its siblings markdown.py, scenario_yaml.py
pedestrians = load_script_from_argv("pedestrians")
SIM = sys.argv.pop(1) if len(sys.argv) > 1 else ""
CLASSES = ["two_sides", "stopping", "crowd"]


class QuickPedestrianReport(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.tmp = tempfile.TemporaryDirectory()
        cls.results = pedestrians.main(SIM, os.path.join(cls.tmp.name, "out"), cls.tmp.name,
                                       runs=pedestrians.QUICK_RUNS, jobs=2, classes=CLASSES, quick=True)
        with open(os.path.join(cls.tmp.name, "pedestrians.md")) as f:
            tables = f.read().split("\n\n")
        # The page's tables in order: the benchmark's, then the one on MRPT's contact-free variants.
        found = [pedestrians.markdown.table_rows(t) for t in tables if t.startswith("|")]
        cls.rows, cls.untouched = found[0], found[1]

    def test_every_column_and_a_row_per_class_and_law(self):
        self.assertEqual(self.rows[0], pedestrians.HEADINGS)
        body = self.rows[1:]
        self.assertEqual(len(body), len(CLASSES) * len(pedestrians.LAWS))
        for row in body:
            self.assertEqual(len(row), len(pedestrians.HEADINGS), row)
            self.assertNotIn("—", row)

    def test_a_row_per_class_on_the_variants_where_mrpt_touched_no_one(self):
        self.assertEqual(self.untouched[0], ["class", "variants"] + list(pedestrians.LAWS))
        self.assertEqual([row[0] for row in self.untouched[1:]], CLASSES)
        for row in self.untouched[1:]:
            clean, total = row[1].split(" of ")
            self.assertEqual(int(total), pedestrians.QUICK_RUNS, row)
            # a class with clean variants has every law's mean; one without has none
            self.assertEqual(all(c == "—" for c in row[2:]), int(clean) == 0, row)

    def test_every_run_completes_without_nan_or_diamond_violation(self):
        for name, law, s in self.results:
            self.assertEqual(s["failed"], 0, (name, law, s.get("reasons")))
            self.assertEqual(s["runs"], pedestrians.QUICK_RUNS)
            self.assertEqual(s["runs_with_nan"], 0, (name, law))
            self.assertEqual(s["diamond_violations"], 0, (name, law))
            self.assertTrue(math.isfinite(s["mean_true_ase"]) and s["mean_true_ase"] > 0.0, (name, law))
            self.assertGreaterEqual(s["mean_omega_reversals_per_minute"], 0.0)

    def test_a_failed_run_is_counted_and_named(self):
        s = pedestrians.summarize([{"failed": "amigobot_sim: mrpt_reactive: MRPT's navigator failed"}])
        self.assertEqual((s["runs"], s["failed"]), (1, 1))
        self.assertEqual(pedestrians.cells(s)[1], "1")

    def test_variants_draw_speeds_in_range_and_keep_the_encounter(self):
        base = pedestrians.scenario_yaml.load(os.path.join(pedestrians.SCENES, "two_sides.yaml"))
        for i in range(20):
            data = pedestrians.make_variant(base, i)
            for before, after in zip(base["obstacles"], data["obstacles"]):
                legs = after["motion"]["legs"]
                speed = math.hypot(*legs[0]["velocity"])
                self.assertGreaterEqual(speed, pedestrians.SPEEDS[0] - 1e-9)
                self.assertLessEqual(speed, pedestrians.SPEEDS[1] + 1e-9)
                # Where it crosses the target's line (y = 0): within the timing and shift of the scene's.
                t_cross = after["motion"]["start_time"] + abs(after["center"][1]) / abs(legs[0]["velocity"][1])
                self.assertLess(abs(t_cross - pedestrians.ENCOUNTER), pedestrians.TIMING + 0.6)
                self.assertLess(abs(after["center"][0] - before["center"][0]), pedestrians.PERSON_SHIFT + 1e-9)


    def test_people_already_walking_at_the_start_stand_where_they_are_then(self):
        # Slow people reach the encounter only if they set off before t = 0: the variant starts
        # them at t = 0 where they would be then, so the file's centre is where they are.
        base = pedestrians.scenario_yaml.load(os.path.join(pedestrians.SCENES, "overtaking.yaml"))
        moved = 0
        for i in range(30):
            person = pedestrians.make_variant(base, i)["obstacles"][0]
            motion = person["motion"]
            self.assertGreaterEqual(motion["start_time"], 0.0)
            self.assertTrue(all(leg["duration"] > 0.0 for leg in motion["legs"]))
            moved += motion["start_time"] == 0.0
            # At the encounter (within the timing) it is where the scene has it, within the shift.
            speed = motion["legs"][0]["velocity"][0]
            x_at = person["center"][0] + speed * (pedestrians.ENCOUNTER - motion["start_time"])
            nominal = base["obstacles"][0]["center"][0] + 0.7 * (pedestrians.ENCOUNTER - 6.0)
            self.assertLess(abs(x_at - nominal), speed * pedestrians.TIMING + pedestrians.PERSON_SHIFT + 1e-9)
        self.assertGreater(moved, 0)  # the case occurred


if __name__ == "__main__":
    unittest.main()
