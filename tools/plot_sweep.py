#!/usr/bin/env python3
"""Charts a `vox bench sweep` CSV: per scene, error (MAE and MSE, log) against GPU milliseconds
per frame, one marker style per method, the Pareto front (no other point is both faster and
more accurate) joined. MAE shows bias best, MSE punishes fireflies: both are drawn.
Usage: plot_sweep.py sweep.csv OUTDIR  ->  OUTDIR/sweep_<scene>.png"""
import csv
import sys
from collections import defaultdict

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

MARKERS = {"restir": "o", "restir-unbiased": "s", "ris": "^", "uniform": "v", "bruteforce": "D", "reference": "*"}


def pareto(points, key):
    front, best = [], float("inf")
    for p in sorted(points, key=lambda p: (p["ms"], p[key])):
        if p[key] < best:
            front.append(p)
            best = p[key]
    return front


def main(path, outdir):
    scenes = defaultdict(list)
    with open(path, newline="") as f:
        for row in csv.DictReader(f):
            scenes[row["scene"]].append({"method": row["method"], "setting": row["setting"],
                                         "ms": float(row["total_ms"]), "mae": float(row["mae"]),
                                         "mse": float(row["mse"])})
    for scene, points in scenes.items():
        fig, axes = plt.subplots(1, 2, figsize=(13, 5))
        for ax, key in zip(axes, ("mae", "mse")):
            for method in sorted({p["method"] for p in points}):
                mine = [p for p in points if p["method"] == method]
                ax.scatter([p["ms"] for p in mine], [p[key] for p in mine], marker=MARKERS.get(method, "x"),
                           label=method)
            front = pareto(points, key)
            ax.plot([p["ms"] for p in front], [p[key] for p in front], "k--", linewidth=1, label="Pareto front")
            for p in front:
                ax.annotate(p["setting"], (p["ms"], p[key]), fontsize=6, xytext=(3, 3), textcoords="offset points")
            ax.set_yscale("log")
            ax.set_xlabel("GPU ms per frame (lavapipe)")
            ax.set_ylabel(f"{key.upper()} vs reference (log)")
            ax.set_title(f"{scene}: {key.upper()} against time")
            ax.grid(True, which="both", linewidth=0.3)
            ax.legend(fontsize=7)
        fig.tight_layout()
        out = f"{outdir}/sweep_{scene}.png"
        fig.savefig(out, dpi=110)
        print(f"wrote    {out}")


if __name__ == "__main__":
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    main(sys.argv[1], sys.argv[2])
