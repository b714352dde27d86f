#!/usr/bin/python3
"""Beyond the paper, measured: each switch beyond the paper, on against off. Writes docs/beyond_paper.md
and docs/figures/beyond_paper/*.png; `make reproduce` calls it after the paper's Section 5.

Usage: scripts/reports/beyond_paper.py --sim PATH/amigobot_sim [--out out/reproduce] [--docs docs]
"""
import argparse
import json
import os
import statistics
import subprocess

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

import scenario_yaml  # noqa: E402

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
SHIPPED = ["paper_5_1", "paper_5_2_rose", "experiment_5_3", "saddle_line", "crossing_obstacles"]
DELAYS = [0.0, 0.1, 0.2, 0.3]
SEEDS = [1, 2, 3, 4, 5]
COMPENSATION = [  # label, flags
    ("none", ["--predict-target", "false", "--compensate-pose-age", "false"]),
    ("predict_target", ["--predict-target", "true", "--compensate-pose-age", "false"]),
    ("compensate_pose_age", ["--predict-target", "false", "--compensate-pose-age", "true"]),
    ("both", ["--predict-target", "true", "--compensate-pose-age", "true"]),
]
MC_RUNS = 100


def scenario_path(name):
    return os.path.join(ROOT, "config", "scenarios", name + ".yaml")


def run(sim, scenario, out, args, log=False):
    cmd = [sim, "--scenario", scenario, "--out", out, "--no-plot"] + args
    if not log:
        cmd += ["--log-period", "1000"]  # first and last rows only: the metrics are what counts
    subprocess.run(cmd, check=True, stdout=subprocess.DEVNULL)
    with open(os.path.join(out, "metrics.json")) as f:
        return json.load(f)


def monte_carlo(sim, scenario, out, args, runs=MC_RUNS):
    cmd = [sim, "--scenario", scenario, "--out", out, "--monte-carlo", str(runs), "--seed", "1"] + args
    subprocess.run(cmd, check=True, stdout=subprocess.DEVNULL)
    with open(os.path.join(out, "monte_carlo.json")) as f:
        return json.load(f)


def variant_file(out_root, name, edit, label):
    """A copy of a shipped scenario with `edit(data)` applied to its YAML data (scenario_yaml.py)."""
    return scenario_yaml.write_variant(scenario_path(name), os.path.join(out_root, f"{name}_{label}.yaml"), edit)


def g(x, digits=3):
    if x is None:
        return "—"
    return f"{x:.{digits}g}" if abs(x) < 1e4 else f"{x:.0f}"


def load_csv(path):
    with open(path) as f:
        header = f.readline().strip().split(",")
    data = np.loadtxt(path, delimiter=",", skiprows=1, ndmin=2)
    return {name: data[:, i] for i, name in enumerate(header)}


