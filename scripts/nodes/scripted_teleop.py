#!/usr/bin/python3
"""scripted_teleop: a repeatable tele-operation. Drives a robot through the amigobot driver by
publishing geometry_msgs/Twist on cmd_vel from a list of (duration, v, w) segments, after
enabling its motors, e.g. the target robot of two_robots.launch (run it in namespace target).

Private parameters (a bad value stops the node before anything moves, naming the key):
  segments      list of [duration s > 0, v m/s, w rad/s], required: driven in order
  rate          double, Hz, 10: Twist rate while driving (>= 5: the driver stops after its
                cmd_vel_timeout, 0.6 s, without one)
  autostart     bool, true: drive once the motors are on (after start_delay); false: wait for
                a call of ~start (std_srvs/Trigger), e.g. from a test once the tracker is ready
  start_delay   double, s, 0: wait this long after the motors are on before the first segment
  enable_motors bool, true: call the driver's enable_motors (std_srvs/Empty) first and wait
                for its motors_state (std_msgs/Bool) to say true
  stop_time     double, s, 1: zero Twists sent at `rate` after the last segment
Topics: publishes cmd_vel (geometry_msgs/Twist) and ~segment (std_msgs/Int32, latched: -1
before the first segment, then the index of the running one, len(segments) once done).
Services: ~start (std_srvs/Trigger) starts the script (when autostart is false).
Example (YAML under the node):  segments: [[10, 0.15, 0.0], [5, 0.15, 0.3], [3, 0.0, 0.0]]
"""
import math
import sys
import threading

import rospy
from geometry_msgs.msg import Twist
from std_msgs.msg import Bool, Int32
from std_srvs.srv import Empty, Trigger, TriggerResponse


def number(value):
    return isinstance(value, (int, float)) and not isinstance(value, bool) and math.isfinite(value)


def parse_segments(raw):
    """[(duration, v, w)] from the ~segments parameter; raises ValueError naming what is wrong."""
    if not isinstance(raw, list) or not raw:
        raise ValueError("~segments must be a non-empty list of [duration, v, w]")
    segments = []
    for i, entry in enumerate(raw):
        if not (isinstance(entry, list) and len(entry) == 3 and all(number(x) for x in entry)):
            raise ValueError("~segments[%d] must be [duration s, v m/s, w rad/s], got %r" % (i, entry))
        if entry[0] <= 0:
            raise ValueError("~segments[%d]: duration must be > 0, got %r" % (i, entry[0]))
        segments.append(tuple(float(x) for x in entry))
    return segments


def read_config():
    config = {
        "segments": parse_segments(rospy.get_param("~segments", None)),
        "rate": rospy.get_param("~rate", 10.0),
        "autostart": rospy.get_param("~autostart", True),
        "start_delay": rospy.get_param("~start_delay", 0.0),
        "enable_motors": rospy.get_param("~enable_motors", True),
        "stop_time": rospy.get_param("~stop_time", 1.0),
    }
    if not number(config["rate"]) or config["rate"] < 5.0:
        raise ValueError("~rate must be a number >= 5 Hz, got %r" % config["rate"])
    for key in ("start_delay", "stop_time"):
        if not number(config[key]) or config[key] < 0:
            raise ValueError("~%s must be a number >= 0 s, got %r" % (key, config[key]))
    for key in ("autostart", "enable_motors"):
        if not isinstance(config[key], bool):
            raise ValueError("~%s must be true or false, got %r" % (key, config[key]))
    return config


class ScriptedTeleop:
    def __init__(self, config):
        self.config = config
        self.cmd_pub = rospy.Publisher("cmd_vel", Twist, queue_size=1)
        self.segment_pub = rospy.Publisher("~segment", Int32, queue_size=1, latch=True)
        self.segment_pub.publish(Int32(-1))
        self.started = threading.Event()
        self.motors_on = threading.Event()
        rospy.Service("~start", Trigger, self.on_start)
        rospy.Subscriber("motors_state", Bool, lambda m: self.motors_on.set() if m.data else None, queue_size=1)

    def on_start(self, _request):
        self.started.set()
        return TriggerResponse(success=True, message="scripted teleop started")

    def enable_motors(self):
        service = rospy.resolve_name("enable_motors")
        rospy.loginfo("scripted_teleop: enabling the motors (%s)", service)
        while not rospy.is_shutdown() and not self.motors_on.is_set():
            try:
                rospy.wait_for_service(service, timeout=5.0)
                rospy.ServiceProxy(service, Empty)()
            except (rospy.ROSException, rospy.ServiceException) as e:
                rospy.logwarn_throttle(10.0, "scripted_teleop: %s: %s" % (service, e))
            self.motors_on.wait(1.0)

    def drive(self, v, w, duration, index):
        self.segment_pub.publish(Int32(index))
        rospy.loginfo("scripted_teleop: segment %d: %.2f s at v %.3f m/s, w %.3f rad/s", index, duration, v, w)
        twist = Twist()
        twist.linear.x, twist.angular.z = v, w
        rate = rospy.Rate(self.config["rate"])
        end = rospy.get_time() + duration
        while not rospy.is_shutdown() and rospy.get_time() < end:
            self.cmd_pub.publish(twist)
            rate.sleep()

    def run(self):
        if self.config["enable_motors"]:
            self.enable_motors()
        if not self.config["autostart"]:
            rospy.loginfo("scripted_teleop: waiting for %s", rospy.resolve_name("~start"))
            while not rospy.is_shutdown() and not self.started.wait(0.5):
                pass
        rospy.sleep(self.config["start_delay"])
        for index, (duration, v, w) in enumerate(self.config["segments"]):
            self.drive(v, w, duration, index)
        self.drive(0.0, 0.0, self.config["stop_time"], len(self.config["segments"]))
        rospy.loginfo("scripted_teleop: done")
        rospy.spin()  # stays up (the latched ~segment says done) until shut down


def main():
    rospy.init_node("scripted_teleop")
    try:
        config = read_config()
    except ValueError as e:
        rospy.logfatal("scripted_teleop refuses to start: %s", e)
        return 1
    rospy.loginfo("scripted_teleop: %d segments, %.1f s, at %.1f Hz", len(config["segments"]),
                  sum(s[0] for s in config["segments"]), config["rate"])
    try:
        ScriptedTeleop(config).run()
    except rospy.ROSInterruptException:
        pass
    return 0


if __name__ == "__main__":
    sys.exit(main())
