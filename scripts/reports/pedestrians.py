#!/usr/bin/python3
"""The pedestrian benchmark: every class of config/scenarios/pedestrians/ as Monte Carlo variants
(walking speeds, timing, start, target noise and sample rate drawn per variant) for every law of
LAWS, one table in docs/pedestrians.md. Each variant is a scenario file of its own (OUT/CLASS/
variants/NNN.yaml), run once per law by amigobot_sim; nothing here names the robot's dynamics,
so the runs use the scenarios' default (SETS adds `section.key=value` to every run).

Usage: scripts/reports/pedestrians.py --sim PATH/amigobot_sim [--runs N] [--jobs J] [--quick]
       [--classes a,b] [--laws a,b] [--set section.key=value ...] [--out out/pedestrians] [--docs docs]
--quick: QUICK_RUNS variants per class (the test's mode). Default: 50.   (`make pedestrians`)
"""
import concurrent.futures
import json
import math
import os
import random
import subprocess
import sys
import time

import batch_cli
import markdown
import scenario_yaml

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
SCENES = os.path.join(ROOT, "config", "scenarios", "pedestrians")

# The laws compared: (name in the table, amigobot_sim arguments). Adding a law is one line.
LAWS = {
    "paper": ["--variant", "paper"],
    "mrpt_reactive": ["--variant", "mrpt_reactive"],
    # The recommended law takes every person's velocity (its barrier rows) and walked path over
    # obstacle_lookahead (its field): the constant-velocity-prediction variant is the law itself
    # (`moving_obstacles` switches only the paper's (10), so a "recommended_cv" row was identical).
    "recommended": ["--variant", "recommended"],
}
CLASSES = {
    "crossing_ahead": "one person crosses the target's line 0.4 m ahead of it",
    "crossing_behind": "one person crosses the robot's line just behind it",
    "two_sides": "two people cross at once from both sides",
    "overtaking": "one person overtakes the robot from behind along its line",
    "head_on_corridor": "one person walks head-on down a 2.1 m corridor of disks",
    "stopping": "one person walks into the path and stands there 8 s beside the target's line",
    "crowd": "seven people cross from both sides, staggered",
    "beside_target": "a person walks beside the target, then overtakes it and cuts across ahead",
}
QUICK_RUNS = 2

# The spread of every variant.
ENCOUNTER = 15.0               # [s] when the scenes' people reach the robot's line (see the scenes)
SPEEDS = (0.3, 1.2)            # [m/s] each person's walking speed, drawn uniformly
WALKING = 0.25                 # [m/s] legs faster than this are walking (scaled); slower ones keep their speed
TIMING = 1.5                   # [s] each person reaches its encounter point within +-this
PERSON_SHIFT = 0.15            # [m] each person's path shifts within this disk
POSE_SHIFT, HEADING_SHIFT = 0.2, 0.3  # [m], [rad] the robot's start
NOISE = 0.03                   # [m] target noise std drawn in [0, NOISE]
SAMPLE_PERIODS = (0.05, 0.1)   # [s] target sample period drawn from these
START_MARGIN = 0.05            # [m] a person at least this far outside the start's keep-out zones

# (heading, summary key, digits or None for an integer) of each column after class and law.
COLUMNS = [
    ("runs", "runs", None),
    ("failed", "failed", None),
    ("mean true ASE [m²]", "mean_true_ase", 3),
    ("worst true ASE [m²]", "worst_true_ase", 3),
    ("runs with contact", "runs_with_contact", None),
    ("min body clearance [m]", "min_clearance_body", 3),
    ("diamond violations", "diamond_violations", None),
    ("widenings", "envelope_widenings", None),
    ("runs with NaN or invalid steps", "runs_with_nan", None),
    ("ω reversals /min (mean)", "mean_omega_reversals_per_minute", 3),
    ("max abs Δv [m/s]", "max_delta_v", 3),
    ("max abs Δω [rad/s]", "max_delta_omega", 3),
]
HEADINGS = ["class", "law"] + [c[0] for c in COLUMNS]


