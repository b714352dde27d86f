#!/usr/bin/python3
"""Prints the AmigoBot URDF with the laser mount pose and an optional frame prefix set.

Plain URDF has no arguments (xacro is not packaged on Debian 12), so launch files call this:
  <param name="robot_description"
         command="$(find amigobot_tracking)/scripts/nodes/urdf_with_laser.py --laser-x 0.11 --prefix robot1/"/>
"""
import argparse
import os
import sys
import xml.etree.ElementTree as ET

DEFAULT_URDF = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "urdf", "amigobot.urdf")


def build(urdf_path, laser_xyz, laser_yaw, prefix, fixed_wheels=False):
    try:
        tree = ET.parse(urdf_path)
    except (OSError, ET.ParseError) as err:
        sys.exit(f"urdf_with_laser: cannot read {urdf_path}: {err}")
    robot = tree.getroot()
    joint = robot.find("joint[@name='laser_joint']")
    if joint is None:
        sys.exit(f"urdf_with_laser: {urdf_path} has no joint named laser_joint")
    origin = joint.find("origin")
    origin.set("xyz", " ".join(f"{v:g}" for v in laser_xyz))
    origin.set("rpy", f"0 0 {laser_yaw:g}")
    if fixed_wheels:
        # The driver publishes no joint_states: fixed wheels let robot_state_publisher
        # place them (on /tf_static) so rviz draws the whole robot.
        for element in robot.iter("joint"):
            if element.get("type") == "continuous":
                element.set("type", "fixed")
                for axis in element.findall("axis"):
                    element.remove(axis)
    if prefix:
        for link in robot.iter("link"):
            link.set("name", prefix + link.get("name"))
        for tag in ("parent", "child"):
            for element in robot.iter(tag):
                element.set("link", prefix + element.get("link"))
        for element in robot.iter("joint"):
            element.set("name", prefix + element.get("name"))
    return ET.tostring(robot, encoding="unicode")


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--urdf", default=DEFAULT_URDF, help="input URDF (default: the package's)")
    parser.add_argument("--laser-x", type=float, default=0.11, help="laser x in base_link [m]")
    parser.add_argument("--laser-y", type=float, default=0.0, help="laser y in base_link [m]")
    parser.add_argument("--laser-z", type=float, default=0.2, help="laser z in base_link [m]")
    parser.add_argument("--laser-yaw", type=float, default=0.0, help="laser yaw in base_link [rad]")
    parser.add_argument("--prefix", default="", help="prefix for every link and joint name, e.g. robot1/")
    parser.add_argument("--fixed-wheels", action="store_true",
                        help="make the wheel joints fixed (no joint_states publisher needed)")
    # roslaunch appends __name:= style arguments to some commands; ignore them.
    args, _ = parser.parse_known_args()
    print(build(args.urdf, (args.laser_x, args.laser_y, args.laser_z), args.laser_yaw, args.prefix, args.fixed_wheels))


if __name__ == "__main__":
    main()
