#!/usr/bin/python3
"""sim.launch runs: odom, scan and commands flow; map -> base_link equals the emulator's true
pose (ground_truth_localization, REP 105); the tracking loop runs and moves the robot; the laser
and world_markers show the default world's walls."""
import math
import threading
import time
import unittest

import rospy
import rostest
import tf2_ros
from geometry_msgs.msg import Twist
from nav_msgs.msg import Odometry
from sensor_msgs.msg import LaserScan
from visualization_msgs.msg import MarkerArray

from amigobot_tracking.msg import TrackingState


class Latest:
    def __init__(self, topic, kind):
        self.lock = threading.Lock()
        self.msg, self.count = None, 0
        rospy.Subscriber(topic, kind, self.store, queue_size=10)

    def store(self, msg):
        with self.lock:
            self.msg, self.count = msg, self.count + 1


def wait(predicate, timeout):
    deadline = time.time() + timeout
    while time.time() < deadline and not rospy.is_shutdown():
        if predicate():
            return True
        time.sleep(0.1)
    return False


class SimLaunch(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        rospy.init_node("test_sim_launch")
        cls.odom = Latest("/odom", Odometry)
        cls.scan = Latest("/scan", LaserScan)
        cls.cmd = Latest("/cmd_vel", Twist)
        cls.truth = Latest("/ground_truth", Odometry)
        cls.state = Latest("/tracking/state", TrackingState)
        cls.world = Latest("/world_markers", MarkerArray)
        cls.tf = tf2_ros.Buffer()
        cls.listener = tf2_ros.TransformListener(cls.tf)
        # Generous: the whole stack starts on a shared 2-core machine.
        wait(lambda: cls.state.msg is not None and cls.state.msg.valid, 60)

    def test_odom_scan_and_commands_flow(self):
        self.assertTrue(wait(lambda: self.odom.count > 5 and self.scan.count > 5 and self.cmd.count > 5, 30),
                        f"odom {self.odom.count}, scan {self.scan.count}, cmd_vel {self.cmd.count} messages")
        scan = self.scan.msg
        self.assertEqual(scan.header.frame_id, "laser")
        hits = [r for r in scan.ranges if math.isfinite(r)]
        # sim.launch's world (config/worlds/lab.yaml) encloses the robot: every beam meets a
        # wall except those through the 0.9 m doorway (< 35 degrees of the 270 seen).
        self.assertGreater(len(hits), 0.8 * len(scan.ranges), "the laser does not see the room's walls")
        self.assertTrue(all(scan.range_min <= r <= scan.range_max for r in hits))

    def test_world_markers_draw_the_room(self):
        self.assertTrue(wait(lambda: self.world.msg is not None, 30), "no /world_markers")
        kinds = [m.ns for m in self.world.msg.markers]
        self.assertGreaterEqual(kinds.count("walls"), 9, "lab.yaml's outline has 9 wall segments")
        self.assertGreaterEqual(kinds.count("polygons"), 2, "lab.yaml's table and cabinet")
        self.assertTrue(all(m.header.frame_id == "map" for m in self.world.msg.markers[1:]))

    def test_map_to_base_link_is_the_true_pose(self):
        self.assertTrue(wait(lambda: self.truth.msg is not None, 30), "no /ground_truth")
        worst = 0.0
        for _ in range(10):  # several samples while the robot moves
            truth = self.truth.msg.pose.pose.position
            t = self.tf.lookup_transform("map", "base_link", rospy.Time(0), rospy.Duration(5.0))
            worst = max(worst, math.hypot(t.transform.translation.x - truth.x, t.transform.translation.y - truth.y))
            time.sleep(0.3)
        # Odometry (10 Hz SIPs) and the true pose are sampled at slightly different times.
        self.assertLess(worst, 0.1)

    def test_tracking_moves_the_robot_after_the_target(self):
        self.assertTrue(wait(lambda: self.truth.msg is not None, 30), "no /ground_truth")
        start = self.truth.msg.pose.pose.position
        self.assertTrue(wait(lambda: math.hypot(self.truth.msg.pose.pose.position.x - start.x,
                                                self.truth.msg.pose.pose.position.y - start.y) > 0.2, 60),
                        "the robot did not move 0.2 m")
        state = self.state.msg
        self.assertTrue(state.enabled)
        self.assertEqual(state.status, "tracking")
        self.assertLess(abs(state.v) / 0.3 + abs(state.omega) / 0.8, 1.0 + 1e-6)


if __name__ == "__main__":
    rostest.rosrun("amigobot_tracking", "sim_launch", SimLaunch)
