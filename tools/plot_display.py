#!/usr/bin/env python3
"""Charts a `vox bench display` output folder: per world, the shown image's relative MAE against
the converged frame (y) against wall milliseconds per frame (x, median; the whole Renderer::render,
host work included), one point per row — raw, upsampled and denoised at each render scale, and raw
at the display's size. A reconstruction row left of and below its scale's raw row is cheaper per
quality; below "raw 1" it beats shading every display pixel.
Usage: plot_display.py OUT_FOLDER [CHART.png]   (default: OUT_FOLDER/display.png)"""
import csv
import os
import sys
from collections import defaultdict

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

MARKERS = {"raw": "s", "upsampled": "^", "denoised": "o"}


def main():
    if len(sys.argv) < 2:
        sys.exit(__doc__)
    folder = sys.argv[1]
    out = sys.argv[2] if len(sys.argv) > 2 else os.path.join(folder, "display.png")
    rows = defaultdict(list)
    with open(os.path.join(folder, "summary.csv"), newline="") as f:
        for r in csv.DictReader(f):
            rows[r["world"]].append(r)
    if not rows:
        sys.exit(f"{folder}/summary.csv: no rows")
    fig, axes = plt.subplots(1, len(rows), figsize=(5 * len(rows), 4), squeeze=False)
    for ax, (world, rs) in zip(axes[0], rows.items()):
        scales = sorted({float(r["scale"]) for r in rs})
        colours = {s: plt.cm.viridis(i / max(len(scales) - 1, 1)) for i, s in enumerate(scales)}
        for r in rs:
            mode = r["row"].split()[0]
            ax.scatter(float(r["wall_ms_median"]), float(r["relative_mae"]), marker=MARKERS[mode],
                       color=colours[float(r["scale"])], s=50, label=r["row"])
        ax.set_xscale("log")
        ax.set_xlabel("wall ms per frame (median)")
        ax.set_ylabel("relative MAE vs converged frame")
        ax.set_title(f"{world}, {rs[0]['display_size']} display")
        ax.grid(True, which="both", alpha=0.3)
        ax.legend(fontsize=7)
    fig.tight_layout()
    fig.savefig(out, dpi=110)
    print(f"wrote {out}")


if __name__ == "__main__":
    main()
