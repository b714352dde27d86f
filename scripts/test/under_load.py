#!/usr/bin/python3
"""make test-under-load: the end-to-end tier with busy loops on every core, several passes.

Usage: under_load.py --ws WS [--passes 1] [--busy 2] [--jobs 2] [--only NAME ...]

Starts BUSY processes that spin (`sh -c 'while :; do :; done'`, nice 0, the tests' own
priority), runs every end-to-end rostest (the catkin targets run_tests_amigobot_tracking_rostest_e2e_*,
JOBS at a time as `make test` runs them) PASSES times, and prints per pass the tests that
failed with the first line of each failure, then one line `under load: P of N passes clean`.
Each pass's JUnit files are kept in WS/build/under_load/pass-K. The busy loops are killed on
every exit. Exit 0 only when every pass was clean.
"""
import argparse
import glob
import os
import re
import shutil
import signal
import subprocess
import sys
import time
import xml.etree.ElementTree as ET

PROJECT = "amigobot_tracking"
PREFIX = f"run_tests_{PROJECT}_rostest_e2e_"


def e2e_targets(build_dir):
    """The e2e run_tests targets the configured build knows (new .test files join by themselves)."""
    out = subprocess.run(["make", "-C", build_dir, "help"], capture_output=True, text=True, check=True).stdout
    return sorted(set(re.findall(r"\b(" + PREFIX + r"\w+)", out)))


def start_busy(count):
    loops = []
    for _ in range(count):
        loops.append(subprocess.Popen(["nice", "-n", "0", "sh", "-c", "while :; do :; done"], start_new_session=True))
    return loops


def stop_busy(loops):
    for p in loops:
        if p.poll() is None:
            os.killpg(p.pid, signal.SIGKILL)
            p.wait()


def failures(results_dir):
    """(file, case, first line of the message) of every failed case under results_dir."""
    found = []
    for path in sorted(glob.glob(os.path.join(results_dir, "*.xml"))):
        try:
            root = ET.parse(path).getroot()
        except ET.ParseError as err:
            found.append((os.path.basename(path), "-", f"unreadable: {err}"))
            continue
        for case in root.iter("testcase"):
            bad = case.find("failure")
            if bad is None:
                bad = case.find("error")
            if bad is None:
                continue
            text = (bad.get("message") or bad.text or "").strip()
            found.append((os.path.basename(path), case.get("name"), text.splitlines()[0][:300] if text else ""))
    return found


def run_pass(ws, targets, jobs, keep):
    results = os.path.join(ws, "build", "test_results", PROJECT)
    for old in glob.glob(os.path.join(results, "*e2e_*")):
        os.remove(old)
    started = time.time()
    rc = subprocess.run(["make", "-C", os.path.join(ws, "build"), "-k", f"-j{jobs}"] + targets,
                        stdout=subprocess.DEVNULL, stderr=subprocess.STDOUT).returncode
    shutil.rmtree(keep, ignore_errors=True)
    os.makedirs(keep)
    for path in glob.glob(os.path.join(results, "*e2e_*")):
        shutil.move(path, keep)
    return rc, time.time() - started


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--ws", required=True, help="catkin workspace, built (make test-under-load builds it)")
    parser.add_argument("--passes", type=int, default=1)
    parser.add_argument("--busy", type=int, default=2, help="busy loops (the machine's cores: 2)")
    parser.add_argument("--jobs", type=int, default=2, help="tests run side by side")
    parser.add_argument("--only", nargs="*", default=[], help="e2e test names (diamond, tracking, ...): these only")
    args = parser.parse_args()
    if args.passes < 1 or args.busy < 0 or args.jobs < 1:
        sys.exit("under_load.py: --passes and --jobs must be >= 1, --busy >= 0")
    targets = e2e_targets(os.path.join(args.ws, "build"))
    if args.only:
        unknown = [n for n in args.only if PREFIX + n not in targets]
        if unknown:
            sys.exit(f"under_load.py: no e2e test named {', '.join(unknown)} (known: "
                     f"{', '.join(t[len(PREFIX):] for t in targets)})")
        targets = [PREFIX + n for n in args.only]
    if not targets:
        sys.exit(f"under_load.py: no {PREFIX}* target in {args.ws}/build (is the workspace configured?)")
    loops = start_busy(args.busy)
    signal.signal(signal.SIGTERM, lambda *_: sys.exit(143))
    clean = 0
    try:
        print(f"under load: {len(targets)} e2e tests x {args.passes} passes, {args.busy} busy loops, "
              f"{args.jobs} tests at a time", flush=True)
        for k in range(1, args.passes + 1):
            keep = os.path.join(args.ws, "build", "under_load", f"pass-{k}")
            rc, took = run_pass(args.ws, targets, args.jobs, keep)
            bad = failures(keep)
            ran = len(glob.glob(os.path.join(keep, "rostest-e2e_*.xml")))
            load = os.getloadavg()[0]
            verdict = "clean" if not bad and rc == 0 and ran == len(targets) else "FAILED"
            print(f"pass {k}: {verdict}: {ran} of {len(targets)} tests ran, {len(bad)} failed cases, runner exit {rc}, "
                  f"{took:.0f} s, load average {load:.1f}", flush=True)
            for file, case, text in bad:
                print(f"  FAILED {file} {case}: {text}", flush=True)
            clean += verdict == "clean"
    finally:
        stop_busy(loops)
    print(f"under load: {clean} of {args.passes} passes clean (results in {args.ws}/build/under_load)")
    return 0 if clean == args.passes else 1


if __name__ == "__main__":
    sys.exit(main())
