#!/usr/bin/env python3
"""Charts a `vox bench flythrough` summary: per scene, the indirect term's error (MAE as a
fraction of the reference's mean indirect light) against wall milliseconds per frame (the whole
Renderer::render, host work included). The path-traced points (1, 2, 4... paths per pixel per
frame) are joined into a curve; the irradiance cache is one point; "none" (ReSTIR alone, whose
error is all of the indirect light) marks the cost of the direct light. A cache point below the
path curve at its own time is the cache winning at equal time.
Usage: plot_flythrough.py summary.csv [OUT.png]   (default: summary.csv's folder/flythrough.png)"""
import csv
import os
import sys
from collections import defaultdict

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def main():
    if len(sys.argv) < 2:
        sys.exit(__doc__)
    source = sys.argv[1]
    out = sys.argv[2] if len(sys.argv) > 2 else os.path.join(os.path.dirname(source) or ".", "flythrough.png")
    rows = defaultdict(list)
    with open(source, newline="") as f:
        for r in csv.DictReader(f):
            rows[r["scene"]].append(r)
    if not rows:
        sys.exit(f"{source}: no rows")
    scenes = list(rows)
    cols = min(len(scenes), 2)
    lines = (len(scenes) + cols - 1) // cols
    fig, axes = plt.subplots(lines, cols, figsize=(5.2 * cols, 3.9 * lines), squeeze=False)
    for ax, scene in zip(axes.flat, scenes):
        rs = rows[scene]
        path = sorted((r for r in rs if r["method"] == "path"), key=lambda r: float(r["wall_ms_mean"]))
        xs = [float(r["wall_ms_mean"]) for r in path]
        ys = [100 * float(r["relative_mae"]) for r in path]
        ax.plot(xs, ys, "o-", color="tab:blue", label="ReSTIR + path-traced indirect")
        for r, x, y in zip(path, xs, ys):
            ax.annotate(f"{r['spp']} spp", (x, y), textcoords="offset points", xytext=(4, 4), fontsize=8)
        for method, style, colour, label in (("cache", "s", "tab:red", "ReSTIR + irradiance cache"),
                                             ("none", "x", "grey", "ReSTIR, no indirect")):
            for r in rs:
                if r["method"] == method:
                    ax.plot(float(r["wall_ms_mean"]), 100 * float(r["relative_mae"]), style, color=colour,
                            markersize=9, label=label)
        first = rs[0]
        ax.set_title(f"{scene} ({first['size']}, {first['reference_frames']} reference frames)", fontsize=10)
        ax.set_xlabel("wall ms per frame (mean over the flythrough)")
        ax.set_ylabel("indirect MAE, % of mean indirect")
        ax.set_ylim(bottom=0)
        ax.set_xlim(left=0)
        ax.grid(alpha=0.3)
        ax.legend(fontsize=7)
    for ax in list(axes.flat)[len(scenes):]:
        ax.axis("off")
    fig.suptitle("Indirect light on a moving camera: error against wall time per frame", fontsize=11)
    fig.tight_layout()
    fig.savefig(out, dpi=110)
    print(f"wrote {out}")


if __name__ == "__main__":
    main()
