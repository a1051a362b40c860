#!/usr/bin/env python3
"""Charts a `vox bench sweep` CSV: per scene, error (MAE and MSE, log) against the cost per frame,
one marker style per method, the Pareto front joined. Sweeps with the front's verdicts (columns
front_mae, front_mse: metrics/pareto_front.h) join every point no other point surely dominates and
ring the members whose place is not resolved at the sweep's budget; older sweeps join the front of
the medians (no other point both cheaper and more accurate). MAE shows bias best, MSE punishes fireflies: both are drawn, and the mean
ratio (mean of non-emitting pixels over the reference's) shows bias at a glance.

The cost (sweeps with the cost model: cost_ms) is the counted work at per-kind costs fitted to the
sweep's interleaved rounds, in ms of the scene's first point; its horizontal bar is the rounds'
interval, the vertical bar the errors' min-max over the seeds. Older sweeps (no cost_ms) are drawn
against their median GPU time without bars.

Rows measured against the multi-bounce reference (reference_bounces > 0: the indirect-light
series none / cache-K / path tracer) get their own chart per scene: their errors are against
another image than the direct-light points', so one axis would compare unlike things.
Usage: plot_sweep.py sweep.csv OUTDIR  ->  OUTDIR/sweep_<scene>.png, OUTDIR/sweep_indirect_<scene>.png"""
import csv
import sys
from collections import defaultdict

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

MARKERS = {"restir": "o", "restir-unbiased": "s", "ris": "^", "uniform": "v", "bruteforce": "D", "reference": "*"}
# The indirect series: one marker family per kind of indirect light (the direct light is ReSTIR's).
INDIRECT_MARKERS = {"none": "o", "cache": "s", "reference": "*"}


def pareto(points, key):
    if all(p.get("front_" + key) for p in points):
        return sorted((p for p in points if p["front_" + key] != "dominated"), key=lambda p: p["ms"])
    front, best = [], float("inf")
    for p in sorted(points, key=lambda p: (p["ms"], p[key])):
        if p[key] < best:
            front.append(p)
            best = p[key]
    return front


def series(row):
    """('direct', method) or ('indirect', kind) with the reference's bounce count."""
    bounces = int(row.get("reference_bounces") or 0)
    if bounces > 0:
        return "indirect", row.get("indirect") or "none", bounces
    return "direct", row["method"], 0


def read(path):
    """scene -> {'direct': [points], 'indirect': [points]}"""
    scenes = defaultdict(lambda: defaultdict(list))
    with open(path, newline="") as f:
        for row in csv.DictReader(f):
            kind, group, bounces = series(row)
            point = {"group": group, "setting": row["setting"], "bounces": bounces,
                     "ms": float(row["total_ms"]), "mae": float(row["mae"]), "mse": float(row["mse"]),
                     "ratio": float(row.get("mean_ratio") or "nan"), "costed": False}
            if row.get("cost_ms"):
                point.update(ms=float(row["cost_ms"]), ms_low=float(row["cost_low"]),
                             ms_high=float(row["cost_high"]), costed=True)
                for key in ("mae", "mse"):
                    point[key + "_low"] = float(row[key + "_low"])
                    point[key + "_high"] = float(row[key + "_high"])
                    point["front_" + key] = row.get("front_" + key) or ""
            scenes[row["scene"]][kind].append(point)
    return scenes


def bars(points, key):
    """Error bars (lower, upper distances) for x (cost) and y (error), or None without them."""
    if not all(p["costed"] for p in points):
        return None, None
    xerr = [[max(p["ms"] - p["ms_low"], 0) for p in points], [max(p["ms_high"] - p["ms"], 0) for p in points]]
    yerr = [[max(p[key] - p[key + "_low"], 0) for p in points], [max(p[key + "_high"] - p[key], 0) for p in points]]
    return xerr, yerr


def xlabel(points):
    if all(p["costed"] for p in points):
        return "cost per frame, ms (counted work x fitted per-kind cost; bar: rounds' interval and drift)"
    return "GPU ms per frame (lavapipe)"


def chart(scene, points, markers, title, out):
    fig, axes = plt.subplots(1, 3, figsize=(19, 5))
    for ax, key in zip(axes, ("mae", "mse")):
        for group in sorted({p["group"] for p in points}):
            mine = [p for p in points if p["group"] == group]
            sc = ax.scatter([p["ms"] for p in mine], [p[key] for p in mine], marker=markers.get(group, "x"),
                            label=group)
            xerr, yerr = bars(mine, key)
            if xerr:
                ax.errorbar([p["ms"] for p in mine], [p[key] for p in mine], xerr=xerr, yerr=yerr, fmt="none",
                            ecolor=sc.get_facecolor()[0], elinewidth=0.7, capsize=1.5)
        front = pareto(points, key)
        ax.plot([p["ms"] for p in front], [p[key] for p in front], "k--", linewidth=1, label="Pareto front")
        unresolved = [p for p in front if p.get("front_" + key) == "unresolved"]
        if unresolved:
            ax.scatter([p["ms"] for p in unresolved], [p[key] for p in unresolved], s=160, facecolors="none",
                       edgecolors="k", linewidths=0.8, label="member, not resolved at this budget")
        for p in front:
            ax.annotate(p["setting"], (p["ms"], p[key]), fontsize=6, xytext=(3, 3), textcoords="offset points")
        ax.set_yscale("log")
        ax.set_xlabel(xlabel(points), fontsize=8)
        ax.set_ylabel(f"{key.upper()} vs {title} (log; bar: seeds' min-max)")
        ax.set_title(f"{scene}: {key.upper()} against cost")
        ax.grid(True, which="both", linewidth=0.3)
        ax.legend(fontsize=7)
    # Bias at a glance: mean of the non-emitting pixels over the reference's (1 = no bias).
    ax = axes[2]
    for group in sorted({p["group"] for p in points}):
        mine = [p for p in points if p["group"] == group]
        ax.scatter([p["ms"] for p in mine], [p["ratio"] for p in mine], marker=markers.get(group, "x"), label=group)
    ax.axhline(1.0, color="k", linewidth=0.8)
    ax.set_xlabel(xlabel(points), fontsize=8)
    ax.set_ylabel(f"mean / {title}")
    ax.set_title(f"{scene}: mean ratio (bias) against cost")
    ax.grid(True, linewidth=0.3)
    fig.tight_layout()
    fig.savefig(out, dpi=110)
    plt.close(fig)
    print(f"wrote    {out}")


def main(path, outdir):
    for scene, kinds in read(path).items():
        if kinds["direct"]:
            chart(scene, kinds["direct"], MARKERS, "direct-light reference", f"{outdir}/sweep_{scene}.png")
        if kinds["indirect"]:
            bounces = kinds["indirect"][0]["bounces"]
            chart(scene, kinds["indirect"], INDIRECT_MARKERS, f"{bounces}-bounce reference",
                  f"{outdir}/sweep_indirect_{scene}.png")


if __name__ == "__main__":
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    main(sys.argv[1], sys.argv[2])
