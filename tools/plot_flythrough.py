#!/usr/bin/env python3
"""Charts a `vox bench flythrough` summary: per scene, the indirect term's error (MAE as a
fraction of the reference's mean indirect light) against wall milliseconds per frame (the whole
Renderer::render, host work included). The path-traced points (1, 2, 4... paths per pixel per
frame) are joined into a curve; the irradiance cache is one point; "none" (ReSTIR alone, whose
error is all of the indirect light) marks the cost of the direct light. A cache point below the
path curve at its own time is the cache winning at equal time. Also prints, per scene, the
path tracer's error at the cache's time (log-log interpolation between the bracketing path points;
"beyond" when the cache's time is outside them) and which of the two is lower: the markdown of
docs/ACCURACY.md's equal-time table.
Usage: plot_flythrough.py summary.csv [OUT.png]   (default: summary.csv's folder/flythrough.png)"""
import csv
import math
import os
import sys
from collections import defaultdict

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def variant_of(row):
    """A cache run's name: its --cache-variant, else its fallback and budget (older CSVs have only those)."""
    if row.get("cache_variant"):
        return row["cache_variant"]
    return ", ".join(f"{k} {row[f'cache_{k}']}" for k in ("fallback", "budget") if row.get(f"cache_{k}"))


def path_error_at(path, ms):
    """The path curve's relative MAE at `ms` and whether the path points bracket it."""
    pts = sorted((float(r["wall_ms_mean"]), float(r["relative_mae"])) for r in path)
    for (x0, y0), (x1, y1) in zip(pts, pts[1:]):
        if x0 <= ms <= x1 and x0 > 0 and y0 > 0 and y1 > 0:
            t = (math.log(ms) - math.log(x0)) / (math.log(x1) - math.log(x0))
            return math.exp(math.log(y0) + t * (math.log(y1) - math.log(y0))), True
    # Outside: the nearest end of the curve (a bound, not an estimate).
    x, y = pts[0] if ms < pts[0][0] else pts[-1]
    return y, False


def path_time_at(path, error):
    """The wall ms at which the path curve reaches `error` (log-log interpolation), or None when
    its points do not bracket it: the cache wins at equal time once it is faster than that."""
    pts = sorted((float(r["wall_ms_mean"]), float(r["relative_mae"])) for r in path)
    for (x0, y0), (x1, y1) in zip(pts, pts[1:]):
        if min(y0, y1) <= error <= max(y0, y1) and y0 != y1 and min(x0, y0, y1) > 0:
            t = (math.log(error) - math.log(y0)) / (math.log(y1) - math.log(y0))
            return math.exp(math.log(x0) + t * (math.log(x1) - math.log(x0)))
    return None


def reference_floor(path):
    """The reference's own noise as the path curve sees it: fitting MAE^2 = a / spp + f^2 to the two
    points with the most paths gives f, the error a perfect method would still show (rough: MAE
    is not RMS)."""
    pts = sorted((int(r["spp"]), float(r["relative_mae"])) for r in path)
    if len(pts) < 2:
        return float("nan")
    (s1, e1), (s2, e2) = pts[-2], pts[-1]
    a = (e1 * e1 - e2 * e2) / (1.0 / s1 - 1.0 / s2)
    return math.sqrt(max(0.0, e2 * e2 - a / s2))


def equal_time_table(rows):
    lines = ["| scene | cache ms/frame | cache MAE | path MAE at the cache's time | lower at equal time "
             "| path's time at the cache's MAE | reference noise (est.) |",
             "|---|---:|---:|---:|---|---:|---:|"]
    for scene, rs in rows.items():
        path = [r for r in rs if r["method"] == "path"]
        caches = [r for r in rs if r["method"] == "cache"]
        for c in caches:
            variant = variant_of(c)
            name = f"{scene} ({variant})" if len(caches) > 1 and variant else scene
            ms, mae = float(c["wall_ms_mean"]), float(c["relative_mae"])
            at, inside = path_error_at(path, ms)
            if inside:
                verdict = "cache" if mae < at else "path tracer"
                text = f"{100 * at:.1f} %"
            else:
                slower = ms > max(float(r["wall_ms_mean"]) for r in path)
                # Past the slowest path point the path tracer's error is at most that point's.
                verdict = ("path tracer" if at < mae else "undecided (add path spp)") if slower else \
                          ("cache" if mae < at else "undecided (add path spp)")
                text = f"{'<=' if slower else '>='} {100 * at:.1f} % (beyond the path points)"
            floor = reference_floor(path)
            even = path_time_at(path, mae)
            even_text = f"{even:.0f}" if even else "beyond the path points"
            lines.append(f"| {name} | {ms:.0f} | {100 * mae:.1f} % | {text} | {verdict} | {even_text} "
                         f"| {100 * floor:.0f} % |")
    return "\n".join(lines)


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
        cache_colours = iter(["tab:red", "tab:orange", "tab:purple", "tab:brown", "tab:pink", "tab:olive"])
        for method, style, label in (("cache", "s", "ReSTIR + irradiance cache"), ("none", "x", "ReSTIR, no indirect")):
            for r in rs:
                if r["method"] == method:
                    variant = variant_of(r)
                    colour = next(cache_colours, "tab:red") if method == "cache" else "grey"
                    ax.plot(float(r["wall_ms_mean"]), 100 * float(r["relative_mae"]), style, color=colour, markersize=9,
                            label=f"{label} ({variant})" if variant else label)
        first = rs[0]
        ax.set_title(f"{scene} ({first['size']}, {first['reference_frames']} reference frames)", fontsize=10)
        ax.set_xscale("log")
        ax.set_xlabel("wall ms per frame (mean over the flythrough, log)")
        ax.set_ylabel("indirect MAE, % of mean |indirect|")
        ax.set_ylim(bottom=0)
        ax.grid(alpha=0.3)
        ax.legend(fontsize=7)
    for ax in list(axes.flat)[len(scenes):]:
        ax.axis("off")
    fig.suptitle("Indirect light on a moving camera: error against wall time per frame", fontsize=10)
    fig.tight_layout()
    fig.savefig(out, dpi=110)
    print(equal_time_table(rows))
    print(f"wrote {out}")


if __name__ == "__main__":
    main()
