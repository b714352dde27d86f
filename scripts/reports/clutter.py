#!/usr/bin/python3
"""The clutter benchmark (issue 20): every scene class of config/scenarios/clutter/ as a Monte
Carlo batch (geometry, start, target noise and sample rate varied) for every law of LAWS, one
table in docs/clutter.md. A law the simulator does not know is marked missing, not fatal.

Usage: scripts/reports/clutter.py --sim PATH/amigobot_sim [--runs N] [--jobs J] [--quick]
       [--classes a,b] [--out out/clutter] [--docs docs]      (`make clutter`)
--quick: 4 variants per batch (the test's mode). Default: 50 variants per class and law.
"""
import json
import os
import subprocess
import sys
import time

import batch_cli
import markdown

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
CLUTTER = os.path.join(ROOT, "config", "scenarios", "clutter")

# The laws compared, by amigobot_sim's --variant name: adding a law is one word here.
LAWS = ["paper", "proportional", "fixed_rho", "mrpt_reactive", "recommended"]

# Monte Carlo spread of every class (shifts, noise, sample periods, obstacle speed): the tuning
# suite's lines, so the benchmark and `amigobot_sim --tune` draw the same variants.
SUITE = os.path.join(ROOT, "config", "scenarios", "clutter_suite.txt")


def read_suite(path=SUITE):
    """{class: {option: value}} from the suite file (PATH key=value ...), as sim/gain_tuner.h reads it."""
    spread = {}
    with open(path) as f:
        for number, line in enumerate(f, 1):
            words = line.split("#", 1)[0].split()
            if not words:
                continue
            options = {}
            for word in words[1:]:
                key, eq, value = word.partition("=")
                if not eq:
                    sys.exit(f"{path}:{number}: expected key=value, got '{word}'")
                options[key] = [float(v) for v in value.split(",")] if key == "sample_periods" else float(value)
            spread[os.path.splitext(os.path.basename(words[0]))[0]] = options
    return spread


CLASSES = {
    "pillar_park": "target parks just behind one pillar (unreachable)",
    "u_behind": "U-shaped group, target passes behind it",
    "u_through": "U-shaped group, target goes through and beyond",
    "gap_pair": "passable gap between two small disks",
    "threshold_in": "a neighbour 1 cm inside the group threshold",
    "threshold_out": "a neighbour 1 cm outside the group threshold",
    "sharp_corner": "sharp corner in the reference",
    "fast_target": "target at 0.6 m/s with v̄ = 0.3",
    "saddle": "symmetric saddle",
    "ring": "ring of small disks",
    "doorway": "doorway in a line of disks",
    "moving_obstacle": "moving obstacle crossing the target's line",
}
QUICK_RUNS = 4

# (heading, summary key, digits or None for an integer) of each column after class and law.
COLUMNS = [
    ("runs", "runs", None),
    ("mean true ASE [m²]", "mean_true_ase", 3),
    ("worst true ASE [m²]", "worst_true_ase", 3),
    ("mean true ISE [m²s]", "mean_true_ise", 3),
    ("worst true ISE [m²s]", "worst_true_ise", 3),
    ("worst stall [s]", "worst_stall_s", 3),
    ("orbit turns", "worst_orbit_turns", 2),
    ("toggles esc/avoid", None, None),
    ("ω reversals /min (mean)", "mean_omega_reversals_per_minute", 3),
    ("max abs Δv [m/s]", "worst_max_delta_v", 3),
    ("max abs Δω [rad/s]", "worst_max_delta_omega", 3),
    ("widenings", "envelope_widenings", None),
    ("min body clearance [m]", "worst_min_clearance_body", 3),
    ("diamond violations", "diamond_violations", None),
    ("runs with NaN or invalid steps", "runs_with_nan", None),
]
HEADINGS = ["class", "law"] + [c[0] for c in COLUMNS]


