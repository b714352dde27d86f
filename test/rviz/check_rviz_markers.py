#!/usr/bin/python3
"""The shipped rviz display shows the tracking markers: under Xvfb with a private master,
sim.launch runs and rviz.launch opens the shipped display (its map display off: see
display_without_map); a screenshot with tracking disabled and no virtual obstacle
(baseline), then tracking is enabled and a virtual obstacle is published on the topic, and a
second screenshot must show, by colour (src/ros/markers.cpp), the rho circle (r + g = 1,
b = 0), the offset point (cyan 0, 1, 1) and the virtual obstacle (purple / magenta), none
of which the baseline shows. Exit 0 when all are seen; the screenshots stay in --out.

Usage: check_rviz_markers.py --ws WS [--out DIR]
"""
import argparse
import os
import subprocess
import sys
import tempfile
import time

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))
sys.path.insert(0, os.path.join(ROOT, "scripts", "test"))
import stack_processes as sp  # noqa: E402

SHIPPED_DISPLAY = os.path.join(ROOT, "config", "amigobot_tracking.rviz")
VIRTUAL = "{id: rviz_test, center: {x: 2.0, y: 1.0, z: 0.0}, radius: 0.3}"
# Pixel counts: a 0.3 m disk at the view's 130 px/m is ~4800 px, the 0.04 m offset point ~80
# px, the rho circle (>= 0.1 m radius, 2 px line) >= ~100 px.
NEEDED = {"rho circle": 40, "offset point": 20, "virtual obstacle": 400}
WIDTH, HEIGHT = 1280, 800  # the Xvfb screen (stack_processes.start_xvfb)
BASELINE_MAX = {"rho circle": 10, "offset point": 5, "virtual obstacle": 50}


def classes(png):
    """Pixel counts of each marker's colour in the screenshot."""
    raw = subprocess.run(["/usr/bin/convert", png, "-depth", "8", "rgb:-"], check=True, capture_output=True).stdout
    px = np.frombuffer(raw, dtype=np.uint8).astype(int).reshape(HEIGHT, WIDTH, 3)
    # Only the 3-D view: the bounding box of the shipped background colour (48, 48, 48); the
    # panels' icons (a red error sign, a green tick) must not count.
    background = np.all(px == 48, axis=2)
    cols, rows = np.nonzero(background.mean(axis=0) > 0.3)[0], np.nonzero(background.mean(axis=1) > 0.3)[0]
    if len(cols) == 0 or len(rows) == 0:
        raise RuntimeError(f"{png}: no rviz view (background 48, 48, 48) on the screen")
    view = px[rows.min():rows.max() + 1, cols.min():cols.max() + 1].reshape(-1, 3)
    r, g, b = view[:, 0], view[:, 1], view[:, 2]
    return {
        # LINE_STRIP (unlit) in (ratio, 1 - ratio, 0): r + g = 255, no blue.
        "rho circle": int(np.sum((np.abs(r + g - 255) <= 12) & (b <= 8) & (np.maximum(r, g) >= 120))),
        # CYLINDER (0, 1, 1), lit from the camera: cyan with g close to b (the safety ring is 0, 0.8, 1).
        "offset point": int(np.sum((r <= 40) & (g >= 170) & (b >= 170) & (np.abs(g - b) <= 20))),
        # CYLINDER (0.6, 0.2, 0.8) or (0.9, 0.1, 0.9) and the interactive disk: purple / magenta.
        "virtual obstacle": int(np.sum((r >= 90) & (b >= 120) & (g * 2 < np.minimum(r, b)))),
    }


def display_without_map(out):
    """The shipped rviz display with its Map display off, written into out: the map drawn over
    the view would hide the background colour by which classes() finds the view."""
    with open(SHIPPED_DISPLAY) as f:
        text = f.read()
    start = text.index("Class: rviz/Map")
    enabled = text.index("Enabled: true", start)
    path = os.path.join(out, "display_without_map.rviz")
    with open(path, "w") as f:
        f.write(text[:enabled] + "Enabled: false" + text[enabled + len("Enabled: true"):])
    return path


