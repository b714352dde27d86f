#!/usr/bin/python3
"""The spread of `make demo` over N runs: is the demo's result stable?

Runs scripts/reports/run_demo.py N times (each a whole stack on its own private master, one after
the other) into OUT/run_1 ... OUT/run_N, then writes OUT/spread.md and OUT/spread.json: min /
median / max of the figures below over the runs, and every run's verdict (exit code).
Exit 0 when every run was safe and tracked, 1 otherwise.
Usage: demo_spread.py [--runs 5] [--ws WS] [--out report/demo_spread] [--paper-law] [run_demo options]
       demo_spread.py --collect OUT   (only re-read OUT/run_*/metrics.json)
"""
import argparse
import glob
import json
import os
import statistics
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))
sys.path.insert(0, os.path.join(ROOT, "scripts", "test"))
import stack_processes as sp  # noqa: E402
# (label, getter over metrics.json)
FIGURES = [
    ("AAE [m]", lambda m: m["aae"]),
    ("ASE [m²]", lambda m: m["ase"]),
    ("IAE ∫‖e‖dt [m s]", lambda m: m["iae"]),
    ("ISE ∫‖e‖²dt [m² s]", lambda m: m["ise"]),
    ("true AAE [m]", lambda m: m["true_aae"]),
    ("final true ‖e*‖ [m]", lambda m: m["tracking"]["final_true_error"]),
    ("max judged true ‖e*‖ [m]", lambda m: m["tracking"]["max_judged_true_error"]),
    ("judged share of the run", lambda m: m["tracking"]["judged_fraction"]),
    ("max ‖e‖/ρ", lambda m: m["max_e_over_rho"]),
    ("max ρ [m]", lambda m: m["max_rho"]),
    ("min true body clearance, world [m]", lambda m: m["min_clearance_world"]),
    ("min true body clearance, virtual [m]", lambda m: m["min_clearance_virtual"]),
    ("saturated share of steps", lambda m: m["saturated_fraction"]),
    ("longest recovery after an obstacle [s]",
     lambda m: max([e["recovered_after_s"] for e in m["tracking"]["episodes"] if e["recovered_after_s"] is not None],
                   default=None)),
]
VERDICTS = {0: "safe, tracked", 3: "UNSAFE", 4: "did not run", 5: "safe, did not track"}


def value(getter, metrics):
    try:
        return getter(metrics)
    except (KeyError, TypeError):
        return None


def collect(out):
    runs = []
    for folder in sorted(glob.glob(os.path.join(out, "run_*")), key=lambda p: int(p.rsplit("_", 1)[1])):
        path = os.path.join(folder, "metrics.json")
        metrics = json.load(open(path)) if os.path.exists(path) else {}
        rc_path = os.path.join(folder, "exit_code")
        rc = int(open(rc_path).read()) if os.path.exists(rc_path) else None
        runs.append((os.path.basename(folder), rc, metrics))
    return runs


def write(out, runs):
    table = ["| figure | min | median | max | runs |", "|---|---|---|---|---|"]
    spread = {}
    for label, getter in FIGURES:
        values = [v for v in (value(getter, m) for _, _, m in runs) if isinstance(v, (int, float))]
        if not values:
            continue
        spread[label] = {"min": min(values), "median": statistics.median(values), "max": max(values), "n": len(values)}
        table.append(f"| {label} | {min(values):.4g} | {statistics.median(values):.4g} | {max(values):.4g} | "
                     f"{len(values)} |")
    laws = sorted({m.get("law", "?") for _, _, m in runs})
    verdicts = [(name, rc, VERDICTS.get(rc, f"exit {rc}")) for name, rc, _ in runs]
    lines = [f"# make demo, {len(runs)} runs (law: {', '.join(laws)})", "",
             "Each run: scripts/reports/run_demo.py on its own private master; figures from its metrics.json.", "",
             *table, "", "| run | exit | verdict | tracking reason |", "|---|---|---|---|"]
    for (name, rc, text), (_, _, m) in zip(verdicts, runs):
        reason = (m.get("tracking") or {}).get("reason") or "–"
        lines.append(f"| {name} | {rc} | {text} | {reason} |")
    with open(os.path.join(out, "spread.md"), "w") as f:
        f.write("\n".join(lines) + "\n")
    with open(os.path.join(out, "spread.json"), "w") as f:
        json.dump({"laws": laws, "figures": spread, "runs": [{"run": n, "exit": rc} for n, rc, _ in verdicts]}, f,
                  indent=2)
    print("\n".join(lines))
    return all(rc == 0 for _, rc, _ in verdicts)


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--runs", type=int, default=5)
    parser.add_argument("--ws", default=sp.default_workspace())
    parser.add_argument("--out", default=os.path.join(ROOT, "report", "demo_spread"))
    parser.add_argument("--collect", action="store_true", help="only summarise the runs already in --out")
    args, demo_args = parser.parse_known_args()
    out = os.path.abspath(args.out)
    os.makedirs(out, exist_ok=True)
    if not args.collect:
        for k in range(1, args.runs + 1):
            folder = os.path.join(out, f"run_{k}")
            print(f"[demo_spread] run {k}/{args.runs} -> {folder}", flush=True)
            rc = subprocess.run([os.path.join(HERE, "run_demo.py"), "--ws", args.ws, "--out", folder] + demo_args).returncode
            with open(os.path.join(folder, "exit_code"), "w") as f:
                f.write(f"{rc}\n")
    return 0 if write(out, collect(out)) else 1


if __name__ == "__main__":
    sys.exit(main())
