#!/usr/bin/python3
"""Reproduces the paper's Section 5 with the offline simulator and writes docs/results.md.
Usage: scripts/reports/reproduce.py --sim PATH/amigobot_sim [--out out/reproduce] [--docs docs] (`make reproduce`). Runs the three shipped scenarios with the proposed law and every
baseline, the body-safe variant, fixed-step references for the variable step, Monte Carlo
batches and the speed benchmark; copies the proposed runs' figures to docs/figures/. Then the
measurements beyond the paper (scripts/reports/beyond_paper.py -> docs/beyond_paper.md).
"""
import argparse
import json
import os
import shutil
import subprocess
import sys
import tempfile

import beyond_paper
import clutter
import markdown
from law_winners import write_law_winners
import scenario_yaml

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
SCENARIOS = {
    "paper_5_1": "Section 5.1: spline among disks (our layout), Table 1, v̄ = ω̄ = 5",
    "paper_5_2_rose": "Section 5.2: rose curve, Table 1 with v̄ = ω̄ = 15, three disks on the curve (ours)",
    "experiment_5_3": "Section 5.3: real-robot gains, tele-operated target, square virtual obstacle, 10 Hz noisy delayed samples",
}
LAW_NAMES = {"paper": "proposed", "fixed_rho": "fixed ρ", "proportional": "proportional"}
BASELINES = [
    ("paper", []),
    ("fixed_rho", ["--variant", "fixed_rho"]),
    ("proportional", ["--variant", "proportional"]),
    ("mrpt_reactive", ["--variant", "mrpt_reactive"]),
    ("finite_difference", ["--estimator", "finite_difference"]),
    ("kalman", ["--estimator", "kalman"]),
    ("body_safe_true", ["--body-safe", "true"]),
    ("body_safe_false", ["--body-safe", "false"]),
]


def scenario_path(name):
    return os.path.join(ROOT, "config", "scenarios", name + ".yaml")


# make bench's fast settings of the rose (Makefile), checked by SimFidelity in test_sim_closed_loop.
SECOND_ORDER = ["--integrator", "second_order", "--control-period", "0.004", "--max-step", "0.01"]


def run(sim, name, label, args, out_root, plot=False):
    out = os.path.join(out_root, name, label)
    cmd = [sim, "--scenario", scenario_path(name), "--out", out] + args + ([] if plot else ["--no-plot"])
    print("+", " ".join(os.path.relpath(c, ROOT) if c.startswith(ROOT) else c for c in cmd), flush=True)
    subprocess.run(cmd, check=True, stdout=subprocess.DEVNULL)
    with open(os.path.join(out, "metrics.json")) as f:
        return json.load(f)


def monte_carlo(sim, name, n, seed, args, out_root, label):
    out = os.path.join(out_root, name, label)
    cmd = [sim, "--scenario", scenario_path(name), "--out", out, "--monte-carlo", str(n), "--seed", str(seed)] + args
    print("+", " ".join(cmd[1:]), flush=True)
    subprocess.run(cmd, check=True, stdout=subprocess.DEVNULL)
    with open(os.path.join(out, "monte_carlo.json")) as f:
        return json.load(f)


def benchmark(sim, name, args, n=30):
    with tempfile.TemporaryDirectory() as tmp:
        path = os.path.join(tmp, "benchmark.json")
        cmd = [sim, "--scenario", scenario_path(name) if not os.path.isabs(name) else name, "--benchmark", str(n),
               "--benchmark-json", path] + args
        subprocess.run(cmd, check=True, stdout=subprocess.DEVNULL)
        with open(path) as f:
            b = json.load(f)
    return b["steps"], float(round(b["realtime_factor_median"])), float(round(b["realtime_factor_best"]))


def f(x, digits=4):
    if x is None:
        return "—"
    if isinstance(x, int) or (isinstance(x, float) and x.is_integer() and abs(x) >= 1 and digits == 0):
        return str(int(x))
    return markdown.number(x, digits)


def ratio(a, b):
    return "—" if not b else f"{a / b:.3f}"


