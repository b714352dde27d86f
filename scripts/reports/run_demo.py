#!/usr/bin/python3
"""make demo: the whole stack on the emulated AmigoBot, headless, scored.

Starts a private ROS master on a free port and Xvfb, runs sim.launch (emulator, driver,
simulated laser, ground-truth localisation, target on the Section 5.3-like course,
tracking, rviz with the shipped display), enables tracking through its service, drops one
virtual obstacle (a disk of radius 0.25 m where the paper has its square) through the topic, records a rosbag,
screenshots rviz, stops everything it started, and writes REPORT/: run.bag, trajectory.csv,
metrics.json, the paper's Figs 3-8 (scripts/reports/plot_run.py), rviz_*.png, summary.md, logs/.
The world's people (lab.yaml: one crossing the robot's path about 60 s into the course) walk
on the emulator's clock; run_report places them from the recorded /ground_truth_clock and
counts a body contact with one as a collision (UNSAFE).
Exit 0: safe run that tracked; 3: collision or a command outside the diamond; 4: the run did
not happen; 5: safe, but it did not track (run_report's tracking verdict: true error above
rho_inf + tolerance outside the obstacle episodes and their recovery time, or at the end).
Tracking runs with config/demo_tracking.yaml (the recommended law) unless --paper-law
(config/paper_law.yaml: the paper's law alone).
Usage: run_demo.py [--ws WS] [--out report/demo] [--world config/worlds/lab.yaml] [--paper-law] [--tolerance 0.05]
                   [--recovery-time 20]
"""
import argparse
import json
import os
import shutil
import subprocess
import sys
import time

import yaml

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "test"))
import stack_processes as sp  # noqa: E402

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
WORLD = os.path.join(ROOT, "config", "worlds", "lab.yaml")  # default room of the run and of its scoring
REFERENCE = os.path.join(ROOT, "config", "references", "experiment_5_3.yaml")  # sim.launch's default course
START_DELAY_S = 10.0  # the target waits this long after the launch (startup on a loaded machine)
SETTLE_S = 6.0        # after the course ends: the robot closes the last gap (the final error is judged)
PROGRESS_PERIOD_S = 5.0  # a line on the console this often during the run (demo_progress.py)
FIRST_PASS = 0.22     # share of the course at which the target crosses the virtual disk first (screenshot)
VIRTUAL = "{id: virtual_disk, center: {x: 2.0, y: 1.0, z: 0.0}, radius: 0.25}"  # a disk where the paper has its square
DEMO_PARAMS = os.path.join(ROOT, "config", "demo_tracking.yaml")
PAPER_PARAMS = os.path.join(ROOT, "config", "paper_law.yaml")
LAW_TEXT = {"recommended": "the recommended law, config/demo_tracking.yaml",
            "escape": "the paper's law with the tangential escape",
            "paper": "the paper's law alone, --paper-law (config/paper_law.yaml)"}
EXIT_NAMES = {0: "SAFE, TRACKED", 3: "UNSAFE", 4: "DID NOT RUN", 5: "SAFE, DID NOT TRACK",
              6: "TRACKED, BUT A NaN WAS PUBLISHED"}
