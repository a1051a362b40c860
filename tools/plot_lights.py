#!/usr/bin/env python3
"""Chart of `vox bench lights`: time per frame and equal-time error against the lamp count.

usage: python3 tools/plot_lights.py out/bench_lights/lights.csv docs/images/lights_scaling.png

One column per layout (dense around the view, sparse over the floor); top: wall ms per frame
(median, bars: the seeds' min-max); bottom: relative RMSE at equal time, each sampling's
MSE x CPU ms brought to the first sampling row's CPU ms (sqrt(MSE x ms / ms0) / the reference's
mean), so lower is better at equal time. The sampling --sampling auto chose is ringed.
"""
import csv
import sys
from collections import defaultdict

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt


def main(path, out):
    rows = list(csv.DictReader(open(path)))
    layouts = sorted({r["layout"] for r in rows})
    fig, axes = plt.subplots(2, len(layouts), figsize=(5.2 * len(layouts), 7), squeeze=False)
    for col, layout in enumerate(layouts):
        series = defaultdict(list)
        for r in rows:
            if r["layout"] == layout:
                series[r["sampling"]].append(r)
        for sampling, pts in sorted(series.items()):
            pts.sort(key=lambda r: int(r["emitters"]))
            x = [int(r["emitters"]) for r in pts]
            wall = [float(r["wall_ms"]) for r in pts]
            lo = [w - float(r["wall_ms_min"]) for w, r in zip(wall, pts)]
            hi = [float(r["wall_ms_max"]) - w for w, r in zip(wall, pts)]
            top = axes[0][col].errorbar(x, wall, yerr=[lo, hi], marker="o", capsize=3,
                                        label=sampling)
            # Relative RMSE at the first row's frame time (the bench's rel_rmse_equal_time).
            err = [float(r["rel_rmse_equal_time"]) for r in pts]
            axes[1][col].plot(x, err, marker="o", color=top[0].get_color(), label=sampling)
            chosen = [(xi, e, w) for xi, e, w, r in zip(x, err, wall, pts)
                      if r["auto_choice"] == sampling]
            if chosen:
                axes[0][col].scatter([c[0] for c in chosen], [c[2] for c in chosen], s=160,
                                     facecolors="none", edgecolors="k")
                axes[1][col].scatter([c[0] for c in chosen], [c[1] for c in chosen], s=160,
                                     facecolors="none", edgecolors="k")
        for row in range(2):
            ax = axes[row][col]
            ax.set_xscale("log")
            ax.set_yscale("log")
            ax.grid(True, which="both", alpha=0.3)
            ax.set_xlabel("emissive voxels")
        axes[0][col].set_title(f"{layout}: wall ms per frame")
        axes[1][col].set_title(f"{layout}: relative RMSE at equal time")
        axes[0][col].legend(title="sampling (ring: auto)")
    fig.tight_layout()
    fig.savefig(out, dpi=110)
    print(f"wrote    {out}")


if __name__ == "__main__":
    if len(sys.argv) != 3:
        sys.exit("usage: plot_lights.py LIGHTS_CSV OUT_PNG")
    main(sys.argv[1], sys.argv[2])
