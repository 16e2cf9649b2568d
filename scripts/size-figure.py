#!/usr/bin/env python3
"""docs/size_field.png: the top view of a surface's triangles, each edge coloured by its length over
the size asked for (blue 0, green 1/2, red 1 and over), on white; numpy and meshio only.

Usage: size-figure.py SURFACE SIZE OUT.png [WIDTH]
  SURFACE  a surface file meshio reads (the pipeline's surface.ply)
  SIZE     the --size the run was given (the colours' scale)
The figure of docs/size_field.md:
  /usr/bin/python3 scripts/box-with-hole.py 3 box.stl surface
  build/bin/meshprep pipeline box.stl -o out/box --size 1 --curvature-points 12
  /usr/bin/python3 scripts/size-figure.py out/box/surface.ply 1 docs/size_field.png
"""
import struct
import sys
import zlib

import meshio
import numpy as np


def png(path, rgb):
    h, w, _ = rgb.shape
    raw = b"".join(b"\x00" + rgb[y].tobytes() for y in range(h))
    def chunk(kind, data):
        return struct.pack(">I", len(data)) + kind + data + struct.pack(">I", zlib.crc32(kind + data) & 0xFFFFFFFF)
    with open(path, "wb") as f:
        f.write(b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", w, h, 8, 2, 0, 0, 0)) +
                chunk(b"IDAT", zlib.compress(raw, 9)) + chunk(b"IEND", b""))


def colour(t):
    """0 blue, 0.5 green, 1 red."""
    t = np.clip(t, 0, 1)
    return np.stack([np.clip(2 * t - 1, 0, 1), 1 - np.abs(2 * t - 1), np.clip(1 - 2 * t, 0, 1)], axis=-1)


def main():
    surface, size, out = sys.argv[1], float(sys.argv[2]), sys.argv[3]
    width = int(sys.argv[4]) if len(sys.argv) > 4 else 1000
    m = meshio.read(surface)
    p, tri = m.points, m.cells_dict["triangle"]
    # The faces facing up, within 25 degrees of the view (the walls' edges would overlap in it).
    n = np.cross(p[tri[:, 1]] - p[tri[:, 0]], p[tri[:, 2]] - p[tri[:, 0]])
    tri = tri[n[:, 2] > 0.9 * np.linalg.norm(n, axis=1)]
    edges = np.unique(np.sort(np.concatenate([tri[:, [0, 1]], tri[:, [1, 2]], tri[:, [2, 0]]]), axis=1), axis=0)
    lo, hi = p[:, :2].min(axis=0), p[:, :2].max(axis=0)
    margin = 0.03 * (hi - lo).max()
    scale = (width - 1) / (hi[0] - lo[0] + 2 * margin)
    height = int((hi[1] - lo[1] + 2 * margin) * scale) + 1
    image = np.full((height, width, 3), 255, np.uint8)
    for a, b in edges:
        length = np.linalg.norm(p[a] - p[b])
        steps = int(np.linalg.norm(p[a, :2] - p[b, :2]) * scale * 2) + 2
        s = np.linspace(0, 1, steps)[:, None]
        xy = ((p[a, :2] * (1 - s) + p[b, :2] * s) - lo + margin) * scale
        x, y = xy[:, 0].astype(int), (height - 1 - xy[:, 1]).astype(int)
        image[y, x] = (255 * colour(length / size)).astype(np.uint8)
    png(out, image)


if __name__ == "__main__":
    main()
