#!/usr/bin/python3
"""Counts test cases in JUnit XML files and prints one line `N passed, N failed`.

Usage: count_test_results.py RESULTS_DIR [--runner-exit CODE]
A non-zero CODE (the test runner itself failed, e.g. a test target did not start) counts as
one more failure. Exits 1 when any test failed or errored, or when no test ran at all.
"""
import glob
import os
import sys
import xml.etree.ElementTree as ET


def count(results_dir):
    passed, failed, skipped, bad_files = 0, 0, 0, []
    for path in sorted(glob.glob(os.path.join(results_dir, "**", "*.xml"), recursive=True)):
        try:
            root = ET.parse(path).getroot()
        except ET.ParseError as err:
            bad_files.append(f"{path}: {err}")
            failed += 1
            continue
        for case in root.iter("testcase"):
            if case.find("failure") is not None or case.find("error") is not None:
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
