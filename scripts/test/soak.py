#!/usr/bin/python3
"""Soak (issue 24 item 3): continuous tracking on the emulated stack, memory and CPU watched.

Starts a private ROS master on a free port, runs sim.launch headless (emulated AmigoBot, driver,
TiM emulator through the real laser chain, localisation on the shipped map, the target on a
repeating circle, config/references/soak_circle.yaml, the tracking nodelet) on free ports,
enables tracking, and for --minutes samples every
--period seconds RSS (VmRSS of /proc/PID/status) and utime + stime (/proc/PID/stat) of every
process roslaunch started. Per process it reports the RSS growth in MB/h (least-squares slope
after a --settle window, because the first seconds allocate maps, buffers and connections and
are not a leak), the mean CPU in % of one core, and counts WARN / ERROR / FATAL lines in the
run's rosout.log (per minute). A process that disappears is a failure (nothing may die), and so
are RSS growth above --max-growth MB/h for any process and a robot (the emulator's true speed)
standing in more than 10 % of the samples after the settle window.
Writes report/soak/summary.md and report/soak/soak.json (--out). Exit 0: pass, 1: fail.
Usage: soak.py [--ws WS] [--minutes 15] [--period 5] [--max-growth 20] [--out report/soak]
"""
import argparse
import glob
import json
import os
import shutil
import socket
import subprocess
import sys
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import stack_processes as sp  # noqa: E402

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
TICKS = os.sysconf("SC_CLK_TCK")
LEVELS = ("WARN", "ERROR", "FATAL")


def name_of(pid):
    """A process's ROS name (its __name:= argument) or its executable's name."""
    try:
        with open(f"/proc/{pid}/cmdline", "rb") as f:
            argv = [a.decode(errors="replace") for a in f.read().split(b"\0") if a]
    except OSError:
        return None
    for a in argv:
        if a.startswith("__name:="):
            return a[len("__name:="):]
    if not argv:
        return None
    # python nodes: the script, not the interpreter
    return os.path.basename(argv[1] if len(argv) > 1 and "python" in os.path.basename(argv[0]) else argv[0])


def sample(pid):
    """(rss_mb, cpu_s) of pid, or None when it is gone."""
    try:
        with open(f"/proc/{pid}/stat") as f:
            fields = f.read().rsplit(")", 1)[1].split()
        if fields[0] in ("Z", "X"):  # a zombie has died even if its entry is still there
            return None
        cpu = (int(fields[11]) + int(fields[12])) / TICKS
        with open(f"/proc/{pid}/status") as f:
            rss_kb = next(int(line.split()[1]) for line in f if line.startswith("VmRSS:"))
        return rss_kb / 1024.0, cpu
    except (OSError, IndexError, ValueError, StopIteration):
        return None


def robot_speed(port):
    """The emulated robot's true speed |v| [m/s] from its status port ("t x y theta v w ..."),
    or None: the judge of "still tracking" is the ground truth, not the controller."""
    try:
        with socket.create_connection(("127.0.0.1", port), timeout=1.0) as s:
            s.sendall(b"status\n")
            line = s.makefile().readline().split()
        return abs(float(line[4]))
    except (OSError, IndexError, ValueError):
        return None


def slope(ts, ys):
    """Least-squares slope dy/dt (0 for fewer than two points)."""
    n = len(ts)
    if n < 2:
        return 0.0
    mt, my = sum(ts) / n, sum(ys) / n
    den = sum((t - mt) ** 2 for t in ts)
    return sum((t - mt) * (y - my) for t, y in zip(ts, ys)) / den if den > 0 else 0.0


def rosout_counts(ros_home):
    """Lines per level in the run's rosout.log (roslaunch's rosout node writes it)."""
    counts = {level: 0 for level in LEVELS}
    examples = {level: [] for level in LEVELS}
    # log/latest is a symlink to the run's folder: each file once, by its real path
    for path in sorted({os.path.realpath(p) for p in glob.glob(os.path.join(ros_home, "log", "*", "rosout.log*"))}):
        with open(path, errors="replace") as f:
            for line in f:
                parts = line.split(" ", 3)
                if len(parts) > 2 and parts[1] in counts:
                    counts[parts[1]] += 1
                    # "stamp LEVEL node [file:line(fn)] [topics: ...] text": keep node and text
                    text = line.split("] ", 2)[-1].strip() if "[topics:" in line else parts[-1].strip()
                    if len(examples[parts[1]]) < 5:
                        examples[parts[1]].append(f"{parts[2]}: {text}"[:200])
    return counts, examples


