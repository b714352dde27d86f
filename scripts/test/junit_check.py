#!/usr/bin/python3
"""Runs one command as one test case and writes its JUnit XML (for checks that are not gtest).

Usage: junit_check.py --name NAME --xml RESULT.xml [--timeout S] -- COMMAND [ARGS...]
The case fails when the command exits non-zero or times out; its output is kept in the XML.
Always exits 0 after writing the XML: the test counter reads the verdict from the file.
"""
import argparse
import os
import subprocess
import sys
import time
import xml.etree.ElementTree as ET


def main():
    argv = sys.argv[1:]
    if "--" not in argv:
        sys.exit(__doc__)
    split = argv.index("--")
    parser = argparse.ArgumentParser()
    parser.add_argument("--name", required=True)
    parser.add_argument("--xml", required=True)
    parser.add_argument("--timeout", type=float, default=600.0)
    args = parser.parse_args(argv[:split])
    command = argv[split + 1:]

    start = time.monotonic()
    try:
        proc = subprocess.run(command, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True,
                              timeout=args.timeout)
        output, failure = proc.stdout, (f"exit code {proc.returncode}" if proc.returncode else None)
    except subprocess.TimeoutExpired as err:
        output = (err.stdout or b"").decode(errors="replace") if isinstance(err.stdout, bytes) else (err.stdout or "")
        failure = f"timed out after {args.timeout:g} s"
    except OSError as err:
        output, failure = "", f"cannot run {command[0]}: {err}"
    elapsed = time.monotonic() - start

    suite = ET.Element("testsuite", name=args.name, tests="1", failures="1" if failure else "0", errors="0",
                       time=f"{elapsed:.3f}")
    case = ET.SubElement(suite, "testcase", classname="check", name=args.name, time=f"{elapsed:.3f}")
    if failure:
        ET.SubElement(case, "failure", message=failure).text = output[-20000:]
    ET.SubElement(case, "system-out").text = output[-20000:]
    os.makedirs(os.path.dirname(os.path.abspath(args.xml)), exist_ok=True)
    ET.ElementTree(suite).write(args.xml, encoding="utf-8", xml_declaration=True)
    print(f"{args.name}: {'FAILED (' + failure + ')' if failure else 'passed'} in {elapsed:.1f} s")
    if failure:
        print(output[-4000:])


if __name__ == "__main__":
    main()