def saddle(sim, out_root, figs):
    base = os.path.join(out_root, "beyond", "saddle")
    path = scenario_path("saddle_line")
    exact = {on: run(sim, path, os.path.join(base, f"tangential_{on}"), ["--tangential", on], log=True)
             for on in ("false", "true")}
    # Plots: the paths and |e| of both runs.
    fig, (ax, bx) = plt.subplots(1, 2, figsize=(11, 3.6))
    disk = exact["false"]["scenario"]["obstacles"][0]
    for on, style, label in [("false", "r-", "paper law (off)"), ("true", "b-", "tangential escape (on)")]:
        d = load_csv(os.path.join(base, f"tangential_{on}", "trajectory.csv"))
        ax.plot(d["p_r_true_x"], d["p_r_true_y"], style, lw=1.2, label=label + ": p_r")
        bx.plot(d["t"], np.hypot(d["p_d_x"] - d["p_r_true_x"], d["p_d_y"] - d["p_r_true_y"]), style, label=label)
        if on == "false":  # where the paper law stands (under the escape's path until there)
            ax.plot(d["p_r_true_x"][-1], d["p_r_true_y"][-1], "rx", ms=8, mew=2, label="paper law: p_r stops here")
    d = load_csv(os.path.join(base, "tangential_true", "trajectory.csv"))
    ax.plot(d["p_d_x"], d["p_d_y"], "k--", lw=0.8, label="target")
    ax.add_patch(plt.Circle(disk["center"], disk["radius"], color="0.5"))
    ax.add_patch(plt.Circle(disk["center"], disk["radius"] + exact["true"]["scenario"]["effective_radius"], fill=False,
                            ls=":", color="0.4"))
    ax.set_aspect("equal")
    ax.set_xlim(-0.2, 9.5)
    ax.set_xlabel("x [m]")
    ax.set_ylabel("y [m]")
    ax.legend(fontsize=7, loc="upper right")
    ax.set_title("saddle_line: offset point paths")
    bx.set_xlabel("t [s]")
    bx.set_ylabel("true |e| [m]")
    bx.set_yscale("log")
    bx.legend(fontsize=7)
    bx.set_title("tracking error")
    fig.tight_layout()
    fig.savefig(os.path.join(figs, "saddle.png"), dpi=72)
    plt.close(fig)

    # The same with 1 cm measurement noise, which breaks the symmetry for the paper law too: at 10 Hz
    # like SLAM, and at every 10 ms step (a stress case: v_hat is then mostly differentiated noise).
    noisy = {}
    for label, section in [("10hz", {"sample_period": 0.1, "noise_std": 0.01}), ("100hz", {"noise_std": 0.01})]:
        noisy_path = variant_file(out_root, "saddle_line", lambda d, s=section: scenario_yaml.set_key(
            d, "target", dict(s), must_exist=False), "noisy_" + label)
        for on in ("false", "true"):
            noisy[(label, on)] = [run(sim, noisy_path, os.path.join(base, f"noisy_{label}_{on}_{s}"),
                                      ["--tangential", on, "--seed", str(s)]) for s in SEEDS]
    # The side latch: the previous default margin 0.2 against 0.6.
    h02 = variant_file(out_root, "saddle_line",
                       lambda d: scenario_yaml.set_key(d, "controller.tangential_hysteresis", 0.2), "h02")
    latch = {"0.2": run(sim, h02, os.path.join(base, "h02"), ["--tangential", "true"]), "0.6": exact["true"]}
    return exact, noisy, latch


def clearance(sim, out_root):
    rows = []
    for name in SHIPPED:
        ships_safe = scenario_yaml.load(scenario_path(name))["controller"].get("body_safe") is True
        for radius in ("shipped",) if ships_safe else ("shipped", "true"):
            extra = [] if radius == "shipped" else ["--body-safe", "true"]
            m = {on: run(sim, scenario_path(name), os.path.join(out_root, "beyond", "clearance", name, radius, on),
                         extra + ["--tangential", on]) for on in ("false", "true")}
            rows.append((name, m["false"]["scenario"]["body_safe"], m["false"], m["true"]))
    return rows


def clearance_mc(sim, out_root, runs=50):
    """The escape against the paper law over randomised variants of the static scenarios."""
    rows = []
    for name in SHIPPED[:4]:
        for body_safe in ("false", "true"):
            j = {on: monte_carlo(sim, scenario_path(name),
                                 os.path.join(out_root, "beyond", "clearance_mc", name, body_safe, on),
                                 ["--body-safe", body_safe, "--tangential", on], runs) for on in ("false", "true")}
            rows.append((name, body_safe, j["false"], j["true"]))
    return rows


def moving(sim, out_root):
    path = scenario_path("crossing_obstacles")
    batches = []
    for body_safe in ("false", "true"):
        for label, flags in [("paper (10)", ["--moving-obstacles", "false"]),
                             ("moving_obstacles", ["--moving-obstacles", "true"]),
                             ("moving_obstacles + tangential", ["--moving-obstacles", "true", "--tangential", "true"])]:
            out = os.path.join(out_root, "beyond", "moving", body_safe, label.replace(" ", "").replace("+", "_"))
            j = monte_carlo(sim, path, out, ["--body-safe", body_safe, "--obstacle-speed", "0.3"] + flags)
            batches.append((body_safe, label, j))
    return batches


