#!/usr/bin/env python3
"""Charts `vox bench stability`'s results in OUTDIR:
- response.csv: MAE against the edited scene's reference, per frame after each edit (and after a
  dynamic object starts moving), one line per method -> stability_response.png;
- ghosting.csv (when present): a fast dynamic object with the cache's neighbourhood on and off,
  MAE over the image and on the object's pixels per frame -> stability_ghosting.png;
- thin_wall_*.png (when present): the cache's indirect term outside and inside the sealed
  one-voxel room -> stability_thin_wall.png.
Usage: plot_stability.py response.csv OUTDIR"""
import csv
import os
import sys
from collections import defaultdict

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def main(path, outdir):
    series = defaultdict(lambda: defaultdict(list))
    with open(path, newline="") as f:
        for row in csv.DictReader(f):
            series[row["case"]][row["method"]].append((int(row["frame"]), float(row["mae"])))
    cases = sorted(series)
    fig, axes = plt.subplots(1, len(cases), figsize=(4.2 * len(cases), 3.4), squeeze=False)
    for ax, case in zip(axes[0], cases):
        for method, points in sorted(series[case].items()):
            ax.plot([p[0] for p in points], [p[1] for p in points], marker=".", label=method)
        ax.set_yscale("log")
        ax.set_title(case, fontsize=9)
        ax.set_xlabel("frames after the edit")
        ax.set_ylabel("MAE vs new reference")
        ax.grid(True, which="both", linewidth=0.3)
        ax.legend(fontsize=7)
    fig.tight_layout()
    out = f"{outdir}/stability_response.png"
    fig.savefig(out, dpi=110)
    print(f"wrote    {out}")
    ghosting(outdir)
    thin_wall(outdir)


def ghosting(outdir):
    path = f"{outdir}/ghosting.csv"
    if not os.path.exists(path):
        return
    series = defaultdict(list)
    with open(path, newline="") as f:
        for row in csv.DictReader(f):
            series[row["method"]].append((int(row["frame"]), float(row["mae"]), float(row["mae_object"])))
    fig, axes = plt.subplots(1, 2, figsize=(10, 3.6))
    for ax, col, title in zip(axes, (1, 2), ("whole image", "the object's pixels")):
        for method, points in sorted(series.items()):
            ax.plot([p[0] for p in points], [p[col] for p in points], marker=".", label=method)
        ax.set_yscale("log")
        ax.set_title(f"fast object (3.7 voxels/frame): MAE on {title}", fontsize=9)
        ax.set_xlabel("frames after it starts moving")
        ax.set_ylabel("MAE vs that frame's 1-bounce reference")
        ax.grid(True, which="both", linewidth=0.3)
        ax.legend(fontsize=7)
    fig.tight_layout()
    out = f"{outdir}/stability_ghosting.png"
    fig.savefig(out, dpi=110)
    print(f"wrote    {out}")


def thin_wall(outdir):
    names = [("thin_wall_outside_indirect.png", "outside: cache indirect"),
             ("thin_wall_inside_indirect.png", "inside, same scale"),
             ("thin_wall_inside_indirect_x1000.png", "inside, 1000x brighter")]
    if not all(os.path.exists(f"{outdir}/{n}") for n, _ in names):
        return
    fig, axes = plt.subplots(1, 3, figsize=(11, 2.8))
    for ax, (name, title) in zip(axes, names):
        ax.imshow(plt.imread(f"{outdir}/{name}"))
        ax.set_title(title, fontsize=9)
        ax.axis("off")
    fig.suptitle("thin wall (one voxel), irradiance cache: does light leak into the sealed room?", fontsize=10)
    fig.tight_layout()
    out = f"{outdir}/stability_thin_wall.png"
    fig.savefig(out, dpi=110)
    print(f"wrote    {out}")


if __name__ == "__main__":
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    main(sys.argv[1], sys.argv[2])
