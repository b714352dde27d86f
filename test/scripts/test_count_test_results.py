#!/usr/bin/python3
"""count_test_results.py on fixture result folders: each rostest counted once.

Usage: test_count_test_results.py PATH/TO/count_test_results.py
The fixtures have the shape rostest and gtest write (see the counter's docstring).
"""
import contextlib
import io
import os
import sys
import tempfile
import unittest

from script_loader import load_script_from_argv

counter = load_script_from_argv("count_test_results")


def wrapper(*cases):
    """rostest-NAME.xml: one case per <test>, (test-name, failure message or None)."""
    body = "".join(f'<testcase classname="rostest.runner.RosTest" name="test{name}" time="1.0">'
                   + (f'<failure message="{failure}" type=""/>' if failure else "") + "</testcase>"
                   for name, failure in cases)
    return f'<?xml version="1.0"?><testsuite name="rostest" tests="{len(cases)}">{body}</testsuite>'


def gtest(suite, *cases):
    """A gtest results file: (case name, failure message or None)."""
    body = "".join(f'<testcase name="{name}" status="run" classname="{suite}">'
                   + (f'<failure message="{failure}"/>' if failure else "") + "</testcase>"
                   for name, failure in cases)
    return f'<?xml version="1.0"?><testsuites><testsuite name="{suite}">{body}</testsuite></testsuites>'


class CountTestResults(unittest.TestCase):
    def setUp(self):
        self.tmp = tempfile.TemporaryDirectory()
        self.dir = os.path.join(self.tmp.name, "amigobot_tracking")
        os.makedirs(self.dir)

    def tearDown(self):
        self.tmp.cleanup()

    def write(self, name, text):
        with open(os.path.join(self.dir, name), "w") as f:
            f.write(text)

    def count(self):
        with contextlib.redirect_stdout(io.StringIO()) as out:
            result = counter.count(self.tmp.name)
        return result, out.getvalue()

    def test_passed_wrapper_with_inner_cases_counts_the_inner_cases_once(self):
        self.write("rostest-test_rostest_tracking_nodelet.xml", wrapper(("tracking_nodelet", None)))
        self.write("rosunit-tracking_nodelet.xml", gtest("Nodelet", ("A", None), ("B", None), ("C", None)))
        self.assertEqual(self.count()[0], (3, 0, 0))

    def test_failed_wrapper_without_inner_results_is_one_failure(self):
        self.write("rostest-e2e_tracking.xml",
                   wrapper(("e2e_tracking", "test [e2e_tracking] did not generate test results")))
        (passed, failed, skipped), out = self.count()
        self.assertEqual((passed, failed, skipped), (0, 1, 0))
        self.assertIn("FAILED: rostest.runner.RosTest.teste2e_tracking", out)

    def test_inner_failure_is_counted(self):
        self.write("rostest-e2e_diamond.xml", wrapper(("e2e_diamond", None)))
        self.write("rosunit-e2e_diamond.xml", gtest("E2E", ("Diamond", "speed 0.9 > 0.5"), ("Bound", None)))
        (passed, failed, _), out = self.count()
        self.assertEqual((passed, failed), (1, 1))
        self.assertIn("FAILED: E2E.Diamond (amigobot_tracking/rosunit-e2e_diamond.xml)", out)

    def test_passed_wrapper_whose_test_left_no_cases_counts_itself(self):
        self.write("rostest-sim_launch.xml", wrapper(("sim_launch", None)))
        self.write("rosunit-sim_launch.xml", '<?xml version="1.0"?><testsuite name="sim_launch" tests="0"/>')
        self.assertEqual(self.count()[0], (1, 0, 0))

    def test_each_test_of_a_wrapper_is_linked_to_its_own_file(self):
        self.write("rostest-e2e_rates.xml", wrapper(("e2e_rate_odom", None), ("e2e_rate_cmd_vel", None)))
        self.write("rosunit-e2e_rate_odom.xml", gtest("E2E", ("Odom", None)))
        self.assertEqual(self.count()[0], (2, 0, 0))  # Odom, and the wrapper case of cmd_vel

    def test_other_files_count_every_case(self):
        self.write("gtest-test_diamond.xml", gtest("Diamond", ("A", None), ("B", None)))
        self.write("check-layers.xml", gtest("check", ("layers", "include crosses a layer")))
        self.write("MISSING-rostest-e2e_watchdog.xml", gtest("Results", ("test_ran", "Unable to find test results")))
        self.assertEqual(self.count()[0], (2, 2, 0))

    def test_summary_line_and_exit_code(self):
        self.write("gtest-test_diamond.xml", gtest("Diamond", ("A", None)))
        with contextlib.redirect_stdout(io.StringIO()) as out, self.assertRaises(SystemExit) as done:
            sys.argv = ["count_test_results.py", self.tmp.name, "--runner-exit", "2"]
            counter.main()
        self.assertEqual(done.exception.code, 1)
        self.assertEqual(out.getvalue().splitlines()[-1], "1 passed, 1 failed")


if __name__ == "__main__":
    unittest.main()
