#!/usr/bin/env python3
"""Charts `vox bench stability`'s response.csv: MAE against the edited scene's reference, per
frame after each edit, one line per method. Usage: plot_stability.py response.csv OUTDIR"""
import csv
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


if __name__ == "__main__":
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    main(sys.argv[1], sys.argv[2])
