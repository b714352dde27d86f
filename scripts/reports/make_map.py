#!/usr/bin/python3
"""make map: builds a world's map by SLAM (the pose graph) on the emulated robot, as a lab maps a new room.

Starts a private ROS master on a free port and runs sim.launch headless with
localization:=slam (the Localization nodelet in mapping mode, the real laser chain), a tour
for the target (reference_publisher parameters, config/maps/WORLD_tour.yaml) that the
tracking stack follows closed-loop on the map being built; when the tour is over it calls
/localization/save_map, which writes OUT.yaml + OUT.pgm (map_server's format), stops
everything it started, and compares the map with the world file (world_map --compare).
Exit 0: map written; 4: the run or the save failed (logs in OUT_logs/ under report/).
Usage: make_map.py [--ws WS] [--world config/worlds/lab.yaml] [--out config/maps/lab.yaml]
"""
import argparse
import math
import os
import shutil
import subprocess
import sys
import time

import yaml

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "test"))
import stack_processes as sp  # noqa: E402

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
START_DELAY_S = 8.0  # the target waits this long after the launch
SETTLE_S = 6.0       # after the tour, before the map is saved
DEMO_PARAMS = os.path.join(ROOT, "config", "demo_tracking.yaml")


def log(msg):
    print(f"[map {time.strftime('%H:%M:%S')}] {msg}", flush=True)


def tour_duration(tour_file):
    """[s] of a waypoints tour: its length over its speed, times time_scale."""
    with open(tour_file) as f:
        tour = yaml.safe_load(f)
    ref = tour["reference"]
    if ref.get("type") != "waypoints":
        raise RuntimeError(f"{tour_file}: reference/type must be waypoints")
    pts = ref["waypoints"]
    length = sum(math.dist(a, b) for a, b in zip(pts, pts[1:]))
    return length / float(ref.get("speed", 0.2)) * float(tour.get("time_scale", 1.0))


def initial_pose(world_file):
    with open(world_file) as f:
        pose = (yaml.safe_load(f) or {}).get("initial_pose", [0.0, 0.0, 0.0])
    return [float(v) for v in pose]


def call(args, env, timeout=30):
    return subprocess.run(args, env=env, capture_output=True, text=True, timeout=timeout)


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--ws", default=sp.default_workspace(), help="catkin workspace (built)")
    parser.add_argument("--world", default=os.path.join(ROOT, "config", "worlds", "lab.yaml"), help="world YAML")
    parser.add_argument("--tour", help="reference_publisher YAML of the tour (default: config/maps/WORLD_tour.yaml)")
    parser.add_argument("--out", help="map YAML to write (default: config/maps/WORLD.yaml; the PGM beside it)")
    args = parser.parse_args()
    name = os.path.splitext(os.path.basename(args.world))[0]
    tour = os.path.abspath(args.tour or os.path.join(ROOT, "config", "maps", f"{name}_tour.yaml"))
    out = os.path.abspath(args.out or os.path.join(ROOT, "config", "maps", f"{name}.yaml"))
    logs = os.path.join(ROOT, "report", f"map_{name}_logs")
    shutil.rmtree(logs, ignore_errors=True)
    os.makedirs(logs)
    duration = tour_duration(tour)
    x, y, yaw = initial_pose(args.world)

    master = sp.free_port()
    env = sp.ros_env(os.path.join(args.ws, "devel", "setup.bash"), master, os.path.join(logs, "ros_home"))
    procs = sp.Processes(logs)
    try:
        sp.start_master(procs, env, master)
        tcp, status, laser = sp.free_port(), sp.free_port(), sp.free_port()
        launch = procs.start("sim_launch", ["roslaunch", "amigobot_tracking", "sim.launch", f"world:={args.world}",
                                            f"reference:={tour}", "localization:=slam", f"map_file:={out}",
                                            f"initial_x:={x}", f"initial_y:={y}", f"initial_yaw:={yaw}",
                                            f"tcp_port:={tcp}", f"status_port:={status}", f"laser_port:={laser}",
                                            f"start_delay:={START_DELAY_S}", f"tracking_params:={DEMO_PARAMS}"], env)
        t_launch = time.time()
        deadline = t_launch + 90
        while not call(["rosservice", "info", "/tracking/enable"], env).returncode == 0:
            if launch.poll() is not None or time.time() > deadline:
                raise RuntimeError("sim.launch did not come up (logs/sim_launch.log)")
            time.sleep(0.5)
        log("tracking/enable: " + " ".join(call(["rosservice", "call", "/tracking/enable"], env).stdout.split()))
        t_end = t_launch + START_DELAY_S + duration + SETTLE_S
        log(f"mapping {args.world} along {tour} ({duration:.0f} s of tour); saving in {t_end - time.time():.0f} s")
        while time.time() < t_end:
            if launch.poll() is not None:
                raise RuntimeError("sim.launch stopped during the tour (logs/sim_launch.log)")
            time.sleep(1.0)
        call(["rosservice", "call", "/tracking/disable"], env)
        res = call(["rosservice", "call", "/localization/save_map"], env, timeout=60)
        log("localization/save_map: " + " ".join(res.stdout.split()) + res.stderr.strip())
        if res.returncode != 0 or "success: True" not in res.stdout:
            raise RuntimeError("save_map failed")
    except (RuntimeError, subprocess.SubprocessError, OSError) as err:
        log(f"FAILED: {err}; logs in {logs}")
        return 4
    finally:
        procs.stop()
    check = subprocess.run([os.path.join(args.ws, "devel", "lib", "amigobot_tracking", "world_map"), "--world",
                            args.world, "--compare", out], capture_output=True, text=True)
    sys.stdout.write(check.stdout)
    sys.stderr.write(check.stderr)
    log(f"map: {out} (+ .pgm); logs in {logs}")
    return 0 if check.returncode == 0 else 4


if __name__ == "__main__":
    sys.exit(main())
