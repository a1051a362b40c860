#!/usr/bin/env python3
"""Chart of `vox bench lights`: time per frame and equal-time error against the lamp count.

usage: python3 tools/plot_lights.py out/bench_lights/lights.csv docs/images/lights_scaling.png

One column per layout (dense around the view, sparse over the floor); top: the process's CPU ms
per frame and, dashed, wall ms (medians, bars: the seeds' min-max; wall ms on a shared machine
also counts the waits for a core); bottom: MAE against the path tracer at equal time, each
sampling's MAE^2 x CPU ms brought to the first sampling row's CPU ms, so lower is better. The sampling --sampling auto chose is ringed.
"""
import csv
import math
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
        first_sampling = next(r["sampling"] for r in rows if r["layout"] == layout)
        first = {r["count"]: float(r["cpu_ms"]) for r in series[first_sampling]}
        for sampling, pts in sorted(series.items()):
            pts.sort(key=lambda r: int(r["emitters"]))
            x = [int(r["emitters"]) for r in pts]
            wall = [float(r["wall_ms"]) for r in pts]
            lo = [w - float(r["wall_ms_min"]) for w, r in zip(wall, pts)]
            hi = [float(r["wall_ms_max"]) - w for w, r in zip(wall, pts)]
            cpu = [float(r["cpu_ms"]) for r in pts]
            clo = [c - float(r["cpu_ms_min"]) for c, r in zip(cpu, pts)]
            chi = [float(r["cpu_ms_max"]) - c for c, r in zip(cpu, pts)]
            top = axes[0][col].errorbar(x, cpu, yerr=[clo, chi], marker="o", capsize=3,
                                        label=f"{sampling} CPU")
            axes[0][col].errorbar(x, wall, yerr=[lo, hi], marker="x", capsize=2, ls="--",
                                  alpha=0.5, color=top[0].get_color(), label=f"{sampling} wall")
            # MAE at the first row's frame time: MAE^2 x ms is constant in time (MAE falls as
            # 1 / sqrt(samples)); MAE, not MSE, because at 64 spp the reference's own noise on
            # lamp fields is as large as a row's MSE (docs/PERFORMANCE.md).
            err = [math.sqrt(float(r["mae_x_ms"]) / first[r["count"]]) for r in pts]
            axes[1][col].plot(x, err, marker="o", color=top[0].get_color(), label=sampling)
            chosen = [(xi, e, c) for xi, e, c, r in zip(x, err, cpu, pts)
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
        axes[0][col].set_title(f"{layout}: ms per frame (CPU; wall dashed)")
        axes[1][col].set_title(f"{layout}: MAE at {first_sampling}'s CPU time")
        axes[0][col].legend(title="sampling (ring: auto)")
    fig.tight_layout()
    fig.savefig(out, dpi=110)
    print(f"wrote    {out}")


if __name__ == "__main__":
    if len(sys.argv) != 3:
        sys.exit("usage: plot_lights.py LIGHTS_CSV OUT_PNG")
    main(sys.argv[1], sys.argv[2])