def walked(legs, tau):
    """Distance walked tau seconds into the legs [(duration, speed)]."""
    total = 0.0
    for duration, speed in legs:
        step = min(tau, duration)
        if step <= 0.0:
            break
        total += speed * step
        tau -= duration
    return total


def time_to_walk(legs, distance):
    """The first time into the legs [(duration, speed)] at which `distance` is walked."""
    tau = 0.0
    for duration, speed in legs:
        if speed > 0.0 and distance <= speed * duration + 1e-12:
            return tau + distance / speed
        distance -= speed * duration
        tau += duration
    return tau


def person_variant(obstacle, rng):
    """A person at a drawn walking speed who is where the scene puts it at ENCOUNTER (+- TIMING):
    walking legs scaled to the speed, the others kept; the start moved back along the first leg
    when the person must already be walking at t = 0. Changes `obstacle` in place."""
    motion = obstacle["motion"]
    legs = [(leg["duration"], math.hypot(*leg["velocity"])) for leg in motion["legs"]]
    at_encounter = walked(legs, ENCOUNTER - motion.get("start_time", 0.0))
    speed = rng.uniform(*SPEEDS)
    for leg in motion["legs"]:
        norm = math.hypot(*leg["velocity"])
        if norm > WALKING:
            leg["velocity"] = [v * speed / norm for v in leg["velocity"]]
            leg["duration"] = leg["duration"] * norm / speed
    legs = [(leg["duration"], math.hypot(*leg["velocity"])) for leg in motion["legs"]]
    start_time = ENCOUNTER + rng.uniform(-TIMING, TIMING) - time_to_walk(legs, at_encounter)
    angle, radius = rng.uniform(0.0, 2.0 * math.pi), PERSON_SHIFT * math.sqrt(rng.random())
    center = [obstacle["center"][0] + radius * math.cos(angle), obstacle["center"][1] + radius * math.sin(angle)]
    if start_time < 0.0:  # already walking at t = 0: start where it is then
        first = motion["legs"][0]
        center = [c - v * start_time for c, v in zip(center, first["velocity"])]
        first["duration"] = first["duration"] + start_time
        start_time = 0.0
    obstacle["center"] = center
    motion["start_time"] = start_time
    motion["legs"] = [leg for leg in motion["legs"] if leg["duration"] > 1e-6]


def feasible_start(data):
    """No disk within START_MARGIN of the start's keep-out zones (the offset point's, R + r: the
    scenes are body-safe; the body's, R), as the simulator checks a start."""
    robot = data["robot"]
    x, y, theta = robot["initial_pose"]
    r, radius = robot["offset"], robot["radius"]
    p_r = (x + r * math.cos(theta), y + r * math.sin(theta))
    for o in data["obstacles"]:
        zone = radius + r + o["radius"]
        if math.dist(p_r, o["center"]) < zone + START_MARGIN or math.dist((x, y), o["center"]) < radius + o["radius"]:
            return False
    return True


def make_variant(base, index, seed=1):
    """Variant `index` of the scene `base` (a dict): reproducible from (seed, index)."""
    rng = random.Random(seed * 1000003 + index)
    for _ in range(100):
        data = json.loads(json.dumps(base))  # a deep copy
        for o in data["obstacles"]:
            if "motion" in o:
                person_variant(o, rng)
        x, y, theta = data["robot"]["initial_pose"]
        angle, radius = rng.uniform(0.0, 2.0 * math.pi), POSE_SHIFT * math.sqrt(rng.random())
        data["robot"]["initial_pose"] = [x + radius * math.cos(angle), y + radius * math.sin(angle),
                                         theta + rng.uniform(-HEADING_SHIFT, HEADING_SHIFT)]
        data["target"] = {"noise_std": rng.uniform(0.0, NOISE), "sample_period": rng.choice(SAMPLE_PERIODS)}
        data["simulation"]["seed"] = index + 1  # the target noise's
        data["simulation"]["log_period"] = 1.0  # the benchmark reads metrics.json only
        if feasible_start(data):
            return data
    raise RuntimeError(f"no feasible start in 100 draws (variant {index})")


