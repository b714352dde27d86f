#!/usr/bin/python3
"""param_docs.py's renderers on small inputs: a YAML key line gets the row's comment and keeps
its value and column, a commented-out key too, a '#' inside a quoted value is no comment, keys
of other sets and prose stay; a docs table between its marks is the rows in order and a mark
without its end names the file and line; a .cfg gets the live rows with range and default.

Usage: test_param_docs.py PATH/TO/param_docs.py
"""
import unittest

from script_loader import load_script_from_argv

docs = load_script_from_argv("param_docs")

ROWS = [
    {"key": "k_d", "type": "double", "unit": "m/s", "default": "0.15", "meaning": "tracking gain", "live": True,
     "range": [0.001, 10.0], "default_value": 0.15},
    {"key": "frame", "type": "string", "unit": "-", "default": '"map"', "meaning": "a frame | with a bar", "live": False},
    {"key": "estimator/a1", "type": "double", "unit": "1/s", "default": "1", "meaning": "stage-1 gain", "live": False},
]
SET = {r["key"]: r for r in ROWS}


class Yaml(unittest.TestCase):
    def render(self, *lines):
        return docs.render_yaml(list(lines), {"": SET})

    def test_a_key_line_gets_the_rows_comment_at_its_column(self):
        self.assertEqual(self.render("k_d: 3.0      # old words"),
                         ["k_d: 3.0      # double, m/s, 0.15: tracking gain (reconfigurable)"])

    def test_a_key_without_comment_gets_one(self):
        self.assertEqual(self.render("frame: odom"), ['frame: odom' + ' ' * 18 + '# string, -, "map": a frame | with a bar'])

    def test_a_commented_out_key_and_a_nested_key(self):
        out = self.render("# k_d:     # old", "estimator:", "  a1: 2.0   # old")
        self.assertEqual(out[0], "# k_d:     # double, m/s, 0.15: tracking gain (reconfigurable)")
        self.assertEqual(out[1], "estimator:")
        self.assertEqual(out[2], "  a1: 2.0   # double, 1/s, 1: stage-1 gain")

    def test_a_hash_inside_quotes_is_part_of_the_value(self):
        self.assertEqual(self.render('frame: "a#b"   # old')[0], 'frame: "a#b"   # string, -, "map": a frame | with a bar')

    def test_a_missing_row_gets_a_line_in_its_mapping(self):
        gain = dict(SET["estimator/a1"], path="estimator/a1")
        out = docs.render_yaml(["k_d: 1   # x", "estimator:", "  a2: 1", "frame: map", ""], {"": SET}, [gain])
        self.assertEqual(out[3], "  a1: 1" + " " * 21 + " # double, 1/s, 1: stage-1 gain")
        self.assertEqual(out[4:], ["frame: map" + " " * 18 + ' # string, -, "map": a frame | with a bar', ""])

    def test_a_missing_row_described_in_words_is_commented_out_at_the_end(self):
        row = dict(SET["k_d"], path="k_d", described=True, default="the robot file's")
        out = docs.render_yaml(["frame: map", "", ""], {"": SET}, [row])
        self.assertEqual(out[1], "# k_d:" + " " * 22 + " # double, m/s, 0.15: tracking gain (reconfigurable)")
        self.assertEqual(out[2:], ["", ""])

    def test_other_keys_and_prose_stay(self):
        lines = ["# Each key: type, unit, default, meaning.", "other: 1   # mine", "a1: 2.0  # not nested: no row"]
        self.assertEqual(self.render(*lines), lines)


class Doc(unittest.TestCase):
    def test_the_table_between_the_marks_is_the_rows(self):
        out = docs.render_doc(["text", "<!-- param_docs: s Gain -->", "| stale |", "<!-- /param_docs -->", "after"],
                              {"s": ROWS[:2]}, "x.md")
        self.assertEqual(out, ["text", "<!-- param_docs: s Gain -->", "| Gain | Type | Unit | Default | Meaning |",
                               "|---|---|---|---|---|",
                               "| `k_d` | double | m/s | 0.15 | tracking gain (reconfigurable) |",
                               "| `frame` | string | – | `map` | a frame \\| with a bar |",
                               "<!-- /param_docs -->", "after"])

    def test_a_mark_without_its_end_names_the_file_and_line(self):
        with self.assertRaises(SystemExit) as raised:
            docs.render_doc(["<!-- param_docs: s -->", "| row |"], {"s": ROWS}, "x.md")
        self.assertIn("x.md:1", str(raised.exception))

    def test_an_unknown_set_is_named(self):
        with self.assertRaises(SystemExit) as raised:
            docs.render_doc(["<!-- param_docs: nope -->", "<!-- /param_docs -->"], {"s": ROWS}, "x.md")
        self.assertIn("'nope'", str(raised.exception))


class Cfg(unittest.TestCase):
    def test_the_live_rows_with_their_range_and_default(self):
        out = docs.render_cfg(["#!/usr/bin/python3", "# header", "from dynamic_reconfigure import old", "gen.add(stale)",
                               'exit(gen.generate("p", "n", "N"))'], ROWS, "x.cfg")
        self.assertEqual(out[:2], ["#!/usr/bin/python3", "# header"])
        self.assertIn('gen.add("k_d", double_t, 0, "tracking gain [m/s]", 0.15, 0.001, 10.0)', out)
        self.assertFalse(any("frame" in line for line in out))
        self.assertEqual(out[-1], 'exit(gen.generate("p", "n", "N"))')


if __name__ == "__main__":
    unittest.main()
