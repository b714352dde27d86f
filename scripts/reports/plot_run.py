#!/usr/bin/python3
"""Plots one simulator run as the paper's Figures 3-8.

Usage: /usr/bin/python3 scripts/reports/plot_run.py DIR/trajectory.csv [--out DIR] [--dpi N]

Reads the CSV written by amigobot_sim and, when present, metrics.json beside it (obstacles,
diamond limits, radii). Writes fig3_xy.png, fig4_xy_time.png, fig5_error_rho.png,
fig6_commands.png, fig7_diamond.png, fig8_estimator.png next to the CSV (or into --out).
"""
import argparse
import csv
import json
import os
import sys
import textwrap

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402


def load(csv_path):
    with open(csv_path, newline="") as f:
        reader = csv.reader(f)
        header = next(reader)
        rows = [[float(x) for x in row] for row in reader if row]
    if not rows:
        sys.exit(f"plot_run.py: {csv_path}: no rows")
    data = np.array(rows)
    return {name: data[:, i] for i, name in enumerate(header)}


def load_meta(csv_path):
    path = os.path.join(os.path.dirname(os.path.abspath(csv_path)), "metrics.json")
    if not os.path.exists(path):
        return {}
    with open(path) as f:
        return json.load(f).get("scenario", {})


def titled(ax, text):
    """Long run names wrap instead of being cut at the figure's edge."""
    ax.set_title(textwrap.fill(text, 70), fontsize=9)


def offset_point(d):
    """The true offset point when the CSV has it (older recorded runs left it zero)."""
    if "p_r_true_x" in d and np.any(d["p_r_true_x"] != 0) or "p_r_true_y" in d and np.any(d["p_r_true_y"] != 0):
        return d["p_r_true_x"], d["p_r_true_y"], "offset point $p_r$ (true)"
    return d["p_r_x"], d["p_r_y"], "offset point $p_r$ (controller)"


def moving_average(t, x, window):
    """Centred moving average over `window` seconds (samples need not be even)."""
    out = np.empty_like(x)
    lo = np.searchsorted(t, t - window / 2, side="left")
    hi = np.searchsorted(t, t + window / 2, side="right")
    csum = np.concatenate([[0.0], np.cumsum(x)])
    out[:] = (csum[hi] - csum[lo]) / np.maximum(hi - lo, 1)
    return out


def save(fig, out_dir, name, dpi):
    fig.tight_layout()
    fig.savefig(os.path.join(out_dir, name), dpi=dpi)
    plt.close(fig)


def fig3_xy(d, meta, out_dir, dpi, title):
    fig, ax = plt.subplots(figsize=(6, 6))
    t_end = d["t"][-1]
    worst = int(np.argmin(d["clearance_body"]))
    for a, b in meta.get("walls", []):  # a recorded run's room (world file)
        ax.plot([a[0], b[0]], [a[1], b[1]], "-", color="0.3", lw=2.0)
    for points in meta.get("polygons", []):
        ax.add_patch(plt.Polygon(points, closed=True, color="0.55", alpha=0.6))
    for obs in meta.get("obstacles", []):
        c, r, v = obs["center"], obs["radius"], obs.get("velocity", [0, 0])
        moving = any(abs(x) > 0 for x in v)
        ax.add_patch(plt.Circle(c, r, color="0.5", alpha=0.6))
        if moving:
            end = [c[0] + v[0] * t_end, c[1] + v[1] * t_end]
            ax.add_patch(plt.Circle(end, r, color="0.5", alpha=0.25))
            ax.plot([c[0], end[0]], [c[1], end[1]], ":", color="0.5")
            at = [c[0] + v[0] * d["t"][worst], c[1] + v[1] * d["t"][worst]]  # where it was at the closest call
            ax.add_patch(plt.Circle(at, r, fill=False, color="0.3", ls="--", lw=0.8))
    ax.plot(d["p_d_x"], d["p_d_y"], "g-", lw=1.2, label="reference $p_d$")
    ax.plot(d["x"], d["y"], "r-", lw=1.0, label="robot centre $p$")
    # The true offset point (p_r_x is the controller's belief, late when the pose is).
    p_r_x, p_r_y, p_r_label = offset_point(d)
    ax.plot(p_r_x, p_r_y, "b--", lw=0.6, label=p_r_label)
    radius = meta.get("robot_radius")
    if radius:
        ax.add_patch(plt.Circle((d["x"][worst], d["y"][worst]), radius, fill=False, color="r", lw=0.8,
                                label=f"body at min clearance ({d['clearance_body'][worst]:.3f} m)"))
    if any(any(abs(x) > 0 for x in o.get("velocity", [0, 0])) for o in meta.get("obstacles", [])):
        # Moving obstacles come from far away: frame the robot's path, not their whole walks.
        xs, ys = np.concatenate([d["x"], d["p_d_x"]]), np.concatenate([d["y"], d["p_d_y"]])
        ax.set_xlim(xs.min() - 1.5, xs.max() + 1.5)
        ax.set_ylim(ys.min() - 1.5, ys.max() + 1.5)
    ax.set_aspect("equal")
    ax.set_xlabel("x [m]")
    ax.set_ylabel("y [m]")
    titled(ax, f"Fig. 3: path — {title}")
    ax.legend(fontsize=7, loc="best")
    ax.grid(alpha=0.3)
    save(fig, out_dir, "fig3_xy.png", dpi)