def shoot_until(display, png, done, timeout):
    """Screenshots into png every second until rviz's view is on the screen and done(counts)
    holds, or timeout [s] passes; returns the last counts (raises if no screenshot or no view
    ever came)."""
    deadline = time.time() + timeout
    while True:
        try:
            # xwd itself can fail while rviz maps its GL window: retry that like a missing view.
            sp.screenshot(display, png)
            counts = classes(png)
            if done(counts) or time.time() > deadline:
                return counts
        except (RuntimeError, subprocess.CalledProcessError):
            if time.time() > deadline:
                raise
        time.sleep(1.0)


def run(args):
    out = os.path.abspath(args.out or tempfile.mkdtemp(prefix="rviz_check_"))
    os.makedirs(out, exist_ok=True)
    master = sp.free_port()
    env = sp.ros_env(os.path.join(args.ws, "devel", "setup.bash"), master, os.path.join(out, "ros_home"))
    procs = sp.Processes(out)
    try:
        env["DISPLAY"] = sp.start_xvfb(procs)
        sp.start_master(procs, env, master)
        launch = procs.start("sim_launch", ["roslaunch", "amigobot_tracking", "sim.launch",
                                            f"pty:={out}/pty", "tcp_port:=-1", f"status_port:={sp.free_port()}",
                                            f"laser_port:={sp.free_port()}", "start_delay:=0"], env)
        # rviz.launch (what sim.launch rviz:=true includes) on the shipped display without its map.
        procs.start("rviz", ["roslaunch", "amigobot_tracking", "rviz.launch", f"config:={display_without_map(out)}"], env)

        def call(cmd):
            return subprocess.run(cmd, env=env, capture_output=True, text=True, timeout=60)

        deadline = time.time() + 90
        while call(["rosservice", "info", "/tracking/enable"]).returncode != 0:
            if time.time() > deadline or launch.poll() is not None:
                raise RuntimeError("sim.launch did not come up (sim_launch.log)")
            time.sleep(0.5)
        # rviz with software GL starts in 10-60 s depending on the machine's load: poll.
        baseline = os.path.join(out, "baseline.png")
        shoot_until(env["DISPLAY"], baseline, lambda counts: True, 90)
        time.sleep(2)  # first frames with the fixed frame resolved
        before = shoot_until(env["DISPLAY"], baseline, lambda counts: True, 30)
        if call(["rosservice", "call", "/tracking/enable"]).returncode != 0:
            raise RuntimeError("tracking/enable failed")
        res = call(["rostopic", "pub", "-1", "/tracking/virtual_obstacle", "amigobot_tracking/VirtualObstacle",
                    VIRTUAL])
        if res.returncode != 0:
            raise RuntimeError("cannot publish the virtual obstacle: " + res.stderr)
        shot = os.path.join(out, "tracking.png")
        after = shoot_until(env["DISPLAY"], shot,
                            lambda counts: all(counts[n] >= NEEDED[n] for n in NEEDED), 60)
    finally:
        procs.stop()
    failures = []
    for name in NEEDED:
        print(f"{name}: {before[name]} px before, {after[name]} px with tracking "
              f"(need <= {BASELINE_MAX[name]} and >= {NEEDED[name]})")
        if before[name] > BASELINE_MAX[name]:
            failures.append(f"the baseline already has {before[name]} px of the {name}'s colour")
        if after[name] < NEEDED[name]:
            failures.append(f"the {name} is not visible ({after[name]} px)")
    print(f"screenshots: {baseline} {shot}")
    if failures:
        print("FAILED: " + "; ".join(failures))
        return 1
    return 0


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--ws", required=True, help="built catkin workspace")
    parser.add_argument("--out", help="folder for screenshots and logs (default: a temporary one)")
    args = parser.parse_args()
    try:
        return run(args)
    except (RuntimeError, subprocess.SubprocessError, OSError) as err:
        print(f"FAILED: {err}")
        return 1


if __name__ == "__main__":
    sys.exit(main())
