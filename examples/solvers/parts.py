#!/usr/bin/env python3
"""The parts of the solver examples, as OBJ files whose groups name their faces.

Usage: parts.py beam|box OUT.obj
       parts.py cylinder OUT.obj SEGMENTS

beam  [0, 20] x [0, 1] x [0, 1]: a cantilever (length / height 20). Patches: fixed (x = 0),
      free (x = 20), loaded (y = 1, the top), bottom (y = 0), sides (z = 0 and z = 1).
box   [0, 2] x [0, 1] x [0, 1]: the Poisson example's part. Patches: fixed (x = 0), and walls.
cylinder  radius 0.5, axis z from 0 to 1, its circles as SEGMENTS-gons (SEGMENTS a multiple of 6;
      every vertex on the cylinder), the side in rings about as tall as a segment is long, the caps
      in concentric rings as well. Patches: fixed (z = 0), walls (the side and z = 1).

meshprep keeps an OBJ's groups as named boundary patches (docs/formats.md): the solver decks and
scripts find the faces to fix or load by these names.
"""
import math
import sys


def box_obj(path, size, names):
    """A box [0, size] as 12 outward triangles, grouped by names[side], side in
    (x0, x1, y0, y1, z0, z1); sides with the same name share a group."""
    sx, sy, sz = size
    corners = [(x, y, z) for x in (0, sx) for y in (0, sy) for z in (0, sz)]
    index = {corner: i + 1 for i, corner in enumerate(corners)}

    def quad(a, b, c, d):  # counter-clockwise seen from outside
        return [(index[a], index[b], index[c]), (index[a], index[c], index[d])]

    sides = {
        "x0": quad((0, 0, 0), (0, 0, sz), (0, sy, sz), (0, sy, 0)),
        "x1": quad((sx, 0, 0), (sx, sy, 0), (sx, sy, sz), (sx, 0, sz)),
        "y0": quad((0, 0, 0), (sx, 0, 0), (sx, 0, sz), (0, 0, sz)),
        "y1": quad((0, sy, 0), (0, sy, sz), (sx, sy, sz), (sx, sy, 0)),
        "z0": quad((0, 0, 0), (0, sy, 0), (sx, sy, 0), (sx, 0, 0)),
        "z1": quad((0, 0, sz), (sx, 0, sz), (sx, sy, sz), (0, sy, sz)),
    }
    groups = {}
    for side, faces in sides.items():
        groups.setdefault(names[side], []).extend(faces)
    with open(path, "w") as out:
        out.writelines(f"v {x:g} {y:g} {z:g}\n" for x, y, z in corners)
        for name, faces in groups.items():
            out.write(f"g {name}\n")
            out.writelines(f"f {a} {b} {c}\n" for a, b, c in faces)


def disk_triangles(rings):
    """A disk's triangulation whose ring j (of `rings`) has 6 j points at angles 2 pi i / (6 j):
    the centre is point 0, ring j's point i is 1 + 3 j (j - 1) + i. Counter-clockwise seen from +z.
    Two rings are zipped by angle: the next triangle takes whichever ring's next point comes first."""
    def index(j, i):
        return 0 if j == 0 else 1 + 3 * j * (j - 1) + i % (6 * j)

    triangles = [(0, index(1, i), index(1, i + 1)) for i in range(6)]
    for j in range(2, rings + 1):
        inner, outer = 6 * (j - 1), 6 * j
        a = b = 0
        while a < inner or b < outer:
            if b < outer and (a >= inner or (b + 1) / outer <= (a + 1) / inner):
                triangles.append((index(j - 1, a), index(j, b), index(j, b + 1)))
                b += 1
            else:
                triangles.append((index(j - 1, a), index(j, b), index(j - 1, a + 1)))
                a += 1
    return triangles


def cylinder_obj(path, segments, radius=0.5, height=1.0):
    """SEGMENTS, a multiple of 6: each cap is a disk of segments / 6 rings (disk_triangles), its
    edges about as long as the side's."""
    rings = max(1, round(height / (2 * math.pi * radius / segments)))
    disk_rings = segments // 6
    angles = [2 * math.pi * k / segments for k in range(segments)]
    points = [(radius * math.cos(a), radius * math.sin(a), height * r / rings) for r in range(rings + 1) for a in angles]

    def at(ring, k):  # 1-based OBJ index of the side's points
        return ring * segments + k % segments + 1

    side = []
    for r in range(rings):
        for k in range(segments):
            side += [(at(r, k), at(r, k + 1), at(r + 1, k + 1)), (at(r, k), at(r + 1, k + 1), at(r + 1, k))]
    caps = []
    for z, ring in ((0.0, 0), (height, rings)):
        # The disk's own points but its rim, which is the side's ring.
        first = len(points) + 1
        disk = [(0.0, 0.0, z)] + [(radius * j / disk_rings * math.cos(2 * math.pi * i / (6 * j)),
                                   radius * j / disk_rings * math.sin(2 * math.pi * i / (6 * j)), z)
                                  for j in range(1, disk_rings) for i in range(6 * j)]
        points += disk
        rim_start = len(disk)

        def obj_index(d, first=first, rim_start=rim_start, ring=ring):
            return first + d if d < rim_start else at(ring, d - rim_start)

        faces = [tuple(obj_index(d) for d in t) for t in disk_triangles(disk_rings)]
        caps.append(faces if z > 0 else [(a, c, b) for a, b, c in faces])  # the bottom faces down
    with open(path, "w") as out:
        out.writelines(f"v {x!r} {y!r} {z!r}\n" for x, y, z in points)
        for name, faces in (("fixed", caps[0]), ("walls", side + caps[1])):
            out.write(f"g {name}\n")
            out.writelines(f"f {a} {b} {c}\n" for a, b, c in faces)


PARTS = {
    "beam": ((20, 1, 1), {"x0": "fixed", "x1": "free", "y0": "bottom", "y1": "loaded", "z0": "sides", "z1": "sides"}),
    "box": ((2, 1, 1), {"x0": "fixed", "x1": "walls", "y0": "walls", "y1": "walls", "z0": "walls", "z1": "walls"}),
}

if __name__ == "__main__":
    if len(sys.argv) == 4 and sys.argv[1] == "cylinder":
        cylinder_obj(sys.argv[2], int(sys.argv[3]))
    elif len(sys.argv) == 3 and sys.argv[1] in PARTS:
        box_obj(sys.argv[2], *PARTS[sys.argv[1]])
    else:
        sys.exit(__doc__)