def fig4_xy_time(d, out_dir, dpi, title):
    # The controller steers the offset point p_r (r ahead of the centre) onto the target: plotted
    # against the target it shows the tracking; the centre, r behind, would read as lag.
    p_r_x, p_r_y, p_r_label = offset_point(d)
    fig, axes = plt.subplots(2, 1, figsize=(7, 5), sharex=True)
    for ax, axis, p_r in zip(axes, "xy", (p_r_x, p_r_y)):
        ax.plot(d["t"], d[f"p_d_{axis}"], "g-", label=f"${axis}_d$ target")
        ax.plot(d["t"], p_r, "b-", lw=0.9, label=f"${axis}$ of the {p_r_label}")
        ax.plot(d["t"], d[axis], color="0.55", ls=":", lw=0.9, label=f"${axis}$ of the robot's centre (r behind $p_r$)")
        ax.set_ylabel(f"position {axis} [m]")
        ax.legend(fontsize=7)
        ax.grid(alpha=0.3)
    axes[-1].set_xlabel("t [s]")
    titled(axes[0], f"Fig. 4: target and offset point against time — {title}")
    save(fig, out_dir, "fig4_xy_time.png", dpi)


def fig5_error(d, meta, out_dir, dpi, title):
    fig, ax = plt.subplots(figsize=(7, 3.5))
    ax.plot(d["t"], d["e_norm"], "r-", lw=0.9, label=r"$\|e\|$ (controller)")
    if "p_r_true_x" in d and np.any(d["p_r_true_x"] != 0):
        true_e = np.hypot(d["p_d_x"] - d["p_r_true_x"], d["p_d_y"] - d["p_r_true_y"])
        # A recorded step without a controller output (stale input) has no target: a gap, not a spike.
        true_e[(d["p_d_x"] == 0) & (d["p_d_y"] == 0) & (d["e_norm"] == 0)] = np.nan
        ax.plot(d["t"], true_e, color="tab:orange", lw=0.6, label=r"$\|e^*\|$ (true offset point)")
    if np.any(d["rho"] > 0):
        ax.plot(d["t"], d["rho"], "k-", lw=1.0, label=r"$\rho(t)$")
    if meta.get("rho_inf"):
        ax.axhline(meta["rho_inf"], color="0.4", ls=":", lw=0.8, label=r"$\rho_\infty$")
    ax.set_xlabel("t [s]")
    ax.set_ylabel(r"error $\|e\|$, bound $\rho$ [m]")
    titled(ax, f"Fig. 5: tracking error against the performance function — {title}")
    ax.legend(fontsize=7)
    ax.grid(alpha=0.3)
    save(fig, out_dir, "fig5_error_rho.png", dpi)