TOPICS = ["/tracking/state", "/tracking/virtual_obstacles", "/cmd_vel", "/ground_truth", "/ground_truth_clock", "/odom",
          "/scan", "/tf", "/tf_static", "/robot_trail", "/target_trail", "/tracking/markers", "/diagnostics"]


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
    parser.add_argument("--ws", default=sp.default_workspace(), help="catkin workspace (built)")
    parser.add_argument("--out", default=os.path.join(ROOT, "report", "demo"), help="report folder (replaced)")
    parser.add_argument("--world", default=WORLD, help="world YAML of the run and its scoring (default: lab.yaml)")
    parser.add_argument("--paper-law", action="store_true",
                        help="the paper's law alone (config/paper_law.yaml instead of config/demo_tracking.yaml)")
    parser.add_argument("--tolerance", type=float, default=0.05,
                        help="[m] tracking verdict: true |e| within rho_inf + this (localisation error, sampling skew)")
    parser.add_argument("--recovery-time", type=float, default=10.0,
                        help="[s] tracking verdict: not judged this long after the start and after each obstacle")
    args = parser.parse_args()
    course_s = course_duration(REFERENCE)
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
                                            f"start_delay:={START_DELAY_S}", f"world:={os.path.abspath(args.world)}",
                                            f"reference:={REFERENCE}", "rviz:=true"]
                             + [f"tracking_params:={PAPER_PARAMS if args.paper_law else DEMO_PARAMS}"],
                             env)
        t_launch = time.time()
        # The C++ recorder itself: Debian's `rosbag record` wrapper chains its SIGINT handler to the
        # previous one, a signal.Handlers member in Python 3, and dies with a TypeError traceback.
        recorder = procs.start("rosbag", ["rosrun", "rosbag", "record", "-O", bag] + TOPICS, env)
        wait_for("the tracking node's enable service",
                 lambda: ok(["rosservice", "info", "/tracking/enable"], env) or launch.poll() is not None, 90)
        if launch.poll() is not None:
            raise RuntimeError("sim.launch exited early (logs/sim_launch.log)")
        params = tracking_params(env)
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
        t_end = t_start + course_s + SETTLE_S
        log(f"target moving from about {max(0.0, t_start - time.time()):.0f} s from now; run ends in "
            f"{t_end - time.time():.0f} s")
        offset = params.get("offset", 0.3)
        procs.start("progress", ["/usr/bin/python3", os.path.join(ROOT, "scripts", "reports", "demo_progress.py"),
                                 "--end", str(t_end), "--period", str(PROGRESS_PERIOD_S),
                                 "--offset", str(offset if isinstance(offset, (int, float)) else 0.3)],
                    env, console=True)
        for name, at in (("rviz_avoiding.png", t_start + FIRST_PASS * course_s + 4.0), ("rviz_end.png", t_end - 1.0)):
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

    law = ("recommended" if params.get("law") == "recommended"
           else "escape" if params.get("tangential_avoidance") else "paper")
    report_args = ["--bag", bag, "--world", os.path.abspath(args.world), "--out", out, "--name", "make demo", "--law", law,
                   "--tolerance", str(args.tolerance), "--recovery-time", str(args.recovery_time)]
    for key in ("rho_inf", "delta", "v_max", "w_max"):  # the values the node ran with
        if isinstance(params.get(key), (int, float)):
            report_args += ["--" + key.replace("_", "-"), str(params[key])]
    if isinstance(params.get("body_safe"), bool):
        report_args += ["--body-safe", "true" if params["body_safe"] else "false"]
    report = subprocess.run([os.path.join(args.ws, "devel", "lib", "amigobot_tracking", "run_report")] + report_args,
                            env=env, capture_output=True, text=True)
    sys.stdout.write(report.stdout)
    sys.stderr.write(report.stderr)
    if report.returncode in (0, 3, 5):
        plots = subprocess.run(["/usr/bin/python3", os.path.join(ROOT, "scripts", "reports", "plot_run.py"),
                                os.path.join(out, "trajectory.csv")], env=env, capture_output=True, text=True)
        if plots.returncode != 0:
            log("plots failed: " + plots.stderr.strip())
    # Nothing published as NaN: every number of every recorded message (scripts/test/check_bag_finite.py).
    finite = subprocess.run(["/usr/bin/python3", os.path.join(ROOT, "scripts", "test", "check_bag_finite.py"), bag],
                            env=env, capture_output=True, text=True)
    log((finite.stdout + finite.stderr).strip())
    returncode = 6 if finite.returncode != 0 and report.returncode == 0 else report.returncode
    write_summary(out, report, shots, time.time() - started, law, returncode, finite.stdout.strip())
    log(f"report: {out} (summary.md, metrics.json, fig*.png, rviz_*.png, run.bag)")
    return returncode


def course_duration(path):
    """[s] the reference's course: duration (spline) times time_scale."""
    with open(path) as f:
        ref = yaml.safe_load(f)
    return float(ref["reference"]["duration"]) * float(ref.get("time_scale", 1.0))


def tracking_params(env):
    """The tracking node's parameters as it loaded them (law, rho_inf, delta, body_safe, diamond)."""
    res = subprocess.run(["rosparam", "get", "/tracking"], env=env, capture_output=True, text=True, timeout=30)
    if res.returncode != 0:
        raise RuntimeError("rosparam get /tracking: " + res.stderr.strip())
    return yaml.safe_load(res.stdout) or {}


def num(value, digits=3):
    """Floats to `digits` significant figures for the tables; anything else as it is."""
    return f"{value:.{digits}g}" if isinstance(value, float) else value


