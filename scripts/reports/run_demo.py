#!/usr/bin/python3
"""make demo: the whole stack on the emulated AmigoBot, headless, scored.

Starts a private ROS master on a free port and Xvfb, runs sim.launch (emulator, driver,
simulated laser, ground-truth localisation, target on the Section 5.3-like course,
tracking, rviz with the shipped display), enables tracking through its service, drops one
virtual obstacle (the paper's square, as a disk) through the topic, records a rosbag,
screenshots rviz, stops everything it started, and writes REPORT/: run.bag, trajectory.csv,
metrics.json, the paper's Figs 3-8 (scripts/reports/plot_run.py), rviz_*.png, summary.md, logs/.
Exit 0: safe run; 3: collision or a command outside the diamond; 4: the run did not happen.
Tracking runs with config/demo_tracking.yaml (tangential escape) unless --paper-law.
Usage: run_demo.py [--ws .ws] [--out report/demo] [--world config/worlds/lab.yaml] [--paper-law]
"""
import argparse
import json
import os
import shutil
import subprocess
import sys
import time

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "test"))
import stack_processes as sp  # noqa: E402

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
WORLD = os.path.join(ROOT, "config", "worlds", "lab.yaml")  # default room of the run and of its scoring
COURSE_S = 80.0       # the reference's duration (config/references/experiment_5_3.yaml)
START_DELAY_S = 10.0  # the target waits this long after the launch (startup on a loaded machine)
SETTLE_S = 4.0        # after the course ends
VIRTUAL = "{id: square, center: {x: 2.0, y: 1.0, z: 0.0}, radius: 0.25}"  # the paper's square, as a disk
DEMO_PARAMS = os.path.join(ROOT, "config", "demo_tracking.yaml")
TOPICS = ["/tracking/state", "/tracking/virtual_obstacles", "/cmd_vel", "/ground_truth", "/odom", "/scan",
          "/tf", "/tf_static", "/robot_trail", "/target_trail"]


def log(msg):
    print(f"[demo {time.strftime('%H:%M:%S')}] {msg}", flush=True)


def wait_for(what, check, timeout):
    deadline = time.time() + timeout
    while time.time() < deadline:
        if check():
            return
        time.sleep(0.5)
    raise RuntimeError(f"{what} not within {timeout:.0f} s")


