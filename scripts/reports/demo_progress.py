#!/usr/bin/python3
"""make demo's progress line every few seconds while the robot runs, instead of two silent
minutes: time left, the true tracking error ‖e*‖ = ‖p_d − p_r‖ with p_r the offset point of the
emulator's true pose (/ground_truth), the body's clearance to the nearest obstacle as the
tracking node sees it (laser + virtual), and the tracking node's state.

Usage: demo_progress.py --end EPOCH_S [--offset 0.3] [--period 5]   (in the run's ROS environment)
"""
import argparse
import math
import signal
import threading
import time

import rospy
from nav_msgs.msg import Odometry

from amigobot_tracking.msg import TrackingState


class Latest:
    """The newest message of a topic (callbacks run on rospy's threads)."""

    def __init__(self, topic, kind):
        self.lock = threading.Lock()
        self.msg = None
        rospy.Subscriber(topic, kind, self.store, queue_size=1)

    def store(self, msg):
        with self.lock:
            self.msg = msg

    def get(self):
        with self.lock:
            return self.msg


def true_error(state, truth, offset):
    """[m] ‖p_d − p_r‖ with p_r the offset point of the true pose; None until both arrived."""
    if state is None or truth is None:
        return None
    pose = truth.pose.pose
    yaw = 2.0 * math.atan2(pose.orientation.z, pose.orientation.w)
    return math.hypot(state.p_d.x - (pose.position.x + offset * math.cos(yaw)),
                      state.p_d.y - (pose.position.y + offset * math.sin(yaw)))


def line(left, state, truth, offset):
    """One progress line: every figure with its unit, '–' for what has not arrived yet."""
    error = true_error(state, truth, offset)
    text = f"{max(0.0, left):5.0f} s left | true ‖e‖ " + ("–" if error is None else f"{error:.3f} m")
    if state is None:
        return text + " | no tracking state yet"
    clearance = state.min_clearance_body
    text += " | clearance " + ("none in range" if not math.isfinite(clearance) else f"{clearance:.2f} m")
    flags = [name for name in ("avoiding", "saturated") if getattr(state, name)]
    return text + f" | {state.status}" + (f" ({', '.join(flags)})" if flags else "")


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--end", type=float, required=True, help="[s since the epoch] when the run ends")
    parser.add_argument("--offset", type=float, default=0.3, help="[m] offset r of the controlled point")
    parser.add_argument("--period", type=float, default=5.0, help="[s] between two lines")
    args = parser.parse_args()
    rospy.init_node("demo_progress", anonymous=True, disable_signals=True)
    state = Latest("/tracking/state", TrackingState)
    truth = Latest("/ground_truth", Odometry)
    left = args.end - time.time()
    while left > 0:
        time.sleep(min(args.period, left))
        left = args.end - time.time()
        print(f"[demo {time.strftime('%H:%M:%S')}] " + line(left, state.get(), truth.get(), args.offset),
              flush=True)
    # The demo stops every process with SIGINT as the run ends: arriving while rospy's exit hook
    # joins its threads, it printed a KeyboardInterrupt traceback under the last line, which
    # reads as a failure. The work is done, so the signal is ignored while the node shuts down.
    signal.signal(signal.SIGINT, signal.SIG_IGN)
    rospy.signal_shutdown("the run is over")


if __name__ == "__main__":
    try:
        main()
    except KeyboardInterrupt:
        pass
