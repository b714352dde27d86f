#!/usr/bin/python3
"""What the tracking side says, for scripts/test/two_machines.py's clock case: run inside the
tracker's machine, it prints one line per message, stamped with this computer's monotonic clock
(shared by every network namespace, so the harness can compare it with its own):

  <monotonic> diag <level> <message>     each /diagnostics status whose name contains NAME
  <monotonic> state <enabled> <status>   TrackingState, only when enabled or status change

Usage (a ROS environment): two_machines_status_probe.py NAME STATE_TOPIC
"""
import sys
import time

import rospy
from diagnostic_msgs.msg import DiagnosticArray

from amigobot_tracking.msg import TrackingState


def main():
    name, state_topic = sys.argv[1], sys.argv[2]
    rospy.init_node("two_machines_status_probe", anonymous=True, disable_signals=True)
    last = [None]

    def on_diagnostics(msg):
        for s in msg.status:
            if name in s.name:
                print("%.3f diag %d %s" % (time.monotonic(), s.level, s.message), flush=True)

    def on_state(msg):
        key = (msg.enabled, msg.status)
        if key != last[0]:
            last[0] = key
            print("%.3f state %d %s" % (time.monotonic(), int(msg.enabled), msg.status), flush=True)

    rospy.Subscriber("/diagnostics", DiagnosticArray, on_diagnostics, queue_size=50)
    rospy.Subscriber(state_topic, TrackingState, on_state, queue_size=50)
    print("%.3f ready" % time.monotonic(), flush=True)
    rospy.spin()


if __name__ == "__main__":
    try:
        main()
    except KeyboardInterrupt:
        pass
