#!/usr/bin/env python3
"""Charts a `vox bench frame` JSON: per image size, one stacked bar per configuration (world,
indirect light, camera): the median GPU milliseconds of each pass, then the host's share (median
wall time minus median GPU time: posing, uploads, the cache's host work, submission and waits),
so a bar is as tall as the median wall time per frame; a tick marks the p95 wall time.
Usage: plot_frame.py frame.json OUTDIR  ->  OUTDIR/frame_<W>x<H>.png"""
import json
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

# Passes below this share of every bar are folded into "other" so the legend stays readable.
MIN_SHARE = 0.02


def chart(configs, size, out):
    passes = []
    for c in configs:
        for name in c["pass_ms"]:
            if name not in passes:
                passes.append(name)
    shown = [p for p in passes
             if any(c["pass_ms"].get(p, 0.0) >= MIN_SHARE * max(c["wall_median_ms"], 1e-9) for c in configs)]
    labels = [f'{c["world"]}\n{c["indirect"]}, {c["camera"]}' for c in configs]
    fig, ax = plt.subplots(figsize=(max(8, 1.1 * len(configs) + 3), 6))
    xs = range(len(configs))
    bottom = [0.0] * len(configs)
    colours = plt.get_cmap("tab20")
    for i, p in enumerate(shown + ["other passes", "host (wall - GPU)"]):
        if p == "other passes":
            values = [sum(v for k, v in c["pass_ms"].items() if k not in shown) for c in configs]
            colour = "lightgrey"
        elif p == "host (wall - GPU)":
            values = [max(0.0, c["wall_median_ms"] - c["gpu_median_ms"]) for c in configs]
            colour = "dimgrey"
        else:
            values = [c["pass_ms"].get(p, 0.0) for c in configs]
            colour = colours(i % 20)
        if not any(values):
            continue
        ax.bar(xs, values, bottom=bottom, label=p, color=colour, width=0.7)
        bottom = [b + v for b, v in zip(bottom, values)]
    ax.scatter(xs, [c["wall_p95_ms"] for c in configs], marker="_", s=400, color="black", label="wall p95", zorder=3)
    for x, c in zip(xs, configs):
        ax.annotate(f'{c["wall_median_ms"]:.0f}', (x, c["wall_median_ms"]), ha="center", va="bottom", fontsize=8,
                    xytext=(0, 2), textcoords="offset points")
    ax.set_xticks(list(xs))
    ax.set_xticklabels(labels, fontsize=8)
    ax.set_ylabel("ms per frame (median)")
    ax.set_title(f"vox bench frame, {size}: GPU ms per pass (median) + host share = median wall time")
    ax.legend(fontsize=8, loc="upper left", bbox_to_anchor=(1.0, 1.0))
    ax.grid(axis="y", alpha=0.3)
    fig.tight_layout()
    fig.savefig(out, dpi=100)
    plt.close(fig)


def main():
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    with open(sys.argv[1]) as f:
        data = json.load(f)
    os.makedirs(sys.argv[2], exist_ok=True)
    sizes = []
    for c in data["configs"]:
        size = f'{c["width"]}x{c["height"]}'
        if size not in sizes:
            sizes.append(size)
    for size in sizes:
        out = os.path.join(sys.argv[2], f"frame_{size}.png")
        chart([c for c in data["configs"] if f'{c["width"]}x{c["height"]}' == size], size, out)
        print(f"wrote {out}")


if __name__ == "__main__":
    main()