def delay(sim, out_root, figs):
    path = scenario_path("experiment_5_3")
    table = {}  # (tangential, mode, delay) -> [true ASE per seed]
    for tangential in ("false", "true"):
        for mode, flags in COMPENSATION:
            for d in DELAYS:
                values = []
                for s in SEEDS:
                    out = os.path.join(out_root, "beyond", "delay", f"tangential_{tangential}", mode, f"{d:g}", str(s))
                    m = run(sim, path, out, flags + ["--tangential", tangential, "--target-delay", f"{d}",
                                                     "--pose-delay", f"{d}", "--pose-period", "0.1", "--seed", str(s)])
                    values.append(m["true_ase"])
                table[(tangential, mode, d)] = values
    # Target delay alone (robot pose fresh and continuous): what prediction can do by itself.
    for mode, flags in COMPENSATION[:2]:
        for d in DELAYS:
            table[("target_only", mode, d)] = [
                run(sim, path, os.path.join(out_root, "beyond", "delay", "target_only", mode, f"{d:g}", str(s)),
                    flags + ["--target-delay", f"{d}", "--seed", str(s)])["true_ase"] for s in SEEDS]
    # Prediction against measurement noise: the shipped 1 cm, none, and either without obstacles.
    noise = {}
    def keep(data):
        pass
    for label, edit in [("1 cm noise", keep), ("no noise", lambda d: scenario_yaml.set_key(d, "target.noise_std", 0.0))]:
        for place, edit2 in [("with the square", keep),
                             ("no obstacles", lambda d: scenario_yaml.set_key(d, "obstacles", []))]:
            f = variant_file(out_root, "experiment_5_3", lambda d, a=edit, b=edit2: (a(d), b(d)),
                             (label + "_" + place).replace(" ", "_"))
            for d in (0.0, 0.3):
                for p in ("false", "true"):
                    runs = [run(sim, f, os.path.join(out_root, "beyond", "delay", "noise",
                                                     f"{label}{place}{d}{p}".replace(" ", ""), str(s)),
                                ["--target-delay", f"{d}", "--predict-target", p, "--seed", str(s)]) for s in SEEDS]
                    noise[(label, place, d, p)] = statistics.mean(m["true_ase"] for m in runs)
                    noise[(label, place, d, p, "v")] = statistics.mean(m["estimator_rms_error"] for m in runs)
    table["noise"] = noise
    # The reference: no delay at all and the robot pose continuous (as the shipped file, delay 0).
    reference = {t: statistics.mean(run(sim, path, os.path.join(out_root, "beyond", "delay", f"ref_{t}_{s}"),
                                        ["--tangential", t, "--target-delay", "0", "--seed", str(s)])["true_ase"]
                                    for s in SEEDS) for t in ("false", "true")}
    fig, axes = plt.subplots(1, 2, figsize=(11, 3.8), sharey=True)
    for ax, tangential in zip(axes, ("false", "true")):
        for (mode, _), style in zip(COMPENSATION, ["r-o", "m-^", "g-s", "b-D"]):
            means = [statistics.mean(table[(tangential, mode, d)]) for d in DELAYS]
            lo = [min(table[(tangential, mode, d)]) for d in DELAYS]
            hi = [max(table[(tangential, mode, d)]) for d in DELAYS]
            x = [1e3 * d for d in DELAYS]
            ax.plot(x, means, style, label=mode, ms=4)
            ax.fill_between(x, lo, hi, color=style[0], alpha=0.12)
        ax.axhline(reference[tangential], color="k", ls=":", lw=1, label="no delay, continuous pose")
        ax.set_xlabel("delay of target and robot pose [ms] (both sampled at 10 Hz)")
        ax.set_title(f"experiment_5_3, tangential_avoidance {tangential}")
        ax.grid(alpha=0.3)
    axes[0].set_ylabel("true ASE [m²] (mean of 5 seeds; band: min-max)")
    axes[0].legend(fontsize=7)
    fig.tight_layout()
    fig.savefig(os.path.join(figs, "delay_ase.png"), dpi=72)
    plt.close(fig)
    return table, reference