def no_obstacle_copy(name, out_root):
    """The rose without obstacles (for the speed figure of the free curve)."""
    return scenario_yaml.write_variant(scenario_path(name), os.path.join(out_root, name + "_no_obstacles.yaml"),
                                       lambda data: scenario_yaml.set_key(data, "obstacles", []))


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--sim", required=True)
    parser.add_argument("--out", default=os.path.join(ROOT, "out", "reproduce"))
    parser.add_argument("--docs", default=os.path.join(ROOT, "docs"))
    args = parser.parse_args()
    sim, out_root = os.path.abspath(args.sim), os.path.abspath(args.out)
    os.makedirs(out_root, exist_ok=True)
    plot = [sys.executable if sys.executable.startswith("/usr/bin") else "/usr/bin/python3",
            os.path.join(ROOT, "scripts", "reports", "plot_run.py")]

    results = {}
    for name in SCENARIOS:
        results[name] = {}
        for label, extra in BASELINES:
            results[name][label] = run(sim, name, label, extra, out_root)
        # Figures for the docs: proposed law, and the body-safe variant's path.
        fig_dir = os.path.join(args.docs, "figures", name)
        if os.path.isdir(fig_dir):
            shutil.rmtree(fig_dir)
        subprocess.run(plot + [os.path.join(out_root, name, "paper", "trajectory.csv"), "--out", fig_dir, "--dpi", "72"],
                       check=True, stdout=subprocess.DEVNULL)
        safe_dir = os.path.join(out_root, name, "body_safe_figs")
        subprocess.run(plot + [os.path.join(out_root, name, "body_safe_true", "trajectory.csv"), "--out", safe_dir,
                               "--dpi", "72"], check=True, stdout=subprocess.DEVNULL)
        shutil.copy(os.path.join(safe_dir, "fig3_xy.png"), os.path.join(fig_dir, "fig3_xy_body_safe.png"))

    # Step fidelity: the variable step against fixed steps.
    fidelity = {}
    # (label, arguments) rows after the scenario's own settings; the last one is each table's reference.
    def fixed(step, integrator="explicit"):
        label = f"fixed {float(step) * 1e3:g} ms" + (f", {integrator}" if integrator != "explicit" else "")
        return label, ["--max-step", "0", "--control-period", step, "--integrator", integrator]
    rose_rows = [("variable 4–10 ms, second_order", SECOND_ORDER), fixed("0.005", "second_order"),
                 fixed("0.002", "band_implicit"), fixed("0.001", "band_implicit"), fixed("0.001"), fixed("0.0005"),
                 fixed("0.0000625")]
    for name, extra_rows in [("paper_5_2_rose", rose_rows),
                             ("paper_5_1", [fixed("0.001"), fixed("0.0005"), fixed("0.000125")])]:
        rows = [("variable 0.5–5 ms (scenario)" if name == "paper_5_2_rose" else "variable (scenario)",
                 results[name]["paper"], benchmark(sim, name, []))]
        for label, step_args in extra_rows:
            slug = label.replace(" ", "_").replace(",", "").replace("–", "-")
            m = run(sim, name, slug, step_args + ["--log-period", "0.01"], out_root)
            slow = "0.0000625" in step_args or "0.000125" in step_args
            rows.append((label, m, benchmark(sim, name, step_args, 3 if slow else (50 if step_args is SECOND_ORDER else 10))))
        fidelity[name] = rows
    free_rose = no_obstacle_copy("paper_5_2_rose", out_root)
    speed_free = []
    for label, extra in [("variable, max step 20 ms", ["--max-step", "0.02"]), ("variable, max step 5 ms", []),
                         ("fixed 0.5 ms", ["--max-step", "0"])]:
        bench = benchmark(sim, free_rose, extra)
        out = os.path.join(out_root, "rose_no_obstacles", label.replace(" ", "_").replace(",", ""))
        subprocess.run([sim, "--scenario", free_rose, "--out", out, "--no-plot"] + extra, check=True,
                       stdout=subprocess.DEVNULL)
        with open(os.path.join(out, "metrics.json")) as f_in:
            speed_free.append((label, json.load(f_in), bench))

    mc = {
        "paper_5_1 (body_safe false)": monte_carlo(sim, "paper_5_1", 20, 1, ["--body-safe", "false"], out_root, "mc_false"),
        "paper_5_1 (body_safe true)": monte_carlo(sim, "paper_5_1", 20, 1, ["--body-safe", "true"], out_root, "mc_true"),
        "paper_5_2_rose (body_safe false)": monte_carlo(sim, "paper_5_2_rose", 50, 1, ["--body-safe", "false"], out_root,
                                                        "mc_false"),
        "paper_5_2_rose (body_safe true)": monte_carlo(sim, "paper_5_2_rose", 50, 1, ["--body-safe", "true"], out_root,
                                                       "mc_true"),
    }
    beyond = beyond_paper.main(sim, out_root, os.path.abspath(args.docs))
    clutter.main(sim, os.path.join(out_root, "clutter"), os.path.abspath(args.docs))  # docs/clutter.md
    write_results(os.path.join(args.docs, "results.md"), results, fidelity, speed_free, mc, beyond)
    print(f"wrote {os.path.join(args.docs, 'results.md')}")