def fig6_commands(d, meta, out_dir, dpi, title):
    # v_d, omega_d are the law's output before the diamond scales it: they may lie far outside
    # U; the applied v, omega are inside. The dashed lines are the diamond's vertices (the
    # largest |v| with omega = 0 and the largest |omega| with v = 0).
    limits = (meta.get("v_max"), meta.get("w_max"))
    fig, axes = plt.subplots(2, 1, figsize=(7, 5), sharex=True)
    for ax, (desired, applied, symbol, unit_label), limit in zip(
            axes, (("v_d", "v", "v", "forward speed v [m/s]"), ("omega_d", "omega", r"\omega", r"turn rate $\omega$ [rad/s]")),
            limits):
        ax.plot(d["t"], d[desired], "c-", lw=0.7, label=f"${symbol}_d$ desired (before saturation)")
        ax.plot(d["t"], d[applied], "b-", lw=0.9, label=f"${symbol}$ applied (inside the diamond)")
        if limit:
            ax.axhline(limit, color="k", ls="--", lw=0.8, label=f"diamond vertex $\\pm${limit:g}")
            ax.axhline(-limit, color="k", ls="--", lw=0.8)
        ax.set_ylabel(unit_label)
        ax.legend(fontsize=7)
        ax.grid(alpha=0.3)
    axes[-1].set_xlabel("t [s]")
    titled(axes[0], f"Fig. 6: desired (before saturation) and applied commands — {title}")
    save(fig, out_dir, "fig6_commands.png", dpi)


def fig7_diamond(d, meta, out_dir, dpi, title):
    v_max = meta.get("v_max") or float(np.max(np.abs(d["v"])))
    w_max = meta.get("w_max") or float(np.max(np.abs(d["omega"])))
    fig, ax = plt.subplots(figsize=(5, 5))
    ax.fill([v_max, 0, -v_max, 0], [0, w_max, 0, -w_max], color="tab:blue", alpha=0.15, label="U")
    ax.plot(d["v"], d["omega"], "r.", ms=1.5, label="applied $u$")
    ax.set_xlabel("forward speed v [m/s]")
    ax.set_ylabel(r"turn rate $\omega$ [rad/s]")
    titled(ax, f"Fig. 7: u inside the diamond U — {title}")
    ax.legend(fontsize=7)
    ax.grid(alpha=0.3)
    save(fig, out_dir, "fig7_diamond.png", dpi)


def fig8_estimator(d, meta, out_dir, dpi, title):
    # The raw error is drawn light (a sampled target makes it jitter), its 1 s average dark.
    truth = meta.get("velocity_truth", "the reference's own velocity")
    fig, axes = plt.subplots(2, 1, figsize=(7, 5.5), sharex=True)
    for ax, axis in zip(axes, "xy"):
        err = d[f"v_d_{axis}"] - d[f"v_hat_{axis}"]
        ax.plot(d["t"], err, color="m", alpha=0.3, lw=0.5, label=rf"$\dot{{{axis}}}_d - \hat v_{axis}$")
        ax.plot(d["t"], moving_average(d["t"], err, 1.0), "k-", lw=0.9, label="1 s average")
        ax.set_ylabel(f"velocity error {axis} [m/s]")
        ax.legend(fontsize=7, loc="upper right")
        ax.grid(alpha=0.3)
        settled = d["t"] > 0.5
        if np.any(settled):
            lim = max(1e-3, 1.2 * float(np.percentile(np.abs(err[settled]), 99)))
            ax.set_ylim(-lim, lim)
    axes[-1].set_xlabel("t [s]")
    titled(axes[0], f"Fig. 8: velocity estimation error ({meta.get('estimator', 'paper')} estimator; truth: {truth}; "
                    f"t < 0.5 s and the top 1 % clipped) — {title}")
    save(fig, out_dir, "fig8_estimator.png", dpi)


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("csv", help="trajectory.csv written by amigobot_sim")
    parser.add_argument("--out", help="folder for the PNGs (default: beside the CSV)")
    parser.add_argument("--dpi", type=int, default=90)
    args = parser.parse_args()
    if not os.path.exists(args.csv):
        sys.exit(f"plot_run.py: {args.csv}: no such file")
    d = load(args.csv)
    meta = load_meta(args.csv)
    out_dir = args.out or os.path.dirname(os.path.abspath(args.csv))
    os.makedirs(out_dir, exist_ok=True)
    title = f"{meta.get('name', os.path.basename(out_dir))} [{meta.get('variant', '?')}]"
    fig3_xy(d, meta, out_dir, args.dpi, title)
    fig4_xy_time(d, out_dir, args.dpi, title)
    fig5_error(d, meta, out_dir, args.dpi, title)
    fig6_commands(d, meta, out_dir, args.dpi, title)
    fig7_diamond(d, meta, out_dir, args.dpi, title)
    fig8_estimator(d, meta, out_dir, args.dpi, title)
    print(f"plot_run.py: 6 figures in {out_dir}")


if __name__ == "__main__":
    main()
