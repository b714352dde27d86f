#!/usr/bin/python3
"""external_laser.test's judge: amigobot.launch laser:=none scan_topic:=/front_laser/scan on the
emulated robot, the lab's driver (a standalone laser_node) on that topic. Judged from the real
topics and from the emulator's ground truth (/ground_truth, the world file), never from what
the stack says about itself alone:
  1. the scans reach the stack only through the lab's topic (its one publisher is the lab's
     driver; nothing publishes the stack's default `scan`), so whatever follows used them;
  2. localisation starts: localization_status ok, tf map -> odom, and map -> base_footprint
     within 0.1 m of the true pose;
  3. the tracking sees the world's disk in that scan: a laser obstacle marker on it and the
     body clearance of ~state equal to the true one;
  4. tracking/enable runs the controller on fresh inputs (the scan is required);
  5. the lab's driver killed: the tracking stops for a stale scan and its laser obstacles go,
     so they came from that driver.
The tests run in name order, 5 last."""
import math
import threading
import time
import unittest

import rosnode
import rospy
import rostest
import rosgraph
import tf2_ros
import yaml
from nav_msgs.msg import Odometry
from sensor_msgs.msg import LaserScan
from std_srvs.srv import Trigger
from visualization_msgs.msg import Marker, MarkerArray

from amigobot_tracking.msg import LocalizationStatus, TrackingState

LAB_TOPIC = "/front_laser/scan"
LAB_DRIVER = "/front_laser_driver"
ROBOT_RADIUS = 0.18  # [m] the URDF's body disk R, which ~state's min_clearance_body is taken from


class Latest:
    """The newest message of a topic and how many came, from the subscriber's thread."""

    def __init__(self, topic, kind):
        self.lock = threading.Lock()
        self.msg, self.count, self.when = None, 0, 0.0
        rospy.Subscriber(topic, kind, self.store, queue_size=5)

    def store(self, msg):
        with self.lock:
            self.msg, self.count, self.when = msg, self.count + 1, time.time()

    def get(self):
        with self.lock:
            return self.msg


def wait(predicate, timeout):
    deadline = time.time() + timeout
    while time.time() < deadline and not rospy.is_shutdown():
        if predicate():
            return True
        time.sleep(0.05)
    return False