def write_results(path, results, fidelity, speed_free, mc, beyond):
    w = markdown.Page()
    w("# Reproducing Section 5 of Trakas et al. (Sensors 2024)")
    w("")
    w("Generated by `make reproduce` (scripts/reports/reproduce.py) from the offline simulator `amigobot_sim`;")
    w("every number below comes from `out/reproduce/<scenario>/<run>/metrics.json`. Re-run to refresh.")
    w("Scenarios: `config/scenarios/`. The paper does not publish its 5.1 layout, its 5.2 obstacles or its")
    w("5.3 path: ours are designed in their spirit and say so in the files.")
    w("")
    w("## Metrics, precisely")
    w("")
    w("With e = p_d − p_r (target minus offset point), the state sampled at t_k and the command u_k = (v_k, ω_k)")
    w("held over [t_k, t_k + h_k) (zero-order hold; variable or fixed h_k), T = Σ h_k:")
    w("")
    w("- **ASE** = (1/T) Σ h_k ‖e_k‖² [m²] — time-average squared tracking error (left Riemann sum of (1/T)∫‖e‖²dt).")
    w("- **AAE** = (1/T) Σ h_k ‖e_k‖ [m] — time-average absolute (Euclidean) tracking error.")
    w("- **ISE** = Σ h_k ‖e_k‖² = T·ASE [m² s] and **IAE** = Σ h_k ‖e_k‖ = T·AAE [m s] — the integrals ∫‖e‖²dt and")
    w("  ∫‖e‖dt themselves (the paper's indices may be these; T is the same for every law of a scenario, so the ratios")
    w("  between laws are the same as for ASE and AAE).")
    w("- **TEC** = Σ h_k (v_k² + ω_k²) [m²/s and rad²/s added numerically] — control energy of the applied command.")
    w("- Clearances: offset = distance from the disk of radius R around p_r to the nearest obstacle surface (what")
    w("  the paper guarantees); body = the same for the disk of radius R around the centre p (the real robot).")
    w("  A *collision* is an episode: each time a clearance turns negative counts one.")
    w("- Diamond violations: steps with |v|/v̄ + |ω|/ω̄ > 1 + 1e-9. NaN count: steps with any non-finite value.")
    w("- Estimator error: time-RMS of ‖ṗ_d − v̂‖ over the run, and its maximum after t = 0.5 s (settled).")
    w("- Envelope widenings: steps where ‖e‖ ≥ max_error_ratio·ρ (0.9999 by default) and ρ had to be widened")
    w("  (docs/simulation.md: start/envelope rule). The continuous-time theory promises ‖e‖/ρ < 1 only; under a sustained")
    w("  conflict (13) settles at ξ* with ξ*·atanh ξ* = k_o/k_r (0.968 for the paper's k_r = 0.5), so the")
    w("  threshold must lie above ξ* (validated): then a widening means the discrete loop, not (13), held ρ.")
    w("")
    w("The paper's own ASE/AAE/TEC (its ref. [36]) are not available, and they cannot be mean‖e‖² and mean‖e‖ over")
    w("the same samples: its Table 2 has ASE = 0.67052 < AAE² = 0.7892, which Jensen's inequality forbids. Only the")
    w("*ratios* proposed/comparison (paper: ASE 0.882, AAE 0.942, TEC 0.941) are comparable with ours. Our ASE ≥ AAE²")
    w("holds by construction (tested). The paper's comparison scheme [35] is not reimplemented (its text is not")
    w("available); our baselines are our own (fixed rho, proportional feedback linearisation).")
    w("")
    rr = results["paper_5_2_rose"]
    w("## Findings in short")
    w("")
    ratios = [rr["paper"][k] / rr["proportional"][k] for k in ("ase", "aae", "tec")]
    verdict = ("the same direction as the paper's proposed / [35] (0.882, 0.942, 0.941)" if all(x < 1 for x in ratios)
               else "NOT all in the paper's direction (paper's proposed / [35]: 0.882, 0.942, 0.941)")
    w(f"- Rose (Section 5.2), proposed / proportional: ASE {ratios[0]:.3f}, AAE {ratios[1]:.3f}, TEC {ratios[2]:.3f} — "
      f"{verdict}.")
    fx = {n: int(results[n]["fixed_rho"]["envelope_widenings"]) for n in results}
    own = {n: int(results[n]["paper"]["envelope_widenings"]) for n in results}
    w("- Fixed ρ: with a truly fixed ρ, T(‖e‖/ρ) is undefined in every step counted under *envelope widenings*")
    w("  (" + ", ".join(f"{fx[n]} on {n}" for n in results) + "); the envelope rule rescues that baseline,")
    w("  which is why its ASE/AAE can look as good as the proposed law's. The proposed law with (13) needed")
    w("  widenings: " + ", ".join(f"{own[n]} on {n}" for n in results) + " (besides the start rule, each is a step")
    w("  the discrete loop left the envelope that (13) keeps in continuous time).")
    better = [n for n in results if results[n]["proportional"]["ase"] < results[n]["paper"]["ase"]]
    w("- The proportional baseline has the lower ASE on: " + (", ".join(better) if better else "none") +
      " (the scenario's gains; k_p = k_d/ρ_∞).")
    write_law_winners(results, LAW_NAMES, w)
    every = [m for r in results.values() for k, m in r.items() if k != "mrpt_reactive"]
    bad = sum(int(m["diamond_violations"]) + int(m["nan_count"]) for m in every)
    offset_hits = sum(int(m["offset_collisions"]) for m in every)
    body = [n for n in results if results[n]["body_safe_false"]["body_collisions"] > 0]
    w(f"- Over all {len(every)} runs: {bad} diamond violations or NaN steps, {offset_hits} offset-point collisions.")
    w("  With the paper's radius the body touched a disk on: " + (", ".join(body) if body else "none") +
      "; with `body_safe: true` on: " +
      (", ".join(n for n in results if results[n]["body_safe_true"]["body_collisions"] > 0) or "none") + ".")
    mr = {n: results[n]["mrpt_reactive"] for n in results}
    w("- MRPT's reactive navigator as a peer (proposed / MRPT, ASE): " +
      ", ".join(f"{n} {ratio(results[n]['paper']['ase'], mr[n]['ase'])}" for n in results) +
      "; its body touched a disk on: " + (", ".join(n for n in results if mr[n]["body_collisions"] > 0) or "none") +
      "; its diamond violations: " + str(sum(int(m["diamond_violations"]) for m in mr.values())) +
      " (every command saturated by (12)); longest stall: " +
      ", ".join(f"{n} {f(mr[n]['longest_stall_s'], 3)} s" for n in results) + ".")
    w("")
    w("## Table 2, extended: proposed law against each baseline")
    w("")
    w("Ratios are proposed / baseline (< 1: the proposed law is better). `fixed ρ` = (9)–(12) with ρ following the")
    w("prescribed decay only (no relaxation term in (13)); `proportional` = feedback linearisation at p_r with")
    w("u_r = v̂ + k_p e + k_o u_c, k_p = k_d/ρ_∞ (the proposed law's small-error stiffness), the same saturation.")
    w("`MRPT reactive` = a peer from outside the paper: MRPT 2.5's `CReactiveNavigationSystem` (TP-space PTGs alpha,")
    w("C forward and C backward of a differential drive, holonomic method ND, robot shape a 16-gon around the body disk)")
    w("re-targeted at the target every 50 ms (20 Hz), the disks seen as a 360-beam laser at the robot centre sees")
    w("them, every (v, ω) saturated by the same diamond (12); it drives the robot centre to the target and ends within")
    w("r of it (`sim_mrpt/reactive_law.h`). It protects its body shape, not the offset disk, so its *offset* contacts")
    w("below are not failures; its body clearance is the figure to compare. Scored like the others (e = p_d − p_r).")
    w("")
    for name, title in SCENARIOS.items():
        r = results[name]
        p, fx, pr = r["paper"], r["fixed_rho"], r["proportional"]
        w(f"### {name} — {title}")
        w("")
        mp = r["mrpt_reactive"]
        w("| index | proposed | fixed ρ | ratio | proportional | ratio | MRPT reactive | ratio |")
        w("|---|---|---|---|---|---|---|---|")
        for key, label in [("ase", "ASE [m²]"), ("aae", "AAE [m]"), ("ise", "ISE ∫‖e‖²dt [m² s]"),
                           ("iae", "IAE ∫‖e‖dt [m s]"), ("tec", "TEC"), ("longest_stall_s", "longest stall [s]")]:
            w(f"| {label} | {f(p[key])} | {f(fx[key])} | {ratio(p[key], fx[key])} | {f(pr[key])} | {ratio(p[key], pr[key])} | "
              f"{f(mp[key])} | {ratio(p[key], mp[key])} |")
        w("")
        w("| run | max ‖e‖/ρ | envelope widenings | min clearance offset [m] | min clearance body [m] | offset collisions | body collisions | diamond violations | NaN | saturated steps |")
        w("|---|---|---|---|---|---|---|---|---|---|")
        for label in ["paper", "fixed_rho", "proportional", "mrpt_reactive", "finite_difference", "kalman", "body_safe_true",
                      "body_safe_false"]:
            m = r[label]
            sc = m["scenario"]
            tag = f"{label} (body_safe {str(sc['body_safe']).lower()})" if not label.startswith("body_safe") else label
            ratio_txt = f(m["max_e_over_rho"], 3) if sc["variant"] in ("paper", "fixed_rho") else "— (no ρ)"
            w(f"| {tag} | {ratio_txt} | {int(m['envelope_widenings'])} | {f(m['min_clearance_offset'])} | "
              f"{f(m['min_clearance_body'])} | {int(m['offset_collisions'])} | {int(m['body_collisions'])} | "
              f"{int(m['diamond_violations'])} | {int(m['nan_count'])} | {int(m['saturated_steps'])} |")
        w("")
        w("Velocity estimators (same law):")
        w("")
        w("| estimator | RMS ‖ṗ_d − v̂‖ [m/s] | max after 0.5 s [m/s] | ASE [m²] | AAE [m] | ISE [m² s] | IAE [m s] | TEC |")
        w("|---|---|---|---|---|---|---|---|")
        for label, title_e in [("paper", "paper (3)–(4)"), ("finite_difference", "finite differences + low-pass τ = 0.05 s"),
                               ("kalman", "constant-velocity Kalman")]:
            m = r[label]
            w(f"| {title_e} | {f(m['estimator_rms_error'])} | {f(m['estimator_max_error_settled'])} | {f(m['ase'])} | "
              f"{f(m['aae'])} | {f(m['ise'])} | {f(m['iae'])} | {f(m['tec'])} |")
        w("")
        w(f"Figures (proposed law): [Fig. 3 path](figures/{name}/fig3_xy.png) · "
          f"[Fig. 3 with body_safe](figures/{name}/fig3_xy_body_safe.png) · [Fig. 4 x, y](figures/{name}/fig4_xy_time.png) · "
          f"[Fig. 5 ‖e‖ and ρ](figures/{name}/fig5_error_rho.png) · [Fig. 6 v, ω](figures/{name}/fig6_commands.png) · "
          f"[Fig. 7 diamond](figures/{name}/fig7_diamond.png) · [Fig. 8 estimator](figures/{name}/fig8_estimator.png)")
        w("")
        w(f"![{name} path](figures/{name}/fig3_xy.png) ![{name} error](figures/{name}/fig5_error_rho.png)")
        w("")
    w("## Safety finding: the paper's radius protects the offset point, not the body")
    w("")
    w("The paper's repulsion (10) keeps the disk of radius R around the *offset point* p_r clear. The body is the")
    w("disk of radius R around the centre p, 0.3 m behind p_r; when the robot turns or backs near a disk the body")
    w("can touch it although p_r stays clear. With `body_safe: true` (effective radius R + r in (10)) the disk of")
    w("radius R + r around p_r, which contains the body, is kept clear.")
    w("")
    w("| scenario | body_safe | min clearance offset [m] | min clearance body [m] | body collisions | body contact time [s] | ASE [m²] |")
    w("|---|---|---|---|---|---|---|")
    for name in SCENARIOS:
        for label in ["body_safe_false", "body_safe_true"]:
            m = results[name][label]
            w(f"| {name} | {label[10:]} | {f(m['min_clearance_offset'])} | {f(m['min_clearance_body'])} | "
              f"{int(m['body_collisions'])} | {f(m['body_contact_time_s'])} | {f(m['ase'])} |")
    w("")
    w("Monte Carlo (obstacles moved uniformly within 0.3 m, initial position within 0.3 m, heading ±0.5 rad;")
    w("`amigobot_sim --monte-carlo N --seed 1`):")
    w("")
    w("| batch | runs | runs with body collision | runs with offset collision | runs with diamond violation | runs with NaN | worst body clearance [m] | worst offset clearance [m] | worst max ‖e‖/ρ | envelope widenings (runs) |")
    w("|---|---|---|---|---|---|---|---|---|---|")
    for label, j in mc.items():
        w(f"| {label} | {j['runs']} | {j['runs_with_body_collision']} | {j['runs_with_offset_collision']} | "
          f"{j['runs_with_diamond_violation']} | {j['runs_with_nan']} | {f(j['worst_min_clearance_body'])} | "
          f"{f(j['worst_min_clearance_offset'])} | {f(j['worst_max_e_over_rho'], 3)} | "
          f"{j['envelope_widenings']} ({j['runs_with_envelope_widening']}) |")
    w("")
    rose = fidelity["paper_5_2_rose"]
    free = speed_free
    w("## Time step: speed and fidelity")
    w("")
    explicit_1ms = next(row for row in rose if row[0] == "fixed 1 ms")
    fast = rose[1]
    ref = rose[-1][1]

    def off(m, key):
        return f"{100 * (m[key] - ref[key]) / ref[key]:+.1f} %"
    met = "met" if fast[2][1] >= 1e4 else f"met at the best run ({fast[2][2]:.0f}×), not at the median"
    w(f"**10⁴ × real time with faithful results: {met}.** With `--integrator second_order --control-period 0.004")
    w(f"--max-step 0.01` (`make bench`) the rose with its three disks takes {fast[2][0]} steps and runs at {fast[2][1]:.0f}× real")
    w(f"time (median of 50; best {fast[2][2]:.0f}×) with ASE {off(fast[1], 'ase')}, AAE {off(fast[1], 'aae')}, TEC {off(fast[1], 'tec')},")
    w(f"max ‖e‖/ρ {fast[1]['max_e_over_rho']:.3f} (reference {ref['max_e_over_rho']:.3f}), the same clearances to 0.1 mm and the same")
    w("contacts as a fixed 62.5 µs step (the reference below; test_sim_closed_loop: SimFidelity asserts 2 %, 0.01 and")
    w(f"1 mm). The scenario's own explicit settings: {rose[0][2][1]:.0f}×, within 3 %. The obstacle-free rose reaches")
    w(f"{free[0][2][1]:.0f}× with explicit 20 ms steps, but {100 * (free[0][1]['aae'] - free[-1][1]['aae']) / free[-1][1]['aae']:+.0f} % off on AAE.")
    w("")
    w("How. The explicit loop is first order in the step and stiff in the bands: at 1 ms the repulsion (10),")
    w(f"stiff as 1/margin, chatters along the 16 mm band ({100 * (explicit_1ms[1]['tec'] - ref['tec']) / ref['tec']:+.0f} % control energy), so ≈ 2200 of its")
    w("steps had to be 0.5 ms. Three pieces, each measured on its own:")
    w("")
    w("- *band_implicit* (core/law/band_implicit.h): the repulsion of the nearest reachable obstacle is evaluated")
    w("  backward-Euler, at the clearance the held command reaches at the end of the step (exact unicycle arc,")
    w("  a scalar secant solve). Long steps neither chatter nor enter a disk (rows \"band_implicit\"), but the")
    w("  error stays ≈ proportional to the step: error × steps ≈ constant (≈ 3 % at ≈ 3700 steps).")
    w("- *Midpoint commands*: each command is computed at the middle of the step it is held over (pose predicted")
    w("  with the previous command, target sampled there): the held command becomes second order.")
    w("- *BDF2 estimator* (estimator.h, `bdf2`, offline only): backward Euler's v̂ lags the target by half a step,")
    w("  about half of the error at 5 ms (measured by feeding the true velocity); BDF2 keeps the bounds by")
    w("  construction and is L-stable too.")
    w("")
    w("*second_order* is all three. The step cost fell meanwhile (`perf`): the estimator's implicit solve takes")
    w("Halley steps (g'' is free once exp(2η) is known) from the quadratic through the last three values, stops at")
    w("a step below 1e-4 min(η, 1) (root to ~1e-12; ≈ 1.5 evaluations and 1.4 `exp` per solve), and takes tanh")
    w("from its last evaluation; one sin/cos of the heading per closed-loop step (p_r, the midpoint prediction, the")
    w("band and the arc share it) and one of the rose for both of its samples; small turns by series. The robot's")
    w("controller is unchanged: the implicit band, the midpoint evaluation and BDF2 are switched on by the")
    w("simulator only. Wall-clock figures on 2 cores shared with other builds vary by ±20 % between runs.")
    w("")
    w("The closed loop holds each command over its step (a sampled controller). Far from obstacles and with")
    w("‖e‖/ρ ≤ 0.5 the step grows to `max_step`; it falls to the fine `control_period` when ‖e‖/ρ → 0.9 and")
    w("wherever a longer step could carry the offset point or the body through a detection band (distance over")
    w("the diamond's speed bound max(v̄, r ω̄)); inside a band only the fine step is used (core/step_size.h).")
    w("With band_implicit the bands need no short step: only the ‖e‖/ρ rule shortens it.")
    w("Differences are relative to the finest fixed step of each table.")
    w("")
    for name, rows in fidelity.items():
        ref = rows[-1][1]
        w(f"### {name}")
        w("")
        w("| step | steps | real-time factor (median) | ASE | ΔASE | AAE | ΔAAE | TEC | ΔTEC | min clearance offset [m] | min clearance body [m] |")
        w("|---|---|---|---|---|---|---|---|---|---|---|")
        for label, m, (steps, median, best) in rows:
            def d(key):
                return f"{100 * (m[key] - ref[key]) / ref[key]:+.1f} %"
            w(f"| {label} | {steps} | {median:.0f}× | {f(m['ase'])} | {d('ase')} | {f(m['aae'])} | {d('aae')} | "
              f"{f(m['tec'])} | {d('tec')} | {f(m['min_clearance_offset'])} | {f(m['min_clearance_body'])} |")
        w("")
    w("### The rose without obstacles")
    w("")
    ref = speed_free[-1][1]
    w("| step | steps | real-time factor (median) | ASE | ΔASE | AAE | ΔAAE |")
    w("|---|---|---|---|---|---|---|")
    for label, m, (steps, median, best) in speed_free:
        w(f"| {label} | {steps} | {median:.0f}× | {f(m['ase'])} | {100 * (m['ase'] - ref['ase']) / ref['ase']:+.1f} % | "
          f"{f(m['aae'])} | {100 * (m['aae'] - ref['aae']) / ref['aae']:+.1f} % |")
    w("")
    w("Real-time factors are wall-clock figures of this machine (2 shared cores), the closed loop alone (CSV")
    w("written afterwards); `make bench` prints them again. See the report text above the tables for what they mean.")
    for line in ["", "## Beyond the paper", "",
                 "The switches beyond the paper (all off above): tangential escape from the saddle, moving obstacles, "
                 "delayed measurements.", "Definitions, every table and the plots: [beyond_paper.md](beyond_paper.md) "
                 "(scripts/reports/beyond_paper.py). In short:", ""] + beyond + ["", "## Clutter", "",
                 "Twelve scene classes (pillar, U groups, gap, group threshold, corner, fast target, saddle, ring, doorway,",
                 "moving obstacle), 50 Monte Carlo variants per class and law: [clutter.md](clutter.md) (`make clutter`)."]:
        w(line)
    w.save(path)


if __name__ == "__main__":
    main()
