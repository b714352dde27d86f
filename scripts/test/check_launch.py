#!/usr/bin/python3
"""Checks a launch file without starting it: roslaunch's own check (packages and
dependencies it names), the node list resolves, and every node's executable is found.

Usage: check_launch.py FILE.launch [ARG:=VALUE ...]   (exit 0 when all checks pass)
"""
import subprocess
import sys

import roslaunch.rlutil


def main():
    if len(sys.argv) < 2:
        sys.exit(__doc__)
    path, args = sys.argv[1], sys.argv[2:]
    problem = roslaunch.rlutil.check_roslaunch(path)
    if problem:
        sys.exit(f"{path}: roslaunch check: {problem}")
    nodes = subprocess.run(["roslaunch", "--nodes", path] + args, capture_output=True, text=True)
    if nodes.returncode != 0 or not nodes.stdout.split():
        sys.exit(f"{path}: cannot list its nodes: {nodes.stderr.strip() or nodes.stdout.strip()}")
    for node in nodes.stdout.split():
        cmd = subprocess.run(["roslaunch", "--args", node, path] + args, capture_output=True, text=True)
        if cmd.returncode != 0:
            sys.exit(f"{path}: node {node}: {cmd.stderr.strip() or cmd.stdout.strip()}")
        print(f"{node}: {cmd.stdout.strip()[:160]}")
    params = subprocess.run(["roslaunch", "--dump-params", path] + args, capture_output=True, text=True)
    if params.returncode != 0:
        sys.exit(f"{path}: parameters do not load: {params.stderr.strip()}")
    print(f"{path}: {len(nodes.stdout.split())} nodes, parameters load")


if __name__ == "__main__":
    main()