def run(args, logs):
    ros_home = os.path.join(logs, "ros_home")
    master = sp.free_port()
    env = sp.ros_env(os.path.join(args.ws, "devel", "setup.bash"), master, ros_home)
    procs = sp.Processes(logs)
    try:
        sp.start_master(procs, env, master)
        tcp, status, laser = sp.free_port(), sp.free_port(), sp.free_port()
        launch = procs.start("sim", ["roslaunch", "amigobot_tracking", "sim.launch", f"tcp_port:={tcp}",
                                     f"status_port:={status}", f"laser_port:={laser}", "start_delay:=5",
                                     "rviz:=false", f"reference:={os.path.join(ROOT, 'config', 'references', 'soak_circle.yaml')}"],
                             env)
        deadline = time.time() + 120
        while subprocess.run(["rosservice", "call", "/tracking/enable"], env=env, capture_output=True).returncode:
            if time.time() > deadline or launch.poll() is not None:
                raise RuntimeError(f"sim.launch did not come up (see {logs})")
            time.sleep(1.0)
        t0 = time.time()
        pids = {pid: name_of(pid) for pid in sp.descendants(launch.pid)}
        pids = {pid: name for pid, name in pids.items() if name}
        series = {pid: [] for pid in pids}  # pid -> [(t, rss_mb, cpu_s)]
        died = {}
        speeds = []  # (t, true |v|) of the robot
        end = t0 + 60.0 * args.minutes
        next_report = t0 + 60.0
        while time.time() < end:
            t = time.time() - t0
            for pid in pids:
                if pid in died:
                    continue
                s = sample(pid)
                if s is None:
                    died[pid] = t
                else:
                    series[pid].append((t, s[0], s[1]))
            speeds.append((t, robot_speed(status)))
            if launch.poll() is not None:
                died.setdefault(launch.pid, time.time() - t0)
                break
            if time.time() >= next_report:  # progress, so a long soak is not silent
                total = sum(v[-1][1] for v in series.values() if v)
                print(f"[soak] {t / 60:.1f} min: {len(pids) - len(died)}/{len(pids)} processes, "
                      f"RSS {total:.0f} MB in all", flush=True)
                next_report += 60.0
            time.sleep(args.period)
        elapsed = time.time() - t0
        counts, examples = rosout_counts(ros_home)
        return pids, series, died, elapsed, counts, examples, speeds
    finally:
        procs.stop()


def summarise(args, pids, series, died, elapsed, counts, examples, speeds):
    rows = []
    for pid, name in pids.items():
        pts = series[pid]
        fit = [p for p in pts if p[0] >= args.settle] or pts
        growth = slope([p[0] / 3600.0 for p in fit], [p[1] for p in fit])  # MB per hour
        cpu = 100.0 * (pts[-1][2] - pts[0][2]) / (pts[-1][0] - pts[0][0]) if len(pts) > 1 and pts[-1][0] > pts[0][0] else 0.0
        rows.append({"process": name, "pid": pid, "rss_start_mb": round(fit[0][1], 2) if fit else None,
                     "rss_end_mb": round(pts[-1][1], 2) if pts else None, "rss_growth_mb_per_h": round(growth, 2),
                     "cpu_percent": round(cpu, 2), "samples": len(pts), "died_at_s": died.get(pid)})
    rows.sort(key=lambda r: -(r["rss_end_mb"] or 0))
    minutes = elapsed / 60.0
    rate = {level: round(counts[level] / minutes, 2) if minutes > 0 else 0.0 for level in LEVELS}
    failures = [f"{r['process']} died at {r['died_at_s']:.0f} s" for r in rows if r["died_at_s"] is not None]
    failures += [f"{r['process']} RSS grows {r['rss_growth_mb_per_h']:.1f} MB/h > {args.max_growth} MB/h"
                 for r in rows if r["rss_growth_mb_per_h"] > args.max_growth]
    # Tracking the whole time: after the settle window the robot drives in nearly every sample
    # (0.05 m/s: the circle is 0.157 m/s; an obstacle stop or a catch-up pause is allowed).
    late = [v for t, v in speeds if t >= args.settle]
    moving = sum(1 for v in late if v is not None and v > 0.05) / len(late) if late else 0.0
    if moving < 0.9:
        failures.append(f"the robot drove in only {100 * moving:.0f} % of the samples after {args.settle:.0f} s")
    if elapsed < 60.0 * args.minutes - 2 * args.period:
        failures.append(f"the soak ended after {elapsed:.0f} s of {60 * args.minutes:.0f} s (sim.launch stopped)")
    return {"minutes": round(minutes, 2), "period_s": args.period, "settle_s": args.settle,
            "max_growth_mb_per_h": args.max_growth, "processes": rows, "rosout_counts": counts,
            "moving_fraction": round(moving, 3), "rosout_per_minute": rate, "rosout_examples": examples, "failures": failures,
            "passed": not failures}


