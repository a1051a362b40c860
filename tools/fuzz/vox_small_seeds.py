#!/usr/bin/env python3
"""Small .vox fuzz seeds from real files: every chunk kept (scene graph, layers, materials,
palette), each model's XYZI cut to its first few voxels, so libFuzzer mutates inputs of a few
kilobytes that still reach the scene-graph walk and the import.
    vox_small_seeds.py OUT_DIR FILE.vox...
"""
import os
import struct
import sys

KEEP = 16


def shrink(data):
    out = bytearray(data[:8])
    main_id, main_content, _ = data[8:12], *struct.unpack_from("<ii", data, 12)
    children = bytearray()
    p = 20 + main_content
    while p + 12 <= len(data):
        cid = data[p:p + 4]
        n, m = struct.unpack_from("<ii", data, p + 4)
        content = data[p + 12:p + 12 + n]
        if cid == b"XYZI" and len(content) >= 4:
            count = min(struct.unpack_from("<i", content)[0], KEEP)
            content = struct.pack("<i", count) + content[4:4 + 4 * count]
        children += cid + struct.pack("<ii", len(content), 0) + content
        p += 12 + n + m
    out += main_id + struct.pack("<ii", 0, len(children)) + children
    return bytes(out)


def main():
    out_dir = sys.argv[1]
    for path in sys.argv[2:]:
        with open(path, "rb") as f:
            data = f.read()
        name = os.path.join(out_dir, "small_" + os.path.basename(path))
        with open(name, "wb") as f:
            f.write(shrink(data))


if __name__ == "__main__":
    main()
