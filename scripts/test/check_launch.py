#!/usr/bin/python3
"""Checks launch files without starting them: roslaunch's own check (packages and
dependencies it names), the configuration loads with the given args (every <param>, <rosparam>
and <arg> resolves), and every node's executable is found — all in this one process through
roslaunch's Python API (one roslaunch process per node made ~25 launch checks cost minutes of
make test under load).

Usage:
  check_launch.py FILE.launch [ARG:=VALUE ...]          one configuration, exit 0 when it passes
  check_launch.py --list LIST --root DIR --xml OUT.xml  every configuration of LIST, one JUnit
                                                        case each (always exits 0 after writing)
LIST: one configuration a line, `NAME FILE [ARG:=VALUE ...]`, FILE relative to DIR/launch;
`{root}` in an argument stands for DIR; `#` starts a comment.
"""
import argparse
import os
import shlex
import sys
import time
import xml.etree.ElementTree as ET

import rosgraph.names
import roslaunch.config
import roslaunch.core
import roslaunch.node_args
import roslaunch.rlutil
import roslib.packages

# roslib walks the package's whole tree for each node it looks up (0.15 s a node, twice per
# configuration: roslaunch's check and the node's command line), and the same few executables
# recur in every configuration: each is looked up once per run (the list is checked in one process).
_find_node_uncached = roslib.packages.find_node
_found_nodes = {}


def _find_node_once(pkg, node_type, rospack=None):
    if (pkg, node_type) not in _found_nodes:
        _found_nodes[(pkg, node_type)] = _find_node_uncached(pkg, node_type, rospack=rospack)
    return _found_nodes[(pkg, node_type)]


roslib.packages.find_node = _find_node_once


def check(path, args):
    """Returns (ok, text): what was found, or the first problem."""
    saved = sys.argv
    sys.argv = ["roslaunch", path] + list(args)  # roslaunch's loader reads the args from sys.argv
    try:
        problem = roslaunch.rlutil.check_roslaunch(path)
        if problem:
            return False, f"{path}: roslaunch check: {problem}"
        config = roslaunch.config.load_config_default([path], None, verbose=False)
    except Exception as err:  # roslaunch raises several kinds; each names the file and element
        return False, f"{path}: does not load: {err}"
    finally:
        sys.argv = saved
    if not config.nodes:
        return False, f"{path}: no nodes"
    lines = []
    for node in config.nodes:
        name = rosgraph.names.ns_join(node.namespace, node.name)
        try:
            cmd = roslaunch.node_args.create_local_process_args(node, "check")
        except Exception as err:
            return False, f"{path}: node {name}: {err}"
        lines.append(f"{name}: {' '.join(cmd)[:160]}")
    lines.append(f"{path}: {len(config.nodes)} nodes, {len(config.params)} parameters load")
    return True, "\n".join(lines)


def run_list(list_path, root, xml_path):
    suite = ET.Element("testsuite", name="launch_checks", errors="0")
    failures = total = 0
    with open(list_path) as f:
        entries = [(n, line) for n, line in enumerate(f, 1) if line.split("#", 1)[0].strip()]
    for lineno, line in entries:
        words = shlex.split(line.split("#", 1)[0])
        if len(words) < 2:
            ok, text, name = False, f"{list_path}:{lineno}: expected NAME FILE [ARG:=VALUE ...]", f"line_{lineno}"
            elapsed = 0.0
        else:
            name, launch = words[0], os.path.join(root, "launch", words[1])
            args = [w.replace("{root}", root) for w in words[2:]]
            start = time.monotonic()
            try:
                ok, text = check(launch, args)
            except Exception as err:  # one broken configuration must not hide the others
                ok, text = False, f"{launch}: check failed: {type(err).__name__}: {err}"
            elapsed = time.monotonic() - start
        total += 1
        case = ET.SubElement(suite, "testcase", classname="launch", name=f"launch_{name}", time=f"{elapsed:.3f}")
        if not ok:
            failures += 1
            ET.SubElement(case, "failure", message=text.splitlines()[0][:500]).text = text
        ET.SubElement(case, "system-out").text = text
        print(f"launch_{name}: {'passed' if ok else 'FAILED: ' + text.splitlines()[0]} ({elapsed:.1f} s)")
    suite.set("tests", str(total))
    suite.set("failures", str(failures))
    os.makedirs(os.path.dirname(os.path.abspath(xml_path)), exist_ok=True)
    ET.ElementTree(suite).write(xml_path, encoding="utf-8", xml_declaration=True)
    print(f"launch checks: {total - failures} of {total} passed")


def main():
    if len(sys.argv) > 1 and sys.argv[1] == "--list":
        parser = argparse.ArgumentParser()
        parser.add_argument("--list", required=True)
        parser.add_argument("--root", required=True)
        parser.add_argument("--xml", required=True)
        a = parser.parse_args()
        run_list(a.list, os.path.abspath(a.root), a.xml)
        return
    if len(sys.argv) < 2:
        sys.exit(__doc__)
    ok, text = check(sys.argv[1], sys.argv[2:])
    print(text)
    sys.exit(0 if ok else 1)


if __name__ == "__main__":
    main()
