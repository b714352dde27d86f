#!/usr/bin/python3
"""check_bag_finite.py on bags it writes: a NaN command, a NaN scan range, a NaN number in
diagnostics, a NaN marker are found by field; the +-inf scan ranges, the +inf sonar range and
the +inf clearance and age REP 117 and TrackingState allow are not; an empty bag fails.

Usage: test_check_bag_finite.py PATH/TO/check_bag_finite.py  (a ROS environment)
"""
import os
import tempfile
import unittest

import rosbag
import rospy
from diagnostic_msgs.msg import DiagnosticArray, DiagnosticStatus, KeyValue
from geometry_msgs.msg import Twist
from sensor_msgs.msg import LaserScan, Range
from visualization_msgs.msg import Marker, MarkerArray

from amigobot_tracking.msg import TrackingState
from script_loader import load_script_from_argv

check = load_script_from_argv("check_bag_finite")
NAN, INF = float("nan"), float("inf")


def scan(ranges):
    return LaserScan(angle_min=-1.0, angle_max=1.0, angle_increment=1.0, scan_time=0.1, range_min=0.05,
                     range_max=20.0, ranges=ranges)


def diagnostics(value):
    return DiagnosticArray(status=[DiagnosticStatus(name="tracking", values=[KeyValue(key="age [s]", value=value)])])


class CheckBagFinite(unittest.TestCase):
    def setUp(self):
        self.tmp = tempfile.TemporaryDirectory()

    def tearDown(self):
        self.tmp.cleanup()

    def bag(self, messages):
        path = os.path.join(self.tmp.name, "run%d.bag" % len(os.listdir(self.tmp.name)))
        with rosbag.Bag(path, "w") as bag:
            for i, (topic, msg) in enumerate(messages):
                bag.write(topic, msg, rospy.Time(1 + i))
        return path

    def fields(self, messages):
        found = []
        for _, msg in messages:
            found += [f for f, _ in check.problems(msg)]
        return found

    def test_allowed_infinities_pass(self):
        state = TrackingState(min_clearance=INF, min_clearance_body=INF, target_age=INF)
        good = [("/scan", scan([1.0, INF, -INF])), ("/sonar", Range(range=INF, max_range=5.0)),
                ("/tracking/state", state), ("/cmd_vel", Twist()), ("/diagnostics", diagnostics("inf"))]
        self.assertEqual(self.fields(good), [])
        self.assertEqual(check.main([self.bag(good)]), 0)

    def test_each_nan_is_found_by_field(self):
        bad = Twist()
        bad.linear.x = NAN
        marker = MarkerArray(markers=[Marker(ns="rho", id=3)])
        marker.markers[0].scale.x = NAN
        state = TrackingState(v=NAN, min_clearance=-INF)
        messages = [("/cmd_vel", bad), ("/scan", scan([1.0, NAN])), ("/diagnostics", diagnostics("nan")),
                    ("/tracking/markers", marker), ("/tracking/state", state), ("/scan", scan([1.0]))]
        messages[-1][1].range_max = INF  # a scan's limits must be finite
        self.assertEqual(self.fields(messages), ["linear.x", "ranges[1]", "status[0].values[0].value",
                                                 "markers[0].scale.x", "v", "min_clearance", "range_max"])
        self.assertEqual(check.main([self.bag(messages)]), 1)

    def test_an_empty_bag_fails(self):
        self.assertEqual(check.main([self.bag([])]), 1)


if __name__ == "__main__":
    unittest.main()