def write(path, saddle_res, clearance_rows, mc_rows, batches, delay_res):
    exact, noisy, latch = saddle_res
    table, reference = delay_res
    L = []
    w = L.append
    w("# Beyond the paper: measured")
    w("")
    w("Generated by `make reproduce` (scripts/reports/beyond_paper.py) with the offline simulator; every number comes from")
    w("`out/reproduce/beyond/**/metrics.json` or `monte_carlo.json`. Each mechanism is a switch of the controller")
    w("(`controller_config.h`, scenario keys in `config/scenarios/*.yaml`, flags of `amigobot_sim`); off is the paper.")
    w("")
    w("## Definitions")
    w("")
    w("- **True error** e* = p_d(t) − p_r(t): the true target minus the true offset point. The controller's own e uses")
    w("  the measured (late, noisy) target and the pose it believes; with delays the two differ, so the figures of this")
    w("  page use e*: **true ASE** = (1/T)∫‖e*‖²dt, **peak ‖e*‖** = max over the run.")
    w("- **Stall**: the offset point makes no headway although it is far behind. A step at t is *stalled* when")
    w("  ‖p_r(t) − p_r(t − 0.5 s)‖ < 0.05 m/s × 0.5 s (net displacement, so chattering in place counts as standing)")
    w("  and ‖e*(t)‖ > 0.2 m (twice the experiment's ρ_∞). Consecutive stalled steps t_a…t_b form one stall over")
    w("  [t_a − 0.5 s, t_b]; the **longest stall** is the longest such interval (0 if no step is stalled).")
    w("- **Clearance**: offset = the disk of radius R around p_r (what the paper's law guarantees with its radius);")
    w("  body = the disk of radius R around the centre (the real robot). A contact is an episode of negative clearance.")
    w("- **Escape steps**: steps with a non-zero tangential term; **conflict steps** (paper law): steps with êᵀu_c < 0;")
    w("  **side flips**: steps whose latched passing side is the opposite of the previous step's.")
    w("")
    w("## 1. No deadlock behind an obstacle (`tangential_avoidance`)")
    w("")
    w("`config/scenarios/saddle_line.yaml`: the target drives the x axis at 0.3 m/s through the centre of a 0.3 m disk;")
    w("the robot starts on the same line behind it. Limits v̄ = 0.6 m/s, ω̄ = 1.6 rad/s: the experiment's diamond with")
    w("twice the wheel speed (same wheel base v̄/ω̄ = 0.375 m). With the paper's v̄ = 0.3 m/s = the target's speed,")
    w("any detour leaves the robot behind for good (full speed needs ω = 0), so catching up could not be measured.")
    w("No noise, a sample every 10 ms step: the case is exactly symmetric.")
    w("")
    w("| run | longest stall [s] | peak ‖e*‖ [m] | true ASE [m²] | final ‖e*‖ [m] | min clearance offset [m] | min clearance body [m] | contacts | escape steps | side flips |")
    w("|---|---|---|---|---|---|---|---|---|---|")
    for on, label in [("false", "paper law (off)"), ("true", "tangential escape (on)")]:
        m = exact[on]
        w(f"| {label} | {g(m['longest_stall_s'])} | {g(m['max_true_error'])} | {g(m['true_ase'])} | "
          f"{g(m['final_error'])} | {g(m['min_clearance_offset'])} | {g(m['min_clearance_body'])} | "
          f"{int(m['offset_collisions'] + m['body_collisions'])} | {int(m['escape_steps'])} | {int(m['side_flips'])} |")
    w("")
    off, on = exact["false"], exact["true"]
    ok_stall = on["longest_stall_s"] <= 0.5
    ok_peak = on["max_true_error"] <= 0.5 * off["max_true_error"]
    w(f"Targets: stall ≤ 0.5 s — **{'met' if ok_stall else 'NOT met'}** ({g(on['longest_stall_s'])} s against "
      f"{g(off['longest_stall_s'])} s); peak ‖e*‖ ≤ ½ of the paper law's — **{'met' if ok_peak else 'NOT met'}** "
      f"({g(on['max_true_error'])} m against {g(off['max_true_error'])} m, ratio {on['max_true_error'] / off['max_true_error']:.2f}).")
    w("In the exactly symmetric discrete loop the paper law never leaves the saddle: it stands for the whole run and")
    w("its peak error is the target's head start at the end, so that peak grows with the run's length. With 1 cm of")
    w("measurement noise (5 seeds) the noise frees it after a few seconds, as expected:")
    w("")
    w("| 1 cm noise, 5 seeds | run | longest stall [s] (mean / max) | peak ‖e*‖ [m] (mean / max) | peak ratio on/off per seed | min clearance body [m] | side flips (max) |")
    w("|---|---|---|---|---|---|---|")
    for noise, title in [("10hz", "sampled at 10 Hz (SLAM-like)"), ("100hz", "every 10 ms step (stress)")]:
        ratio = [b["max_true_error"] / a["max_true_error"] for a, b in zip(noisy[(noise, "false")], noisy[(noise, "true")])]
        for key, label in [("false", "paper law (off)"), ("true", "tangential escape (on)")]:
            runs = noisy[(noise, key)]
            st = [m["longest_stall_s"] for m in runs]
            pk = [m["max_true_error"] for m in runs]
            ratios = ", ".join(f"{r:.2f}" for r in ratio) if key == "true" else ""
            w(f"| {title} | {label} | {g(statistics.mean(st))} / {g(max(st))} | {g(statistics.mean(pk))} / {g(max(pk))} | "
              f"{ratios} | {g(min(m['min_clearance_body'] for m in runs))} | {max(int(m['side_flips']) for m in runs)} |")
    r10 = max(b["max_true_error"] / a["max_true_error"] for a, b in zip(noisy[("10hz", "false")], noisy[("10hz", "true")]))
    r100 = max(b["max_true_error"] / a["max_true_error"] for a, b in zip(noisy[("100hz", "false")], noisy[("100hz", "true")]))
    w("")
    v100 = statistics.mean(m["estimator_rms_error"] for m in noisy[("100hz", "true")])
    v10 = statistics.mean(m["estimator_rms_error"] for m in noisy[("10hz", "true")])
    w(f"Peak ratio ≤ ½ at 10 Hz: **{'met' if r10 <= 0.5 else 'NOT met'}** (worst seed {r10:.2f}); in the 100 Hz stress case "
      f"**{'met' if r100 <= 0.5 else 'NOT met'}** (worst seed {r100:.2f}): there the paper estimator turns 1 cm of noise")
    w(f"at 100 Hz into a v̂ off by {g(v100, 2)} m/s RMS (at 10 Hz: {g(v10, 2)} m/s) against a target at 0.3 m/s, which")
    w("shakes both laws and lengthens the detour.")
    w("")
    w("![saddle](figures/beyond_paper/saddle.png)")
    w("")
    w("**Side choice.** The escape adds, for every detected obstacle that opposes tracking (w_j = max(0, −êᵀn_j) > 0),")
    w("w_j‖u_cj‖ along ±n_j^⊥: perpendicular to the outward normal, so it never pushes into the disk and leaves the")
    w("radial barrier (10) as it is. The side is the one that turns toward the target (sign of the weighted sine")
    w("between −n and ê; exactly symmetric: counter-clockwise), *latched*: it switches only when that sine exceeds")
    w("`tangential_hysteresis` on the other side, and it is released when no obstacle opposes tracking any more.")
    h2, h6 = latch["0.2"], latch["0.6"]
    w(f"Measured here: with the margin 0.2 the side flipped {int(h2['side_flips'])} times (stall {g(h2['longest_stall_s'])} s, "
      f"peak {g(h2['max_true_error'])} m) — close to the disk ‖e‖ is short and the escape itself moves p_r sideways, so ê")
    w(f"turns by more than 0.2 — with 0.6 (now the default) {int(h6['side_flips'])} flips (stall {g(h6['longest_stall_s'])} s,"
      f" peak {g(h6['max_true_error'])} m).")
    w("")
    w("**Cap.** The escape redirects the attraction that the barrier cancels, so k_o‖u_t‖ is capped at k_t times the")
    w("attraction of (9) (k_d T ê + v̂ + λ(ρ − ρ_∞)e/ρ). Uncapped it grows like u_c (1/margin) and, after the diamond's")
    w("radial scaling, crowds out the radial barrier: on crossing_obstacles.yaml the uncapped escape (without")
    w("`moving_obstacles`) let the offset point touch a crossing person 3 times; capped, no contact (table below).")
    w("At the saddle the cap changes nothing (there the repulsion equals the attraction).")
    w("")
    w("### Clearance on every shipped scenario, escape off against on")
    w("")
    w("Each shipped scenario as shipped (`body_safe` of the file), and with `--body-safe true`. *Identical* = every")
    w("figure equal (the escape never acted). Target: min clearance with the escape ≥ without, or no contact.")
    w("")
    w("| scenario | body_safe | offset clearance off → on [m] | body clearance off → on [m] | contacts offset / body off → on | escape steps | conflict steps (off) | longest stall off → on [s] | true ASE off → on [m²] | verdict |")
    w("|---|---|---|---|---|---|---|---|---|---|")
    for name, body_safe, a, b in clearance_rows:
        same = all(a[k] == b[k] for k in ("ase", "tec", "min_clearance_offset", "min_clearance_body", "final_error"))

        def keeps(kind):
            return b[f"min_clearance_{kind}"] >= a[f"min_clearance_{kind}"] or b[f"{kind}_collisions"] == 0
        verdict = "identical" if same else ("no loss" if keeps("offset") and keeps("body") else
                                            ("offset kept; body touches (paper radius)" if keeps("offset") else "LOSS"))
        w(f"| {name} | {str(body_safe).lower()} | {g(a['min_clearance_offset'])} → {g(b['min_clearance_offset'])} | "
          f"{g(a['min_clearance_body'])} → {g(b['min_clearance_body'])} | {int(a['offset_collisions'])} / "
          f"{int(a['body_collisions'])} → {int(b['offset_collisions'])} / {int(b['body_collisions'])} | "
          f"{int(b['escape_steps'])} | {int(a['conflict_steps'])} | {g(a['longest_stall_s'])} → {g(b['longest_stall_s'])} | "
          f"{g(a['true_ase'])} → {g(b['true_ase'])} | {verdict} |")
    w("")
    w("Where nothing conflicts the escape term is exactly zero and the run is bit-identical (tested:")
    w("`ShippedScenarios.EscapeChangesNothingWithoutConflict` moves every obstacle away and compares all figures).")
    w("With the paper's radius (`body_safe: false`, the files of 5.1 and 5.2) the law protects only the disk around p_r;")
    w("the body already touches without the escape, and the escape's turns around the disks can make the body's")
    w("contacts deeper — see the rows above. With `body_safe: true` no body contact occurs with or without it.")
    w("")
    w("The same over randomised variants (`--monte-carlo 50 --seed 1`: obstacles shifted within 0.3 m, start within")
    w("0.3 m and ±0.5 rad), escape off → on:")
    w("")
    w("| scenario | body_safe | runs with offset contact | runs with body contact | worst offset clearance [m] | worst body clearance [m] | runs with a stall > 0.5 s | longest stall [s] | mean true ASE [m²] |")
    w("|---|---|---|---|---|---|---|---|---|")
    for name, body_safe, a, b in mc_rows:
        w(f"| {name} | {body_safe} | {a['runs_with_offset_collision']} → {b['runs_with_offset_collision']} | "
          f"{a['runs_with_body_collision']} → {b['runs_with_body_collision']} | {g(a['worst_min_clearance_offset'])} → "
          f"{g(b['worst_min_clearance_offset'])} | {g(a['worst_min_clearance_body'])} → {g(b['worst_min_clearance_body'])} | "
          f"{a['runs_with_stall_over_0_5s']} → {b['runs_with_stall_over_0_5s']} | {g(a['worst_stall_s'])} → "
          f"{g(b['worst_stall_s'])} | {g(a['mean_true_ase'])} → {g(b['mean_true_ase'])} |")
    w("")
    worse = sorted({f"{n} (body_safe {b})" for n, b, a, c in mc_rows if c["mean_true_ase"] > a["mean_true_ase"]})
    flips = {n: int(b["side_flips"]) for n, _, a, b in clearance_rows}
    w("The stalls the escape leaves on experiment_5_3's variants are waits, not deadlocks: its target drives *through*")
    w("the virtual square, and while the target is inside the square or its band p_r cannot follow and shadows it")
    w("from the boundary with ‖e*‖ just above 0.2 m (inspected: variant 30, body_safe true).")
    w("")
    w("**Not solved: two-disk traps.** Where two disks leave a gap narrower than the effective diameter (some")
    w("paper_5_1 variants with the body-safe radius 2(R + r) = 1 m), the offset point wedges into the gap and both")
    w("laws stand there for tens of seconds (the long stalls above). The escape takes one rotational side for every")
    w("disk, which inside such a gap pushes in opposite directions along it, so it does not free the robot. Latching")
    w("the side harder made it worse (measured while choosing the margin: 12–21 trapped runs of 50 instead of 4), so")
    w("the side may still flip near the disks of paper_5_1, where the target is tracked within millimetres and ê")
    w("swings as p_r enters a 16 mm band. A fix needs the obstacles treated as one cluster (pass around the union);")
    w("it is left open.")
    w("")
    w("Tracking cost: the escape raises the mean true ASE on " + (", ".join(worse) if worse else "none") + " and lowers")
    w("it elsewhere. Side flips per single run with the escape: " + ", ".join(f"{n} {k}" for n, k in flips.items()) +
      ". Where the target drives through a row of disks at 0.35–0.5 m/s (paper_5_1) the latched side is re-chosen at")
    w("every disk and sometimes flipped; why that costs more tracking than the paper law's wait-and-back-off has not")
    w("been analysed further: an open point, not a claim.")
    w("")
    w("## 2. Moving obstacles (`moving_obstacles`)")
    w("")
    w("Derivation (core/avoidance.h): with n_j the outward normal and a_j = max(0, v_jᵀn_j) the speed at which")
    w("obstacle j approaches p_r, the term becomes [1/d_j − 1/δ_j](p_r − p_j) + a_j n_j with δ_j = δ + a_j·horizon.")
    w("In the obstacle's frame the distance changes at n_jᵀ(ṗ_r − v_j); the feed-forward a_j n_j (k_o = 1) cancels")
    w("the approach so the static barrier argument of (10) holds again, and the wider band starts the push `horizon`")
    w("seconds of approach earlier. Static or receding obstacles give exactly (10). The simulator gives the controller")
    w("the true velocities (on the robot: core/obstacle_tracker.h from the laser).")
    w("")
    w(f"`config/scenarios/crossing_obstacles.yaml`, Monte Carlo of {MC_RUNS} runs (seed 1): the experiment's robot")
    w("(v̄ = 0.3 m/s, ω̄ = 0.8 rad/s) follows a target on a straight line at 0.15 m/s; four people (0.25 m disks)")
    w("cross the line, each re-drawn per run with a speed uniform in [0, 0.3 m/s] (up to the robot's own top speed),")
    w("its direction kept and re-timed to reach its encounter point (shifted uniformly within 0.3 m) when the target")
    w("does; the initial pose is shifted within 0.3 m and ±0.5 rad.")
    w("")
    w("| body_safe | avoidance | runs with body contact per 100 | body contact episodes | runs with offset contact per 100 | worst body clearance [m] | worst offset clearance [m] | mean true ASE [m²] |")
    w("|---|---|---|---|---|---|---|---|")
    for body_safe, label, j in batches:
        per100 = 100.0 / j["runs"]
        w(f"| {body_safe} | {label} | {g(j['runs_with_body_collision'] * per100)} | {j['body_collision_episodes']} | "
          f"{g(j['runs_with_offset_collision'] * per100)} | {g(j['worst_min_clearance_body'])} | "
          f"{g(j['worst_min_clearance_offset'])} | {g(j['mean_true_ase'])} |")
    w("")
    w("A contact is counted whoever causes it: a person walking into a robot that cannot get away at v̄ counts too.")
    w("")
    w("## 3. Delayed and slow measurements (`predict_target`, `compensate_pose_age`)")
    w("")
    w("`predict_target`: p_d = latest sample + v̂·(t − stamp) (v̂ from the paper's estimator, run on the stamps).")
    w("`compensate_pose_age`: the pose sample is moved from its stamp to t by replaying the commands applied meanwhile")
    w("(each over the interval it was held; exact for the unicycle, what odometry gives on the robot; at most")
    w("`max_prediction` = 0.5 s). It first used only the last command over the whole age, which is wrong as soon as")
    w("the age spans several control periods: on this scenario it made the error *worse* than no compensation")
    w("(true ASE 2.1–3.4 m² against 0.9–3.1 at 100–300 ms); the replay is now in the core (tested exact to 1e-9).")
    w("")
    w("experiment_5_3 (20 Hz control, 1 cm noise), target and robot pose both sampled at 10 Hz and both `delay` late;")
    w("true ASE in m², mean of 5 noise seeds (min–max in the plot). The shipped file runs the paper law, whose error")
    w("on this path is dominated by the stall in front of the square (the target crosses it twice), so the same sweep")
    w("is repeated with the escape on, where the delay's own effect shows.")
    w("")
    for tangential in ("false", "true"):
        w(f"**tangential_avoidance {tangential}** (no delay and a continuous pose: {g(reference[tangential])} m²)")
        w("")
        w("| delay [ms] | " + " | ".join(mode for mode, _ in COMPENSATION) + " |")
        w("|---|" + "---|" * len(COMPENSATION))
        for d in DELAYS:
            w(f"| {1e3 * d:.0f} | " + " | ".join(g(statistics.mean(table[(tangential, mode, d)])) for mode, _ in COMPENSATION)
              + " |")
        w("")
    w("**Target delay alone** (robot pose fresh and continuous; tangential off): what prediction does by itself.")
    w("")
    w("| delay [ms] | none | predict_target |")
    w("|---|---|---|")
    for d in DELAYS:
        w(f"| {1e3 * d:.0f} | {g(statistics.mean(table[('target_only', 'none', d)]))} | "
          f"{g(statistics.mean(table[('target_only', 'predict_target', d)]))} |")
    w("")
    w("**Why prediction does not pay here: noise.** Target delay alone, robot pose fresh; true ASE [m²], mean of 5 seeds:")
    w("")
    w("| target samples | obstacles | 0 ms | 300 ms | 300 ms + predict_target | RMS ‖ṗ_d − v̂‖ [m/s] |")
    w("|---|---|---|---|---|---|")
    noise = table["noise"]
    for label in ("no noise", "1 cm noise"):
        for place in ("no obstacles", "with the square"):
            w(f"| {label} | {place} | {g(noise[(label, place, 0.0, 'false')], 4)} | {g(noise[(label, place, 0.3, 'false')], 4)} | "
              f"{g(noise[(label, place, 0.3, 'true')], 4)} | {g(noise[(label, place, 0.3, 'true', 'v')])} |")
    w("")
    w("Without noise the prediction removes the delay's cost almost entirely (it is exact for a constant-velocity")
    w("target: unit test `Prediction.ExactForAConstantVelocityTarget`); with 1 cm of noise at 10 Hz the paper")
    w("estimator's v̂ (ρ_o = 1 cm, as large as the noise) is off by the RMS shown — the order of the target's")
    w("0.15 m/s — and v̂·age adds about as much error as it removes. Predicting with the Kalman or finite-difference baselines'")
    w("velocity instead did no better (tried by hand in a modified build, not kept: the controller predicts with the")
    w("paper estimator's v̂).")
    w("")
    w("Reading: what hurts is the *robot pose's* age — a delayed feedback of the robot's own motion — and replaying")
    w("the commands removes almost all of it (at 300 ms the error stays within a few per cent of the undelayed run).")
    w("The target's age matters little at 0.15 m/s (300 ms = 4.5 cm), and predicting it with the paper estimator's v̂")
    w("(differentiated 10 Hz samples with 1 cm noise) brings no reliable gain: v̂·age adds the estimator's noise.")
    w("")
    w("![ASE against delay](figures/beyond_paper/delay_ase.png)")
    w("")
    with open(path, "w") as f:
        f.write("\n".join(L) + "\n")