# The unit of each metrics.json figure (keys ending in _s, _m, _deg carry theirs); "-" for a
# ratio, "steps" / "count" for the counters. A key missing here is shown with "?" (add it).
METRIC_UNITS = {
    "ase": "m²", "aae": "m", "ise": "m² s", "iae": "m s", "tec": "-", "max_e_over_rho": "-", "max_rho": "m",
    "min_clearance_offset": "m", "min_clearance_body": "m", "min_clearance_world": "m", "min_clearance_virtual": "m",
    "min_clearance_people": "m",
    "body_collisions": "count", "offset_collisions": "count", "diamond_violations": "steps",
    "command_diamond_violations": "commands", "max_command_diamond_norm": "- (1 = on the diamond)",
    "saturated_steps": "steps", "saturated_fraction": "share of steps", "envelope_widenings": "steps",
    "estimator_rms_error": "m/s", "estimator_max_error_settled": "m/s", "steps": "steps", "nan_count": "steps",
    "invalid_steps": "steps", "true_ase": "m²", "true_aae": "m", "true_ise": "m² s", "true_iae": "m s",
    "max_true_error": "m", "final_error": "m", "conflict_steps": "steps", "escape_steps": "steps", "side_flips": "steps",
    "max_orbit_turns": "turns", "escape_toggles": "steps", "avoidance_toggles": "steps", "max_delta_v": "m/s",
    "max_delta_omega": "rad/s", "within_rho_fraction": "share of steps", "commands": "count",
    "omega_reversals": "count", "omega_reversals_per_minute": "1/min",
    "path_length": "m", "virtual_obstacles": "count", "truth_samples": "count", "safe": "-", "ran": "-",
    "law": "-", "variant": "-", "samples": "count", "missed": "count", "frames": "-", "realtime_factor": "-",
}
# Two "final" errors are easily confused: the controller's |e| at its last step (its believed
# pose) and the verdict's true |e*| at the end. Each row says which it is.
METRIC_NAMES = {"final_error": "final_error: ‖e‖ at the last step, as the controller saw it (believed pose)"}


def metric_unit(key):
    for suffix, unit in (("_s", "s"), ("_m", "m"), ("_deg", "deg")):
        if key.endswith(suffix):
            return unit
    return METRIC_UNITS.get(key.rsplit(".", 1)[-1], "?")


def metric_rows(metrics):
    """| metric | value | unit | rows of metrics.json (nested tables flattened as a.b)."""
    rows = []
    for key, value in metrics.items():
        if key in ("scenario", "tracking"):
            continue
        if isinstance(value, dict):
            rows += [(f"{key}.{k}", v) for k, v in value.items()]
        else:
            rows.append((key, value))
    return [f"| {METRIC_NAMES.get(k, k)} | {num(v, 4)} | {metric_unit(k)} |" for k, v in rows]


def write_summary(out, report, shots, wall, law, returncode, finite):
    metrics = {}
    path = os.path.join(out, "metrics.json")
    if os.path.exists(path):
        with open(path) as f:
            metrics = json.load(f)
    lines = ["# make demo: the stack on the emulated AmigoBot", "",
             f"Law: **{law}** ({LAW_TEXT[law]}). "
             f"Run wall time {wall:.0f} s. Verdict: **{EXIT_NAMES.get(returncode, f'exit {returncode}')}** "
             f"(exit {returncode}).", "", "NaN check of the recorded bag: " + finite, ""]
    tracking = metrics.get("tracking")
    if tracking:
        lines += [f"Tracking verdict: true ‖e*‖ = ‖p_d − p_r‖ (target against the robot's true offset point) "
                  f"within ρ∞ + tolerance = {tracking['bound']:g} m at every step at least "
                  f"{tracking['recovery_time_s']:g} s after the start and after each obstacle episode (a true "
                  f"clearance of the effective disk around p_r or around the target inside δ = {tracking['band']:g} m), "
                  f"and at the end. Judged {100 * (tracking['judged_fraction'] or 0):.0f} % of the run: max "
                  f"{num(tracking['max_judged_true_error'])} m; final true ‖e*‖ (at the end, judged) "
                  f"{num(tracking['final_true_error'])} m. "
                  + (tracking["reason"] or "Passed."), "",
                  "| obstacle episode [s] | peak ‖e*‖ [m] | back under the bound after [s] |", "|---|---|---|"]
        lines += [f"| {e['start_s']:.1f}–{e['end_s']:.1f} | {e['peak_true_error']:.3f} | "
                  f"{'never' if e['recovered_after_s'] is None else format(e['recovered_after_s'], '.1f')} |"
                  for e in tracking["episodes"]]
        lines.append("")
    lines += ["```", report.stdout.strip(), report.stderr.strip(), "```", ""]
    if metrics:
        lines += ["| metric | value | unit |", "|---|---|---|"] + metric_rows(metrics)
        lines.append("")
    lines += [f"![{os.path.basename(s)}]({os.path.basename(s)})" for s in shots]
    lines += [f"![{f}]({f})" for f in sorted(os.listdir(out)) if f.startswith("fig") and f.endswith(".png")]
    with open(os.path.join(out, "summary.md"), "w") as f:
        f.write("\n".join(lines) + "\n")


if __name__ == "__main__":
    sys.exit(main())
