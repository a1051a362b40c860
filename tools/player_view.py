#!/usr/bin/python3
"""The pictures of docs/DISPLAY.md's "What the player sees" and README's first picture.

One still view of a world with vox play's lighting (ReSTIR + the irradiance cache, auto exposure),
shown three ways at the display's size: the raw render at half of it blown up by nearest
neighbour (what `--display raw` shows), the reconstruction from the same half-size render
after N frames (`--display denoised`, vox play's default), and the path tracer's box-filtered
reference. Writes OUT/player_view.png (the reconstructed frame) and OUT/player_view_crops.png
(the same crop of the three, enlarged, side by side), and prints each render's command.

Usage: tools/player_view.py VOX OUT [--world sandbox] [--camera NAME] [--size 640x360]
       [--scale 0.5] [--frames 32] [--spp 64] [--crop x,y,w,h] [--zoom 2]
"""
import argparse
import os
import subprocess
import sys

import numpy as np
from PIL import Image, ImageDraw


def render(vox, out, args, extra):
    cmd = [vox, "render", args.world, "--size", args.size, "--auto-exposure", "on", "-o", out] + extra
    if args.camera:
        cmd += ["--camera", args.camera]
    print("$", " ".join(cmd), flush=True)
    done = subprocess.run(cmd, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True)
    if done.returncode != 0:
        sys.exit(f"player_view: {' '.join(cmd)} failed: {done.stderr.strip()}")
    return Image.open(out).convert("RGB")


def main():
    p = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    p.add_argument("vox")
    p.add_argument("out")
    p.add_argument("--world", default="sandbox")
    p.add_argument("--camera", default="")
    p.add_argument("--size", default="640x360")
    p.add_argument("--scale", default="0.5")
    p.add_argument("--frames", default="32")
    p.add_argument("--spp", default="64")
    p.add_argument("--crop", default="", help="x,y,w,h in display pixels (default: the middle quarter)")
    p.add_argument("--zoom", type=int, default=2)
    args = p.parse_args()
    os.makedirs(args.out, exist_ok=True)
    w, h = (int(v) for v in args.size.split("x"))

    raw = render(args.vox, os.path.join(args.out, "raw.png"), args,
                 ["--indirect", "cache", "--render-scale", args.scale, "--display", "raw", "--frames",
                  args.frames])
    raw = raw.resize((w, h), Image.NEAREST)
    shown = render(args.vox, os.path.join(args.out, "player_view.png"), args,
                   ["--indirect", "cache", "--render-scale", args.scale, "--frames", args.frames])
    ref = render(args.vox, os.path.join(args.out, "reference.png"), args,
                 ["--method", "reference", "--indirect", "reference", "--spp", args.spp,
                  "--display", "raw"])

    x, y, cw, ch = ((int(v) for v in args.crop.split(",")) if args.crop else
                    (w // 4, h // 4, w // 2, h // 2))
    crops = [im.crop((x, y, x + cw, y + ch)).resize((cw * args.zoom, ch * args.zoom), Image.NEAREST)
             for im in (raw, shown, ref)]
    labels = [f"raw {args.scale} (blit)", f"reconstructed from {args.scale}, {args.frames} frames",
              f"path tracer, {args.spp} spp"]
    gap, band = 6, 18
    sheet = Image.new("RGB", (3 * cw * args.zoom + 2 * gap, ch * args.zoom + band), "white")
    draw = ImageDraw.Draw(sheet)
    for i, (c, label) in enumerate(zip(crops, labels)):
        left = i * (cw * args.zoom + gap)
        sheet.paste(c, (left, band))
        draw.text((left + 4, 3), label, fill="black")
    sheet.save(os.path.join(args.out, "player_view_crops.png"))
    # How far each is from the reference, in the crop (8-bit display values, not the metrics of
    # vox bench display, which compare linear radiance).
    r = np.asarray(crops[2], dtype=np.float64)
    for label, c in zip(labels[:2], crops[:2]):
        mae = np.abs(np.asarray(c, dtype=np.float64) - r).mean() / max(r.mean(), 1e-9)
        print(f"{label}: mean |difference| against the reference in the crop {mae:.3f} of its mean")
    print("wrote", os.path.join(args.out, "player_view.png"), "and",
          os.path.join(args.out, "player_view_crops.png"))


if __name__ == "__main__":
    main()