class ExternalLaser(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        rospy.init_node("test_external_laser")
        with open(rospy.get_param("~world")) as f:
            disk = yaml.safe_load(f)["obstacles"][0]
        cls.disk_center, cls.disk_radius = disk["center"], disk["radius"]
        cls.scan = Latest(LAB_TOPIC, LaserScan)
        cls.status = Latest("/localization_status", LocalizationStatus)
        cls.state = Latest("/tracking/state", TrackingState)
        cls.markers = Latest("/tracking/markers", MarkerArray)  # built only while subscribed
        cls.truth = Latest("/ground_truth", Odometry)
        cls.tf = tf2_ros.Buffer()
        cls.listener = tf2_ros.TransformListener(cls.tf)

    def true_xy(self):
        p = self.truth.get().pose.pose.position
        return p.x, p.y

    def test_1_scans_come_only_on_the_lab_topic(self):
        self.assertTrue(wait(lambda: self.scan.count >= 5, 20), f"{self.scan.count} scans on {LAB_TOPIC}")
        self.assertEqual(self.scan.get().header.frame_id, "laser")
        publishers = dict(rosgraph.Master("/test_external_laser").getSystemState()[0])
        self.assertEqual(publishers.get(LAB_TOPIC), [LAB_DRIVER], "the lab's topic has another publisher")
        # With laser:=none the stack starts no Laser nodelet: no scan on its default topic.
        self.assertFalse(publishers.get("/scan"), "something publishes /scan")

    def test_2_localisation_starts_on_the_lab_scan(self):
        ok = wait(lambda: self.status.get() is not None and self.status.get().ok, 20)
        last = self.status.get()
        self.assertTrue(ok, "localization_status never ok: " + (last.reason if last else "none received"))
        self.tf.lookup_transform("map", "odom", rospy.Time(0), rospy.Duration(2.0))  # raises if absent
        self.assertTrue(wait(lambda: self.truth.get() is not None, 5), "no /ground_truth")
        t = self.tf.lookup_transform("map", "base_footprint", rospy.Time(0), rospy.Duration(2.0))
        x, y = self.true_xy()
        error = math.hypot(t.transform.translation.x - x, t.transform.translation.y - y)
        rospy.loginfo("localisation error %.3f m, match %.2f", error, self.status.get().match)
        self.assertLess(error, 0.1)

    def laser_disks(self):
        msg = self.markers.get()
        if msg is None:
            return []
        return [m for m in msg.markers if m.ns == "laser_obstacles" and m.action == Marker.ADD]

    def test_3_tracking_sees_the_disk_in_the_lab_scan(self):
        cx, cy = self.disk_center

        def on_disk():
            return any(math.hypot(m.pose.position.x - cx, m.pose.position.y - cy) < self.disk_radius + 0.1
                       for m in self.laser_disks())

        self.assertTrue(wait(on_disk, 10), f"no laser obstacle within 0.1 m of the disk at ({cx}, {cy}); "
                        f"{len(self.laser_disks())} laser obstacles")
        self.assertTrue(wait(lambda: self.truth.get() is not None, 5), "no /ground_truth")
        x, y = self.true_xy()
        # The disk is the nearest obstacle (every wall >= 3 m away), so ~state's body clearance
        # is to it. The tracker covers the arc it sees with disks of at most max_disk_radius
        # centred on the arc, nearer than the disk's centre: its clearance is the true one or up
        # to ~0.1 m less (measured 0.07 m), never more (that would be unsafe).
        expected = math.hypot(cx - x, cy - y) - self.disk_radius - ROBOT_RADIUS
        state = self.state.get()
        rospy.loginfo("tracking: %d obstacles, body clearance %.3f m (true %.3f m)", state.obstacles,
                      state.min_clearance_body, expected)
        self.assertGreater(state.obstacles, 0)
        self.assertLess(state.min_clearance_body, expected + 0.02)
        self.assertGreater(state.min_clearance_body, expected - 0.12)

    def test_4_tracking_runs_on_the_lab_scan(self):
        rospy.wait_for_service("/tracking/enable", 10)
        self.assertTrue(rospy.ServiceProxy("/tracking/enable", Trigger)().success)
        # require_scan is true: "tracking" needs a fresh scan, a pose and localisation ok.
        ok = wait(lambda: self.state.get().status == "tracking" and self.state.get().valid, 5)
        self.assertTrue(ok, "tracking status: " + self.state.get().status)

    def test_5_lab_driver_killed_tracking_stops_for_the_scan(self):
        self.assertTrue(wait(lambda: self.state.get().status == "tracking", 5), self.state.get().status)
        self.assertIn(LAB_DRIVER, rosnode.kill_nodes([LAB_DRIVER])[0])
        self.assertTrue(wait(lambda: self.state.get().status.startswith("scan is stale"), 3),
                        "status after the kill: " + self.state.get().status)
        # Timed from the last scan the driver sent: the stop is the tracking's scan_timeout
        # (0.5 s), not something else, within one control period (0.05 s), our 0.05 s polling and
        # slack; it may come earlier by up to one sweep (67 ms at 15 Hz) and a period, as the
        # scan is stamped at its first beam (measured 0.466-0.534 s).
        lag = time.time() - self.scan.when
        rospy.loginfo("scan stale %.3f s after the lab driver's last scan", lag)
        self.assertGreater(lag, 0.5 - 0.067 - 0.05 - 0.03)
        self.assertLess(lag, 0.5 + 0.05 + 0.15)
        self.assertTrue(wait(lambda: self.state.get().obstacles == 0, 2), f"{self.state.get().obstacles} obstacles")

if __name__ == "__main__":
    rostest.rosrun("amigobot_tracking", "external_laser", ExternalLaser)
