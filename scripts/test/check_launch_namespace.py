#!/usr/bin/python3
"""Checks that `amigobot.launch robot:=NAME` puts everything of the robot under NAME, without
starting it (roslaunch's Python API, as check_launch.py): every node in /NAME/, every
parameter under /NAME/, every remapped topic resolved under /NAME/, every frame parameter
and every URDF link NAME/..., except the frames the robots share (global_frame: map) and
the target's frame (another robot's, given as an argument).

Usage: check_launch_namespace.py FILE.launch NAME [ARG:=VALUE ...]   exit 0: all under NAME
"""
import re
import sys
import xml.etree.ElementTree as ET

import roslaunch.config
from rosgraph.names import ns_join

# Parameters roslaunch adds itself, and frame parameters that name another robot's or the
# shared frame by design.
ROSLAUNCH_OWN = {"/run_id", "/rosdistro", "/rosversion"}
SHARED_FRAMES = {"map"}  # global_frame: one map for every robot
FRAME_KEY = re.compile(r"(^|_)frame(_id|_prefix)?$|_link$")


def resolve(ns, node, name):
    if name.startswith("/"):
        return name
    if name.startswith("~"):
        return ns_join(ns + node, name[1:])
    return ns_join(ns, name)


def problems(path, robot, args):
    saved = sys.argv
    sys.argv = ["roslaunch", path, f"robot:={robot}"] + list(args)
    try:
        config = roslaunch.config.load_config_default([path], None, verbose=False)
    finally:
        sys.argv = saved
    under = f"/{robot}/"
    found = []
    # The target's frame (target_frame:=, default `target`) is another robot's or the lab's.
    target = dict(a.split(":=", 1) for a in args if ":=" in a).get("target_frame", "target")
    shared = SHARED_FRAMES | {target}
    for node in config.nodes:
        ns = node.namespace if node.namespace.endswith("/") else node.namespace + "/"
        full = ns + node.name
        if not ns.startswith(under):
            found.append(f"node {full}: not under {under}")
        for src, dst in node.remap_args:
            target = resolve(ns, node.name, dst)
            if not target.startswith(under):
                found.append(f"node {full}: remap {src} -> {target}: not under {under}")
    for key, param in config.params.items():
        if key in ROSLAUNCH_OWN:
            continue
        if not key.startswith(under):
            found.append(f"parameter {key}: not under {under}")
            continue
        leaf = key.rsplit("/", 1)[1]
        if isinstance(param.value, str) and FRAME_KEY.search(leaf) and param.value not in shared:
            if not param.value.startswith(robot + "/"):
                found.append(f"parameter {key} = '{param.value}': a frame not under {robot}/")
        if leaf == "robot_description":
            for link in ET.fromstring(param.value).iter("link"):
                if not link.get("name", "").startswith(robot + "/"):
                    found.append(f"parameter {key}: URDF link '{link.get('name')}' not under {robot}/")
    if not config.nodes:
        found.append(f"{path}: no nodes")
    return found, len(config.nodes), len(config.params)


def main():
    if len(sys.argv) < 3:
        sys.exit(__doc__)
    path, robot, args = sys.argv[1], sys.argv[2], sys.argv[3:]
    found, nodes, params = problems(path, robot, args)
    for f in found:
        print(f)
    if found:
        print(f"{len(found)} name(s) of robot:={robot} outside /{robot}/")
        return 1
    print(f"robot:={robot} {' '.join(args)}: {nodes} nodes and {params} parameters, all under /{robot}/")
    return 0


if __name__ == "__main__":
    sys.exit(main())
