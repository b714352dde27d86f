#!/usr/bin/python3
"""Nothing recorded as NaN: every floating-point field of every message in the bags, walked
generically, must be finite, except where a standard or our message allows otherwise (the same
rules as test/e2e/include/finite_messages.h, which the e2e and rostest runs apply live):

  sensor_msgs/LaserScan ranges            +inf, -inf (REP 117: no return / closer than range_min)
  sensor_msgs/Range range                 +inf, -inf (REP 117)
  amigobot_tracking/TrackingState         min_clearance, min_clearance_body, pose_age, target_age: +inf
  diagnostic_msgs/KeyValue value          text: one that reads as a number must not be NaN or -inf

Usage: check_bag_finite.py BAG [BAG...]  (a ROS environment with the messages). Prints the
messages and topics checked and every field that broke the rule (the first 20); exit 1 then.
"""
import math
import sys

import rosbag

ALLOWED = {  # (message type, field) -> the non-finite values it may hold
    ("sensor_msgs/LaserScan", "ranges"): (math.inf, -math.inf),
    ("sensor_msgs/Range", "range"): (math.inf, -math.inf),
    ("amigobot_tracking/TrackingState", "min_clearance"): (math.inf,),
    ("amigobot_tracking/TrackingState", "min_clearance_body"): (math.inf,),
    ("amigobot_tracking/TrackingState", "pose_age"): (math.inf,),
    ("amigobot_tracking/TrackingState", "target_age"): (math.inf,),
}


def bad_value(value, allowed):
    return not math.isfinite(value) and not any(value == a for a in allowed)


def number_in_text(text):
    try:
        return float(text)
    except ValueError:
        return None


def problems(msg, path=""):
    """(field path, value) of every field of msg (nested, arrays included) that breaks the rules."""
    out = []
    for name, kind in zip(msg.__slots__, msg._slot_types):  # pylint: disable=protected-access
        value = getattr(msg, name)
        where = path + name
        allowed = ALLOWED.get((msg._type, name), ())  # pylint: disable=protected-access
        base = kind.split("[")[0]
        if base in ("float32", "float64"):
            values = value if "[" in kind else [value]
            out += [("%s[%d]" % (where, i) if "[" in kind else where, v) for i, v in enumerate(values)
                    if bad_value(v, allowed)]
        elif msg._type == "diagnostic_msgs/KeyValue" and name == "value":  # pylint: disable=protected-access
            v = number_in_text(value)
            if v is not None and bad_value(v, (math.inf,)):
                out.append((where, value))
        elif hasattr(value, "_type"):  # a nested message (not a Time or Duration)
            out += problems(value, where + ".")
        elif "[" in kind and value and hasattr(value[0], "_type"):
            for i, item in enumerate(value):
                out += problems(item, "%s[%d]." % (where, i))
    return out


def main(paths):
    messages, topics, found = 0, set(), []
    for path in paths:
        with rosbag.Bag(path) as bag:
            for topic, msg, stamp in bag.read_messages():
                messages += 1
                topics.add(topic)
                for field, value in problems(msg):
                    found.append("%s %s at %.3f: %s = %r" % (path, topic, stamp.to_sec(), field, value))
    print("check_bag_finite: %d messages on %d topics checked (%s): %s" % (
        messages, len(topics), " ".join(sorted(topics)),
        "no message: nothing checked" if messages == 0 else
        "nothing non-finite where it is not allowed" if not found else "%d fields break the rule" % len(found)))
    for line in found[:20]:
        print("  " + line)
    return 1 if found or messages == 0 else 0


if __name__ == "__main__":
    if len(sys.argv) < 2 or sys.argv[1] in ("-h", "--help"):
        print(__doc__)
        sys.exit(0 if len(sys.argv) >= 2 else 2)
    sys.exit(main(sys.argv[1:]))