def batch(sim, name, law, runs, jobs, out_root, seed=1):
    """One Monte Carlo batch: its summary dict, or {"missing": reason} when the simulator
    does not know the law, or {"failed": reason} when the run failed otherwise."""
    spread = read_suite()[name]
    out = os.path.join(out_root, name, law)
    cmd = [sim, "--scenario", os.path.join(CLUTTER, name + ".yaml"), "--out", out, "--variant", law,
           "--monte-carlo", str(runs), "--seed", str(seed), "--jobs", str(jobs), "--no-plot",
           "--mc-obstacle-shift", str(spread.get("obstacle_shift", 0.0)), "--mc-pose-shift",
           str(spread.get("pose_shift", 0.0)), "--mc-heading-shift", str(spread.get("heading_shift", 0.0)),
           "--mc-noise", str(spread.get("noise", 0.0))]
    if spread.get("sample_periods"):
        cmd += ["--mc-sample-periods"] + [str(p) for p in spread["sample_periods"]]
    if spread.get("obstacle_speed"):
        cmd += ["--obstacle-speed", str(spread["obstacle_speed"])]
    done = subprocess.run(cmd, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True)
    if done.returncode != 0:
        reason = done.stderr.strip().splitlines()[-1] if done.stderr.strip() else f"exit {done.returncode}"
        return {"missing": reason} if "variant" in reason else {"failed": reason}
    with open(os.path.join(out, "monte_carlo.json")) as f:
        return json.load(f)


def cells(summary):
    """The table cells of one batch (after class and law)."""
    if "missing" in summary or "failed" in summary:
        mark = "missing" if "missing" in summary else "failed"
        return [mark] + ["—"] * (len(COLUMNS) - 1)
    row = []
    for _, key, digits in COLUMNS:
        if key is None:  # toggles: worst escape / worst avoidance
            row.append(f"{summary['worst_escape_toggles']}/{summary['worst_avoidance_toggles']}")
        elif digits is None:
            row.append(str(summary[key]))
        else:
            row.append(markdown.number(summary[key], digits))
    return row


def write_page(path, results, runs, seconds, quick):
    page = markdown.Page()
    page("# Clutter benchmark")
    page("")
    page("Generated by `make clutter` (scripts/reports/clutter.py" + (" --quick" if quick else "") + "); "
         f"{runs} Monte Carlo variants per class and law, {seconds:.0f} s on this machine. "
         "Scenes: config/scenarios/clutter/ (body-safe, Section 5.3's gains and limits, 20 Hz). "
         "Each variant shifts the obstacles and the start, draws the target noise in [0, 3 cm] and a "
         "sample period of 50 or 100 ms (classes with a precise geometry shift their disks less: "
         "config/scenarios/clutter_suite.txt). Robot dynamics: the scenes' default, the AmigoBot's "
         "firmware (ramps, 0.1 s cycle and latency, wheel-speed limit; robot.dynamics, docs/simulation.md).")
    page("")
    page("True ASE/ISE use the true target and robot. Stall: target reachable (beyond its best standoff) "
         "but not approached (docs/simulation.md). Orbit turns: the largest |angle| / 2π of the offset "
         "point about one disk in one visit (passing a disk ≈ 0.5). Toggles: the worst run's escape / "
         "avoidance on-off switches. ω reversals: sign changes of ω beyond ±0.01 rad/s per minute of run, "
         "the mean over the runs; Δv, Δω: the worst run's largest change of the command between two steps. "
         "Widenings: steps where the guard widened ρ, summed over the runs "
         "(0 for a law without ρ). A law the simulator does not offer is marked missing.")
    page("")
    markdown.benchmark_table(page, HEADINGS, results, cells, CLASSES)
    page.save(path)


def main(sim, out_root, docs, runs=50, jobs=None, classes=None, quick=False, laws=None):
    """Runs the batches and writes DOCS/clutter.md; returns [(class, law, summary)]."""
    jobs = jobs or os.cpu_count() or 1
    names = classes or list(CLASSES)
    start = time.monotonic()
    results = []
    for name in names:
        for law in laws or LAWS:
            print(f"clutter: {name} / {law} ({runs} variants)", file=sys.stderr, flush=True)
            results.append((name, law, batch(sim, name, law, runs, jobs, out_root)))
    os.makedirs(docs, exist_ok=True)
    write_page(os.path.join(docs, "clutter.md"), results, runs, time.monotonic() - start, quick)
    return results


if __name__ == "__main__":
    args = batch_cli.parse(__doc__, "clutter.py", "clutter", ROOT, CLASSES, LAWS, QUICK_RUNS)
    main(args.sim, args.out, args.docs, args.runs, args.jobs, args.classes, args.quick, args.laws)
