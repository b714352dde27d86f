#!/usr/bin/python3
"""Checks config/udev/99-amigobot.rules without udev (no udevadm here, no adapter plugged in):
every line parses as udev(7) rules do, and the rules give what the docs use.

A rule that udev cannot use is skipped by it with a log line nobody reads, and the robot's
port then silently keeps its ttyUSBn name, which can swap at boot (issue 21). So: each rule is
KEY[{attr}] OP "value" pairs separated by commas; `==`/`!=` only on match keys and the others
only on assignment keys (`ATTRS{serial}="..."` is the usual typo: an assignment udev refuses);
each rule matches on something and adds a SYMLINK with `+=` (`=` would drop the by-id links);
MODE is octal; USB ids are 4 hex digits; the links are exactly amigobot and laser
(docs/real_robot.md's `port:=/dev/amigobot laser_port:=/dev/laser`).

Usage: check_udev_rules.py RULES_FILE    (exit 1 naming the line and the problem)
"""
import re
import sys

MATCH_ONLY = {"ACTION", "DEVPATH", "KERNEL", "KERNELS", "SUBSYSTEM", "SUBSYSTEMS", "DRIVER", "DRIVERS",
              "ATTRS", "TAGS", "TEST", "PROGRAM", "RESULT", "CONST"}
ASSIGN_ONLY = {"OWNER", "GROUP", "MODE", "RUN", "LABEL", "GOTO", "IMPORT", "OPTIONS", "SECLABEL"}
BOTH = {"NAME", "SYMLINK", "ATTR", "ENV", "TAG", "SYSCTL"}
WITH_ATTRIBUTE = {"ATTR", "ATTRS", "ENV", "TEST", "IMPORT", "SYSCTL", "CONST"}
PAIR = re.compile(r'\s*([A-Z]+)(?:\{([^}]+)\})?\s*(==|!=|\+=|-=|:=|=)\s*"([^"]*)"\s*(,|$)')
LINKS = {"amigobot", "laser"}


def check_rule(text):
    """Problems of one rule line (empty: fine) and the SYMLINK names it adds."""
    problems, links, pos, matches = [], set(), 0, 0
    while pos < len(text):
        m = PAIR.match(text, pos)
        if not m:
            return [f"cannot parse from column {pos + 1}: {text[pos:pos + 30]!r} "
                    "(expected KEY[{attr}] OP \"value\", pairs separated by commas)"], links
        key, attribute, op, value, _ = m.groups()
        pos = m.end()
        known = MATCH_ONLY | ASSIGN_ONLY | BOTH
        if key not in known:
            problems.append(f"unknown key {key}")
            continue
        if (attribute is not None) != (key in WITH_ATTRIBUTE) and key != "IMPORT":
            problems.append(f"{key} " + ("takes no {attribute}" if attribute else "needs an {attribute}"))
        matching = op in ("==", "!=")
        if matching and key in ASSIGN_ONLY:
            problems.append(f"{key}{op}: {key} can only be assigned")
        if not matching and key in MATCH_ONLY:
            problems.append(f"{key}{{{attribute}}}{op}: {key} can only be matched (== or !=)" if attribute
                            else f"{key}{op}: {key} can only be matched (== or !=)")
        matches += matching
        if key == "SYMLINK" and not matching:
            if op != "+=":
                problems.append(f"SYMLINK{op}\"{value}\": use += (= replaces the other links, /dev/serial/by-id among them)")
            links.update(value.split())
        if key == "MODE" and not re.fullmatch(r"0?[0-7]{3}", value):
            problems.append(f"MODE \"{value}\" is not octal")
        if attribute in ("idVendor", "idProduct") and not re.fullmatch(r"[0-9a-f]{4}", value):
            problems.append(f"{attribute} \"{value}\" is not 4 lower-case hex digits (udev compares the text)")
    if not matches:
        problems.append("matches nothing (no == or !=): it would apply to every device")
    if not links:
        problems.append("adds no SYMLINK")
    return problems, links


def check(path):
    problems, links = [], set()
    with open(path) as f:
        lines = f.read().split("\n")
    for number, line in enumerate(lines, 1):
        if not line.strip() or line.lstrip().startswith("#"):
            continue
        if line.rstrip().endswith("\\"):
            problems.append(f"{path}:{number}: a continued line: keep each rule on one line")
            continue
        rule_problems, rule_links = check_rule(line.strip())
        problems += [f"{path}:{number}: {p}" for p in rule_problems]
        links |= rule_links
    if links != LINKS and not problems:
        problems.append(f"{path}: the links are {sorted(links)}, the docs use {sorted(LINKS)}")
    return problems


def main():
    if len(sys.argv) != 2:
        sys.exit(__doc__)
    problems = check(sys.argv[1])
    for p in problems:
        print(p, file=sys.stderr)
    if problems:
        return 1
    print(f"{sys.argv[1]}: every rule parses; links {sorted(LINKS)}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