def markdown(report):
    lines = [f"# Soak: {report['minutes']:.1f} min of tracking on sim.launch", "",
             f"Samples every {report['period_s']:.0f} s; RSS growth is the least-squares slope after the first "
             f"{report['settle_s']:.0f} s; bound {report['max_growth_mb_per_h']} MB/h per process.", "",
             "| process | RSS start [MB] | RSS end [MB] | growth [MB/h] | CPU [% of a core] | died |",
             "|---|---|---|---|---|---|"]
    for r in report["processes"]:
        died = "–" if r["died_at_s"] is None else f"at {r['died_at_s']:.0f} s"
        lines.append(f"| {r['process']} | {r['rss_start_mb']} | {r['rss_end_mb']} | {r['rss_growth_mb_per_h']:+.2f} | "
                     f"{r['cpu_percent']:.1f} | {died} |")
    c, m = report["rosout_counts"], report["rosout_per_minute"]
    lines += ["", f"The robot drove (true |v| > 0.05 m/s) in {100 * report['moving_fraction']:.0f} % of the samples "
              f"after the first {report['settle_s']:.0f} s.", "", "rosout: " + ", ".join(f"{level} {c[level]} ({m[level]}/min)" for level in LEVELS), ""]
    for level in LEVELS:
        for e in report["rosout_examples"][level]:
            lines.append(f"    {e}")
    lines += ["", "**PASS**" if report["passed"] else "**FAIL**: " + "; ".join(report["failures"]), ""]
    return "\n".join(lines)


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--ws", default=sp.default_workspace(), help="catkin workspace (built)")
    parser.add_argument("--minutes", type=float, default=15.0, help="soak length [min]")
    parser.add_argument("--period", type=float, default=5.0, help="sampling period [s]")
    parser.add_argument("--settle", type=float, default=30.0, help="[s] excluded from the RSS fit (start-up)")
    # 20 MB/h is 480 MB a day: more than an Odroid's headroom in one lab day would be a leak
    # worth failing on; below it the fit over 15 min cannot tell a leak from allocator noise.
    parser.add_argument("--max-growth", type=float, default=20.0, help="RSS growth bound per process [MB/h]")
    parser.add_argument("--out", default=os.path.join(ROOT, "report", "soak"), help="report folder (replaced)")
    args = parser.parse_args()
    out = os.path.abspath(args.out)
    shutil.rmtree(out, ignore_errors=True)
    logs = os.path.join(out, "logs")
    os.makedirs(logs)
    print(f"[soak] sim.launch, tracking for {args.minutes:g} min, sampling every {args.period:g} s", flush=True)
    report = summarise(args, *run(args, logs))
    with open(os.path.join(out, "soak.json"), "w") as f:
        json.dump(report, f, indent=1)
    text = markdown(report)
    with open(os.path.join(out, "summary.md"), "w") as f:
        f.write(text)
    print(text)
    return 0 if report["passed"] else 1


if __name__ == "__main__":
    sys.exit(main())