def ok(args, env):
    return subprocess.run(args, env=env, capture_output=True, timeout=30).returncode == 0


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--ws", default=os.path.join(ROOT, ".ws"), help="catkin workspace (built)")
    parser.add_argument("--out", default=os.path.join(ROOT, "report", "demo"), help="report folder (replaced)")
    parser.add_argument("--world", default=WORLD, help="world YAML of the run and its scoring (default: lab.yaml)")
    parser.add_argument("--paper-law", action="store_true",
                        help="the paper's law alone (without config/demo_tracking.yaml's tangential escape)")
    args = parser.parse_args()
    out = os.path.abspath(args.out)
    shutil.rmtree(out, ignore_errors=True)
    logs = os.path.join(out, "logs")
    os.makedirs(logs)
    started = time.time()

    master = sp.free_port()
    env = sp.ros_env(os.path.join(args.ws, "devel", "setup.bash"), master, os.path.join(out, "ros_home"))
    procs = sp.Processes(logs)
    bag = os.path.join(out, "run.bag")
    shots = []
    try:
        display = sp.start_xvfb(procs)
        env["DISPLAY"] = display
        sp.start_master(procs, env, master)
        log(f"private ROS master on port {master}, Xvfb on {display}")
        tcp, status, laser = sp.free_port(), sp.free_port(), sp.free_port()
        launch = procs.start("sim_launch", ["roslaunch", "amigobot_tracking", "sim.launch", f"tcp_port:={tcp}",
                                            f"status_port:={status}", f"laser_port:={laser}",
                                            f"start_delay:={START_DELAY_S}", f"world:={os.path.abspath(args.world)}", "rviz:=true"]
                             + ([] if args.paper_law else [f"tracking_params:={DEMO_PARAMS}"]),
                             env)
        t_launch = time.time()
        recorder = procs.start("rosbag", ["rosbag", "record", "-O", bag] + TOPICS, env)
        wait_for("the tracking node's enable service",
                 lambda: ok(["rosservice", "info", "/tracking/enable"], env) or launch.poll() is not None, 90)
        if launch.poll() is not None:
            raise RuntimeError("sim.launch exited early (logs/sim_launch.log)")
        wait_for("ground truth", lambda: ok(["rostopic", "echo", "-n", "1", "/ground_truth/header/seq"], env), 60)
        res = subprocess.run(["rosservice", "call", "/tracking/enable"], env=env, capture_output=True, text=True,
                             timeout=30)
        log("tracking/enable: " + " ".join(res.stdout.split()))
        res = subprocess.run(["rostopic", "pub", "-1", "/tracking/virtual_obstacle",
                              "amigobot_tracking/VirtualObstacle", VIRTUAL], env=env, capture_output=True, text=True,
                             timeout=30)
        if res.returncode != 0:
            raise RuntimeError("could not publish the virtual obstacle: " + res.stderr.strip())
        log("virtual obstacle injected on /tracking/virtual_obstacle: " + VIRTUAL)
        t_start = t_launch + START_DELAY_S
        t_end = t_start + COURSE_S + SETTLE_S
        log(f"target moving from about {max(0.0, t_start - time.time()):.0f} s from now; run ends in "
            f"{t_end - time.time():.0f} s")
        for name, at in (("rviz_avoiding.png", t_start + 21.0), ("rviz_end.png", t_end - 1.0)):
            time.sleep(max(0.0, at - time.time()))
            if launch.poll() is not None:
                raise RuntimeError("sim.launch stopped during the run (logs/sim_launch.log)")
            path = os.path.join(out, name)
            sp.screenshot(display, path)
            shots.append(path)
        time.sleep(max(0.0, t_end - time.time()))
        procs.stop_one(recorder, timeout=20)  # SIGINT: rosbag closes the bag
    except (RuntimeError, subprocess.SubprocessError, OSError) as err:
        log(f"FAILED: {err}")
        procs.stop()
        log(f"logs in {logs}")
        return 4
    finally:
        procs.stop()
    log(f"stack stopped after {time.time() - started:.0f} s; scoring the run")

    report = subprocess.run([os.path.join(args.ws, "devel", "lib", "amigobot_tracking", "run_report"), "--bag", bag,
                             "--world", os.path.abspath(args.world), "--out", out, "--name", "make demo (sim.launch, Section 5.3-like)"],
                            env=env, capture_output=True, text=True)
    sys.stdout.write(report.stdout)
    sys.stderr.write(report.stderr)
    if report.returncode in (0, 3):
        plots = subprocess.run(["/usr/bin/python3", os.path.join(ROOT, "scripts", "reports", "plot_run.py"),
                                os.path.join(out, "trajectory.csv")], env=env, capture_output=True, text=True)
        if plots.returncode != 0:
            log("plots failed: " + plots.stderr.strip())
    write_summary(out, report, shots, time.time() - started)
    log(f"report: {out} (summary.md, metrics.json, fig*.png, rviz_*.png, run.bag)")
    return report.returncode


def write_summary(out, report, shots, wall):
    metrics = {}
    path = os.path.join(out, "metrics.json")
    if os.path.exists(path):
        with open(path) as f:
            metrics = json.load(f)
    lines = ["# make demo: the stack on the emulated AmigoBot", "",
             f"Run wall time {wall:.0f} s. Verdict: " + ("SAFE" if report.returncode == 0 else
                                                          "UNSAFE" if report.returncode == 3 else "DID NOT RUN"), "",
             "```", report.stdout.strip(), report.stderr.strip(), "```", ""]
    if metrics:
        lines += ["| metric | value |", "|---|---|"]
        lines += [f"| {k} | {v} |" for k, v in metrics.items() if k != "scenario"]
        lines.append("")
    lines += [f"![{os.path.basename(s)}]({os.path.basename(s)})" for s in shots]
    lines += [f"![{f}]({f})" for f in sorted(os.listdir(out)) if f.startswith("fig") and f.endswith(".png")]
    with open(os.path.join(out, "summary.md"), "w") as f:
        f.write("\n".join(lines) + "\n")


if __name__ == "__main__":
    sys.exit(main())
