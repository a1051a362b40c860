#!/usr/bin/env python3
"""Charts a `vox bench frame` JSON: per image size, one stacked bar per configuration (world,
indirect light, camera): the median GPU milliseconds of each pass, then the host's share (median
wall time minus median GPU time: posing, uploads, the cache's host work, submission and waits),
so a bar is as tall as the median wall time per frame; a tick marks the p95 wall time. Also
prints the results as the markdown table of docs/PERFORMANCE.md ("Frame time"), so a partial
run's JSON (written after every configuration) gives a table too.
Usage: plot_frame.py frame.json OUTDIR  ->  OUTDIR/frame_<W>x<H>.png, table on stdout"""
import json
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

# Passes below this share of every bar are folded into "other" so the legend stays readable.
MIN_SHARE = 0.02


def bars(ax, configs, passes, colour_of):
    """One stacked bar per configuration on `ax`."""
    shown = [p for p in passes
             if any(c["pass_ms"].get(p, 0.0) >= MIN_SHARE * max(c["wall_median_ms"], 1e-9) for c in configs)]
    xs = range(len(configs))
    bottom = [0.0] * len(configs)
    for p in shown + ["other passes", "host (wall - GPU)"]:
        if p == "other passes":
            values = [sum(v for k, v in c["pass_ms"].items() if k not in shown) for c in configs]
        elif p == "host (wall - GPU)":
            values = [max(0.0, c["wall_median_ms"] - c["gpu_median_ms"]) for c in configs]
        else:
            values = [c["pass_ms"].get(p, 0.0) for c in configs]
        if not any(values):
            continue
        ax.bar(xs, values, bottom=bottom, label=p, color=colour_of(p), width=0.7)
        bottom = [b + v for b, v in zip(bottom, values)]
    ax.scatter(xs, [c["wall_p95_ms"] for c in configs], marker="_", s=400, color="black", label="wall p95", zorder=3)
    for x, c in zip(xs, configs):
        ax.annotate(f'{c["wall_median_ms"]:.0f}', (x, c["wall_median_ms"]), ha="center", va="bottom", fontsize=8,
                    xytext=(0, 2), textcoords="offset points")
    ax.set_xticks(list(xs))
    ax.set_xticklabels([f'{c["world"]}\n{c["camera"]}' for c in configs], fontsize=8)
    ax.grid(axis="y", alpha=0.3)


def chart(configs, size, out):
    """One panel per lighting row (their times differ by an order of magnitude), colours shared."""
    passes = []
    for c in configs:
        for name in c["pass_ms"]:
            if name not in passes:
                passes.append(name)
    cmap = plt.get_cmap("tab20")
    fixed = {"other passes": "lightgrey", "host (wall - GPU)": "dimgrey"}
    colour_of = lambda p: fixed.get(p) or cmap(passes.index(p) % 20)  # noqa: E731
    rows = []
    for c in configs:
        if c["indirect"] not in rows:
            rows.append(c["indirect"])
    fig, axes = plt.subplots(1, len(rows), figsize=(max(9, 1.1 * len(configs) + 4), 5.5), squeeze=False)
    handles = {}
    for ax, row in zip(axes[0], rows):
        bars(ax, [c for c in configs if c["indirect"] == row], passes, colour_of)
        ax.set_title(f"ReSTIR + indirect {row}", fontsize=10)
        ax.set_ylabel("ms per frame (median)")
        for h, label in zip(*ax.get_legend_handles_labels()):
            handles.setdefault(label, h)
    fig.suptitle(f"vox bench frame {size}: GPU ms per pass + host share = median wall time; tick: p95 wall")
    fig.legend(handles.values(), handles.keys(), fontsize=8, loc="center right")
    fig.tight_layout(rect=(0, 0, 0.88, 1))
    fig.savefig(out, dpi=100)
    plt.close(fig)


def table(configs):
    print("| world | size | indirect | camera | wall median ms | wall p95 ms | GPU ms | host ms | rays/frame "
          "| cache entries updated | top passes (GPU ms, median) |")
    print("| --- | --- | --- | --- | ---: | ---: | ---: | ---: | ---: | ---: | --- |")
    for c in configs:
        top = sorted(c["pass_ms"].items(), key=lambda kv: -kv[1])[:3]
        print(f'| {c["world"]} | {c["width"]}×{c["height"]} | {c["indirect"]} | {c["camera"]} '
              f'| {c["wall_median_ms"]:.0f} | {c["wall_p95_ms"]:.0f} | {c["gpu_median_ms"]:.0f} '
              f'| {c["host_median_ms"]:.1f} | {c["rays"] / 1e6:.2f} M | {c["cache_updated"]:.0f} | '
              + ", ".join(f"{k} {v:.0f}" for k, v in top) + " |")


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
        print(f"wrote {out}", file=sys.stderr)
    table(data["configs"])


if __name__ == "__main__":
    main()
