#!/usr/bin/env python3
"""Fit the robot's dynamics (ramps, latency, wheel-speed limit) to a recorded run.

Reads a bag with the commands the driver received (geometry_msgs/Twist on cmd_vel, timed by
the bag's receive time) and its odometry (nav_msgs/Odometry, timed by header.stamp, twist =
the velocities the firmware reported), writes them as the CSV `amigobot_sim --identify` reads
(lines cmd|odom,t,v,w) and runs it. Record on the machine that runs the driver, so the two
streams share one clock; drive steps in v and in w, stops, reversals and one fast turn.

  scripts/tools/identify_robot.py RUN.bag --out config/robots/my_robot.yaml [--sim PATH]
"""
import argparse
import os
import subprocess
import sys
import tempfile


def bag_to_csv(bag_path, csv_path, cmd_topic, odom_topic):
    """Writes the CSV; returns (commands, odometry) counts."""
    import rosbag  # Debian's python3-rosbag; only this script needs it

    counts = {"cmd": 0, "odom": 0}
    with rosbag.Bag(bag_path) as bag, open(csv_path, "w") as out:
        out.write("# kind,t [s],v [m/s],w [rad/s] from %s\n" % bag_path)
        for topic, msg, stamp in bag.read_messages(topics=[cmd_topic, odom_topic]):
            if topic == cmd_topic:
                out.write("cmd,%.6f,%.6f,%.6f\n" % (stamp.to_sec(), msg.linear.x, msg.angular.z))
                counts["cmd"] += 1
            else:
                twist = msg.twist.twist
                out.write("odom,%.6f,%.6f,%.6f\n" % (msg.header.stamp.to_sec(), twist.linear.x, twist.angular.z))
                counts["odom"] += 1
    return counts["cmd"], counts["odom"]


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("bag")
    parser.add_argument("--out", required=True, help="the robot YAML to write")
    parser.add_argument("--sim", default="amigobot_sim", help="the amigobot_sim executable (default: on PATH)")
    parser.add_argument("--cmd-topic", default="/cmd_vel")
    parser.add_argument("--odom-topic", default="/odom")
    parser.add_argument("--half-track", type=float, default=None, help="half the wheel track [m] (default: the AmigoBot's)")
    parser.add_argument("--keep-csv", default=None, help="also keep the CSV here")
    args = parser.parse_args()
    if not os.path.isfile(args.bag):
        sys.exit(f"identify_robot: {args.bag}: no such file")
    csv_path = args.keep_csv or os.path.join(tempfile.mkdtemp(prefix="identify_"), "run.csv")
    commands, odometry = bag_to_csv(args.bag, csv_path, args.cmd_topic, args.odom_topic)
    if commands == 0 or odometry == 0:
        sys.exit(f"identify_robot: {args.bag}: {commands} messages on {args.cmd_topic}, {odometry} on "
                 f"{args.odom_topic}; both are needed")
    cmd = [args.sim, "--identify", csv_path, "--identify-out", args.out]
    if args.half_track is not None:
        cmd += ["--half-track", str(args.half_track)]
    return subprocess.call(cmd)


if __name__ == "__main__":
    sys.exit(main())
