#!/usr/bin/python3
"""CPU of the whole demo with the real laser chain against sim_laser (a measurement, not a test).

For each laser (default: sick_tim5xx, then sim) it starts a private ROS master on a free
port, runs sim.launch headless (no rviz) on free ports with that laser:=, enables tracking,
lets it settle (localisation on the shipped map; laser:=sim runs with ground-truth
localisation, which sim_laser needs), then reads utime + stime (/proc/PID/stat) of every process roslaunch started
at the start and the end of a window of --duration seconds, and prints per process and in
total the CPU used in percent of one core. It stops only what it started.
Usage: measure_laser_cpu.py [--ws WS] [--duration 60] [--lasers sick_tim5xx sim] [--out report/laser_cpu]
"""
import argparse
import os
import shutil
import subprocess
import sys
import time

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "test"))
import stack_processes as sp  # noqa: E402

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
TICKS = os.sysconf("SC_CLK_TCK")


def descendants(root):
    """pid -> name of every live process below `root` (the name: its __name:= or executable)."""
    return {pid: name_of(pid) for pid in sp.descendants(root)}


def name_of(pid):
    try:
        with open(f"/proc/{pid}/cmdline", "rb") as f:
            argv = [a.decode(errors="replace") for a in f.read().split(b"\0") if a]
    except OSError:
        return "?"
    for a in argv:
        if a.startswith("__name:="):
            return a[len("__name:="):]
    exe = os.path.basename(argv[1] if len(argv) > 1 and argv[0].endswith("python3") else argv[0]) if argv else "?"
    return exe


def cpu_seconds(pid):
    try:
        with open(f"/proc/{pid}/stat") as f:
            fields = f.read().rsplit(")", 1)[1].split()
        return (int(fields[11]) + int(fields[12])) / TICKS  # utime, stime
    except (OSError, IndexError, ValueError):
        return None


def measure(ws, laser, duration, logs):
    master = sp.free_port()
    env = sp.ros_env(os.path.join(ws, "devel", "setup.bash"), master, os.path.join(logs, "ros_home"))
    procs = sp.Processes(logs)
    try:
        sp.start_master(procs, env, master)
        tcp, status, port = sp.free_port(), sp.free_port(), sp.free_port()
        launch = procs.start(f"sim_{laser}", ["roslaunch", "amigobot_tracking", "sim.launch", f"tcp_port:={tcp}",
                                              f"status_port:={status}", f"laser_port:={port}", f"laser:={laser}",
                                              "start_delay:=5", "rviz:=false"]
                             # sim_laser casts from the true map -> laser: ground-truth localisation
                             + (["localization:=ground_truth"] if laser == "sim" else []), env)
        deadline = time.time() + 120
        while subprocess.run(["rosservice", "call", "/tracking/enable"], env=env, capture_output=True).returncode != 0:
            if time.time() > deadline or launch.poll() is not None:
                raise RuntimeError(f"sim.launch laser:={laser} did not come up (see {logs})")
            time.sleep(1.0)
        time.sleep(10.0)  # settle: connections made, the target moving
        before = {pid: (name, cpu_seconds(pid)) for pid, name in descendants(launch.pid).items()}
        t0 = time.time()
        time.sleep(duration)
        elapsed = time.time() - t0
        if launch.poll() is not None:
            raise RuntimeError(f"sim.launch laser:={laser} stopped during the window")
        rows = {}
        for pid, (name, start) in before.items():
            end = cpu_seconds(pid)
            if start is not None and end is not None:
                rows[name] = rows.get(name, 0.0) + 100.0 * (end - start) / elapsed
        return rows
    finally:
        procs.stop()


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--ws", default=sp.default_workspace(), help="catkin workspace (built)")
    parser.add_argument("--duration", type=float, default=60.0, help="measurement window [s]")
    parser.add_argument("--lasers", nargs="+", default=["sick_tim5xx", "sim"], help="sim.launch laser:= values")
    parser.add_argument("--out", default=os.path.join(ROOT, "report", "laser_cpu"), help="logs folder (replaced)")
    args = parser.parse_args()
    shutil.rmtree(args.out, ignore_errors=True)
    results = {}
    for laser in args.lasers:
        logs = os.path.join(os.path.abspath(args.out), laser)
        os.makedirs(logs)
        print(f"[laser_cpu] sim.launch laser:={laser}: {args.duration:.0f} s window", flush=True)
        results[laser] = measure(args.ws, laser, args.duration, logs)
    names = sorted({n for r in results.values() for n in r}, key=lambda n: -max(r.get(n, 0.0) for r in results.values()))
    print("\n| process | " + " | ".join(f"laser:={l} [% of a core]" for l in args.lasers) + " |")
    print("|---|" + "---|" * len(args.lasers))
    for n in names:
        print(f"| {n} | " + " | ".join(f"{results[l][n]:.1f}" if n in results[l] else "–" for l in args.lasers) + " |")
    print("| **total** | " + " | ".join(f"**{sum(results[l].values()):.1f}**" for l in args.lasers) + " |")
    return 0


if __name__ == "__main__":
    sys.exit(main())