def run_one(sim, scenario, law, out, sets):
    """One run: its metrics dict, or {"failed": reason} (a law's error, a refused scenario)."""
    cmd = [sim, "--scenario", scenario, "--out", out, "--no-plot"] + LAWS[law]
    for s in sets:
        cmd += ["--set", s]
    done = subprocess.run(cmd, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True)
    if done.returncode != 0:
        lines = [line for line in done.stderr.splitlines() if line.startswith("amigobot_sim:")]
        return {"failed": (lines or done.stderr.strip().splitlines() or [f"exit {done.returncode}"])[-1]}
    with open(os.path.join(out, "metrics.json")) as f:
        return json.load(f)


def summarize(runs):
    """The table's figures of one class and law from its runs' metrics."""
    ok = [m for m in runs if "failed" not in m]
    s = {"runs": len(runs), "failed": len(runs) - len(ok), "reasons": sorted({m["failed"] for m in runs if "failed" in m})}
    if not ok:
        return s
    s.update({
        "mean_true_ase": sum(m["true_ase"] for m in ok) / len(ok),
        "worst_true_ase": max(m["true_ase"] for m in ok),
        "runs_with_contact": sum(m["body_collisions"] > 0 for m in ok),
        "min_clearance_body": min(m["min_clearance_body"] for m in ok),
        "diamond_violations": sum(m["diamond_violations"] for m in ok),
        "envelope_widenings": sum(m["envelope_widenings"] for m in ok),
        "runs_with_nan": sum(m["nan_count"] > 0 for m in ok),
        "mean_omega_reversals_per_minute": sum(m["omega_reversals_per_minute"] for m in ok) / len(ok),
        "max_delta_v": max(m["max_delta_v"] for m in ok),
        "max_delta_omega": max(m["max_delta_omega"] for m in ok),
    })
    return s


def untouched_rows(raw, classes, laws):
    """Per class: the variants where MRPT's navigator touched no one, and each law's mean true ASE
    on them: the laws compared where MRPT kept clear too, not against runs it won by walking into
    a person."""
    rows = []
    for name in classes:
        peer = raw.get((name, "mrpt_reactive"))
        if peer is None:
            continue
        clean = [i for i, m in enumerate(peer) if "failed" not in m and m["body_collisions"] == 0]
        means = {}
        for law in laws:
            runs = raw.get((name, law), [])
            ase = [runs[i]["true_ase"] for i in clean if i < len(runs) and "failed" not in runs[i]]
            means[law] = sum(ase) / len(ase) if ase and len(ase) == len(clean) else None
        rows.append((name, len(clean), len(peer), means))
    return rows


def cells(summary):
    """The table cells of one class and law (after class and law)."""
    row = []
    for _, key, digits in COLUMNS:
        value = summary.get(key)
        row.append("—" if value is None else str(value) if digits is None else markdown.number(value, digits))
    return row


