"""The measurements of docs/beyond_paper.md: amigobot_sim runs of each switch beyond the paper, on
against off, and their figures (docs/figures/beyond_paper/*.png). The page itself: beyond_paper.py."""
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
SHIPPED = ["paper_5_1", "paper_5_2_rose", "experiment_5_3", "saddle_line", "crossing_obstacles", "ring", "pair_cluster"]
# Static obstacles: single disks, pairs, rings, clusters, walls of disks.
STATIC = ["paper_5_1", "paper_5_2_rose", "experiment_5_3", "saddle_line", "ring", "pair_cluster"]
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
    for name in STATIC:
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
