#!/usr/bin/python3
"""Counts test cases in JUnit XML files and prints one line `N passed, N failed`.

Usage: count_test_results.py RESULTS_DIR [--runner-exit CODE]
A non-zero CODE (the test runner itself failed, e.g. a test target did not start) counts as
one more failure. Exits 1 when any test failed or errored, or when no test ran at all.

A rostest writes two kinds of file: its wrapper rostest-NAME.xml holds one case `testX` per
<test test-name="X"> of the .test file, which fails only when X did not run (fixture nodes
did not start, no results, time-out); X's own cases are in rosunit-X.xml beside it. A
wrapper case therefore counts only when it failed or X left no cases of its own; otherwise
X's cases stand for it. (A rostest that wrote nothing leaves catkin's MISSING-rostest-NAME.xml,
one failed case, counted like any file.)
"""
import glob
import os
import sys
import xml.etree.ElementTree as ET


def is_failure(case):
    return case.find("failure") is not None or case.find("error") is not None


def inner_results(wrapper_path, case):
    """The rosunit-X.xml of a rostest wrapper's case `testX` (rosunit's file-name rule)."""
    name = case.get("name", "")
    name = name[len("test"):] if name.startswith("test") else name
    for c in " \"'&$!`/\\":
        name = name.replace(c, "_")
    return os.path.join(os.path.dirname(wrapper_path), f"rosunit-{name}.xml")


def has_cases(path):
    try:
        return next(ET.parse(path).getroot().iter("testcase"), None) is not None
    except (OSError, ET.ParseError):
        return False


def counted_cases(path, root):
    """The cases of one result file that count: all of them, less a rostest wrapper's cases
    whose test ran and left its own cases."""
    cases = list(root.iter("testcase"))
    if not os.path.basename(path).startswith("rostest-"):
        return cases
    return [c for c in cases if is_failure(c) or not has_cases(inner_results(path, c))]


def count(results_dir):
    passed, failed, skipped, bad_files = 0, 0, 0, []
    for path in sorted(glob.glob(os.path.join(results_dir, "**", "*.xml"), recursive=True)):
        try:
            root = ET.parse(path).getroot()
        except ET.ParseError as err:
            bad_files.append(f"{path}: {err}")
            failed += 1
            continue
        for case in counted_cases(path, root):
            if is_failure(case):
                failed += 1
                print(f"FAILED: {case.get('classname')}.{case.get('name')} ({os.path.relpath(path, results_dir)})")
            elif case.find("skipped") is not None or case.get("status") == "notrun":
                skipped += 1
            else:
                passed += 1
    for line in bad_files:
        print(f"FAILED: unreadable result file {line}")
    return passed, failed, skipped


def main():
    args = sys.argv[1:]
    runner_exit = 0
    if len(args) == 3 and args[1] == "--runner-exit":
        runner_exit = int(args[2])
        args = args[:1]
    if len(args) != 1:
        sys.exit(__doc__)
    passed, failed, skipped = count(args[0])
    if runner_exit:
        print(f"FAILED: the test runner exited with {runner_exit}: a test did not run (see the log above)")
        failed += 1
    line = f"{passed} passed, {failed} failed"
    if skipped:
        line += f", {skipped} skipped"
    print(line)
    sys.exit(1 if failed or passed == 0 else 0)


if __name__ == "__main__":
    main()