def summary_lines(saddle_res, batches, delay_res):
    """A few lines for the 'Beyond the paper' section of results.md."""
    exact, _, _ = saddle_res
    table, _ = delay_res
    off, on = exact["false"], exact["true"]
    lines = [
        f"- Deadlock (saddle_line): longest stall {g(off['longest_stall_s'])} s → {g(on['longest_stall_s'])} s, peak ‖e*‖ "
        f"{g(off['max_true_error'])} m → {g(on['max_true_error'])} m with `tangential_avoidance`.",
    ]
    per = {(b, label): j for b, label, j in batches}
    for b in ("false", "true"):
        a, m = per[(b, "paper (10)")], per[(b, "moving_obstacles")]
        lines.append(f"- Crossing people, {MC_RUNS} Monte Carlo runs, body_safe {b}: runs with body contact "
                     f"{a['runs_with_body_collision']} → {m['runs_with_body_collision']}, with offset contact "
                     f"{a['runs_with_offset_collision']} → {m['runs_with_offset_collision']} with `moving_obstacles`.")
    mean = {k: statistics.mean(v) for k, v in table.items() if isinstance(v, list)}
    lines.append("- experiment_5_3 with target and pose 300 ms late at 10 Hz: true ASE "
                 f"{g(mean[('false', 'none', 0.3)])} → {g(mean[('false', 'both', 0.3)])} m² with `predict_target` + "
                 "`compensate_pose_age` (" + ", ".join(f"{1e3 * d:.0f} ms: {g(mean[('false', 'none', d)])} → "
                                                     f"{g(mean[('false', 'both', d)])}" for d in DELAYS[:-1]) + ").")
    return lines


def main(sim, out_root, docs):
    figs = os.path.join(docs, "figures", "beyond_paper")
    os.makedirs(figs, exist_ok=True)
    os.makedirs(os.path.join(out_root, "beyond"), exist_ok=True)
    saddle_res = saddle(sim, out_root, figs)
    clearance_rows = clearance(sim, out_root)
    mc_rows = clearance_mc(sim, out_root)
    batches = moving(sim, out_root)
    delay_res = delay(sim, out_root, figs)
    write(os.path.join(docs, "beyond_paper.md"), saddle_res, clearance_rows, mc_rows, batches, delay_res)
    print(f"wrote {os.path.join(docs, 'beyond_paper.md')}")
    return summary_lines(saddle_res, batches, delay_res)


if __name__ == "__main__":
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--sim", required=True)
    parser.add_argument("--out", default=os.path.join(ROOT, "out", "reproduce"))
    parser.add_argument("--docs", default=os.path.join(ROOT, "docs"))
    args = parser.parse_args()
    for line in main(os.path.abspath(args.sim), os.path.abspath(args.out), os.path.abspath(args.docs)):
        print(line)