def write_page(path, results, runs, seconds, quick, sets, untouched=()):
    page = markdown.Page()
    page("# Pedestrian benchmark")
    page("")
    page("Generated by `make pedestrians` (scripts/reports/pedestrians.py" + (" --quick" if quick else "") + "); "
         f"{runs} Monte Carlo variants per class, each run by every law, {seconds:.0f} s on this machine"
         + (f", with {', '.join(sets)}" if sets else "") + ". "
         "Scenes: config/scenarios/pedestrians/ (body-safe, Section 5.3's gains and limits, 20 Hz; on the "
         "AmigoBot's dynamics: the firmware's ramps, 0.1 s cycle and 0.1 s latency, core/robot/actuator_model.h). People are disks of 0.25 m on piecewise-constant velocities. "
         f"Each variant draws every person's walking speed in [{SPEEDS[0]}, {SPEEDS[1]}] m/s (legs slower than "
         f"{WALKING} m/s, standing or pacing beside the target, keep theirs), keeps where they are at the "
         f"encounter (t = {ENCOUNTER:.0f} s) within ±{TIMING} s, shifts their paths within {PERSON_SHIFT} m and the "
         f"robot's start within {POSE_SHIFT} m and ±{HEADING_SHIFT} rad, draws the target noise in [0, {NOISE * 100:.0f} cm] "
         f"and a sample period of {' or '.join(f'{p * 1000:.0f}' for p in SAMPLE_PERIODS)} ms.")
    page("")
    page("True ASE uses the true target and robot. Contact: the body disk (radius R) overlaps a person or a disk "
         "(true clearance < 0); min body clearance is the least over the runs. Widenings: steps where the guard "
         "widened ρ (0 for a law without ρ). ω reversals: sign changes of ω beyond ±0.01 rad/s per minute of run; "
         "Δv, Δω: the largest change of the command between two steps. Failed: runs that ended in an error "
         "(a law's own, named below) instead of metrics. The recommended law uses the people's velocities (its barrier rows) "
         "and their paths over `obstacle_lookahead` (its field): it is the constant-velocity-prediction variant. "
         "How it yields to people, waits beside a person's way and passes behind one who stopped, and what each of "
         "those rules changed on these variants: docs/recommended_law.md.")
    page("")
    markdown.benchmark_table(page, HEADINGS, results, cells, CLASSES)
    if untouched:
        laws = list(untouched[0][3])
        page("")
        page("Mean true ASE [m²] on the variants where MRPT's navigator touched no one (the same variants "
             "for every law; a class where it touched someone in every variant has none):")
        page("")
        page("| class | variants | " + " | ".join(laws) + " |")
        page("|---|---|" + "---|" * len(laws))
        for name, clean, total, means in untouched:
            page(f"| {name} | {clean} of {total} | "
                 + " | ".join("—" if means[law] is None else markdown.number(means[law], 3) for law in laws) + " |")
    failures = [(name, law, reason) for name, law, s in results for reason in s.get("reasons", [])]
    if failures:
        page("")
        page("Failed runs:")
        for name, law, reason in failures:
            page(f"- {name} / {law}: {reason}")
    page.save(path)


def main(sim, out_root, docs, runs=50, jobs=None, classes=None, quick=False, laws=None, sets=()):
    """Writes the variants, runs them and DOCS/pedestrians.md; returns [(class, law, summary)]."""
    jobs = jobs or os.cpu_count() or 1
    laws = laws or list(LAWS)
    start = time.monotonic()
    results = []
    raw = {}
    with concurrent.futures.ThreadPoolExecutor(jobs) as pool:
        for name in classes or list(CLASSES):
            base = scenario_yaml.load(os.path.join(SCENES, name + ".yaml"))
            folder = os.path.join(out_root, name, "variants")
            os.makedirs(folder, exist_ok=True)
            files = []
            for i in range(runs):
                files.append(os.path.join(folder, f"{i:03d}.yaml"))
                scenario_yaml.write_data(make_variant(base, i), files[-1])
            for law in laws:
                print(f"pedestrians: {name} / {law} ({runs} variants)", file=sys.stderr, flush=True)
                futures = [pool.submit(run_one, sim, f, law, os.path.join(out_root, name, law, f"{i:03d}"), sets)
                           for i, f in enumerate(files)]
                raw[(name, law)] = [f.result() for f in futures]
                results.append((name, law, summarize(raw[(name, law)])))
    os.makedirs(docs, exist_ok=True)
    write_page(os.path.join(docs, "pedestrians.md"), results, runs, time.monotonic() - start, quick, sets,
               untouched_rows(raw, classes or list(CLASSES), laws))
    with open(os.path.join(out_root, "pedestrians.json"), "w") as f:
        json.dump([{"class": n, "law": law, **s} for n, law, s in results], f, indent=1)
    return results


if __name__ == "__main__":
    args = batch_cli.parse(__doc__, "pedestrians.py", "pedestrians", ROOT, CLASSES, LAWS, QUICK_RUNS,
                           lambda p: p.add_argument("--set", action="append", default=[],
                                                    help="section.key=value for every run (repeatable)"))
    main(args.sim, args.out, args.docs, args.runs, args.jobs, args.classes, args.quick, args.laws, args.set)
