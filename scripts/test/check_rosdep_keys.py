#!/usr/bin/python3
"""Checks that every rosdep key of package.xml resolves on Debian 12 and on ROS Noetic.

Usage: check_rosdep_keys.py ROSDISTRO_DIR [PACKAGE_XML]
ROSDISTRO_DIR is a checkout of ros/rosdistro (rosdep/base.yaml, rosdep/python.yaml,
noetic/distribution.yaml); it is not part of the tests because it needs that checkout.
Debian 12 is judged with ROS_DISTRO unset, Noetic on Ubuntu 20.04 (focal) with
ROS_DISTRO=noetic, after package.xml's conditions. A ROS package key (roscpp, ...) passes on
Noetic when noetic/distribution.yaml releases it; on Debian 12 Debian's own ROS packages
stand in for it (scripts/debian_packages*.txt), so only system keys are judged there.
Prints one line per key and exits 1 naming every key that does not resolve.
"""
import os
import sys

import yaml
from catkin_pkg.package import parse_package

PLATFORMS = {"debian": ("debian", "bookworm", ""), "noetic": ("ubuntu", "focal", "noetic")}


def system_rule(rules, os_name, codename):
    """The package list for os_name/codename, None when the key does not resolve there."""
    entry = rules.get(os_name)
    if isinstance(entry, dict):
        entry = entry[codename] if codename in entry else entry.get("*")
    return entry or None


def noetic_packages(distribution):
    names = set()
    for repo_name, repo in distribution["repositories"].items():
        release = repo.get("release")
        if release:
            names.update(release.get("packages", [repo_name]))
    return names


def keys_for(package_xml, ros_distro):
    env = dict(os.environ, ROS_DISTRO=ros_distro)
    package = parse_package(package_xml)
    package.evaluate_conditions(env)
    deps = (package.buildtool_depends + package.build_depends + package.exec_depends +
            package.test_depends)
    return sorted({d.name for d in deps if d.evaluated_condition})


def main():
    if len(sys.argv) not in (2, 3):
        sys.exit(__doc__)
    root = sys.argv[1]
    package_xml = sys.argv[2] if len(sys.argv) == 3 else os.path.join(os.path.dirname(__file__), "..", "..", "package.xml")
    rules = {}
    for name in ("base.yaml", "python.yaml"):
        with open(os.path.join(root, "rosdep", name)) as f:
            rules.update(yaml.safe_load(f))
    with open(os.path.join(root, "noetic", "distribution.yaml")) as f:
        ros_packages = noetic_packages(yaml.safe_load(f))
    bad = []
    for platform, (os_name, codename, ros_distro) in PLATFORMS.items():
        for key in keys_for(package_xml, ros_distro):
            if key in rules:
                found = system_rule(rules[key], os_name, codename)
                verdict = f"{os_name} {codename}: {found}" if found else f"no rule for {os_name} {codename}"
            elif key in ros_packages:
                found, verdict = True, "ROS package of noetic/distribution.yaml"
            elif not ros_distro:
                found, verdict = True, "ROS package (Debian's own ROS packages)"
            else:
                found, verdict = False, "neither a rosdep key nor a noetic package"
            print(f"{platform:7} {key:24} {'ok ' if found else 'BAD'} {verdict}")
            if not found:
                bad.append(f"{platform}: {key}")
    if bad:
        sys.exit("rosdep keys that do not resolve: " + ", ".join(bad))


if __name__ == "__main__":
    main()
