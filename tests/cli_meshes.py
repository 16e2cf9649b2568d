#!/usr/bin/env python3
"""Writes the small OFF meshes the CLI test scripts use, into the current folder.

Usage: cli_meshes.py NAME...   (NAME.off is written for each)
  cube       the closed unit cube, 12 triangles, outward
  open_box   the cube without its top
  two_boxes  two interpenetrating cubes (self-intersections)
  duplicate  the cube with one face twice
  fin        the cube with a fin on an edge (a non-manifold edge)
  split_cube the cube with every face corner its own vertex (as VTK's normals filter writes it)
  terrain    an 8 x 8 grid on z = 0.3 sin(x) cos(y) (an open height field, one boundary loop)
  holed      a 4 x 4 grid without its middle 2 x 2 cells (two boundary loops)
  sliver     a closed tet of 4 triangles whose smallest dihedral angle is 2.005 degrees (largest
             177.2): (0,0,0), (1,1,0), (0,1,h), (1,0,h), h = 0.0175 (tet_quality_test's SliverByHand)
  plate      the cube scaled to 100 x 100 x 0.05 (a sheet part thinner than the weld distance)
  double_sided the cube with every face listed twice, once per orientation
  collapsed  50 faces whose three corners are one point each (zero area)
  ridge      the cube with its top's diagonal (1,0,1)-(0,1,1) raised by 1e-4: its two top triangles
             meet at 179.98 degrees, within TetGen's 0.1-degree facet tolerance
  wavy       two sheets z = 0.3 sin 3x cos 2y over [0, 3]^2, 0.002 apart, 16 x 16 squares each,
             closed by a rim (test_meshes.h: thin_wavy_plate): a remeshing pierces one sheet with the other
"""
import math
import sys

P = [(x, y, z) for z in (0, 1) for y in (0, 1) for x in (0, 1)]
T = [(0,2,1),(1,2,3),(4,5,6),(5,7,6),(0,1,4),(1,5,4),(2,6,3),(3,6,7),(0,4,2),(2,4,6),(1,3,5),(3,7,5)]


def grid(n, height, skip=()):
    pts = [(float(i), float(j), height(i, j)) for j in range(n + 1) for i in range(n + 1)]
    tris = []
    for j in range(n):
        for i in range(n):
            if (i, j) in skip:
                continue
            a, b, c, d = j * (n + 1) + i, j * (n + 1) + i + 1, (j + 1) * (n + 1) + i + 1, (j + 1) * (n + 1) + i
            tris += [(a, b, c), (a, c, d)]
    return pts, tris


def wavy_plate(n, gap):
    pts = [(3.0 * i / n, 3.0 * j / n, 0.3 * math.sin(9.0 * i / n) * math.cos(6.0 * j / n) + sheet * gap)
           for sheet in (0, 1) for j in range(n + 1) for i in range(n + 1)]
    def at(sheet, i, j):
        return sheet * (n + 1) * (n + 1) + j * (n + 1) + i
    tris = []
    for j in range(n):
        for i in range(n):
            tris += [(at(0, i, j), at(0, i + 1, j + 1), at(0, i + 1, j)), (at(0, i, j), at(0, i, j + 1), at(0, i + 1, j + 1)),
                     (at(1, i, j), at(1, i + 1, j), at(1, i + 1, j + 1)), (at(1, i, j), at(1, i + 1, j + 1), at(1, i, j + 1))]
    rim = ([(i, 0) for i in range(n)] + [(n, j) for j in range(n)] + [(i, n) for i in range(n, 0, -1)] +
           [(0, j) for j in range(n, 0, -1)])
    for k, (i0, j0) in enumerate(rim):
        i1, j1 = rim[(k + 1) % len(rim)]
        tris += [(at(0, i0, j0), at(0, i1, j1), at(1, i1, j1)), (at(0, i0, j0), at(1, i1, j1), at(1, i0, j0))]
    return pts, tris


def meshes():
    Q = [(x + 0.5, y + 0.25, z + 0.3) for (x, y, z) in P]
    return {
        "cube": (P, T),
        "open_box": (P, [t for t in T if t not in ((4, 5, 6), (5, 7, 6))]),
        "two_boxes": (P + Q, T + [tuple(i + 8 for i in t) for t in T]),
        "duplicate": (P, T + [T[3]]),
        "fin": (P + [(0.5, 0.5, -1.0)], T + [(0, 1, 8)]),
        "split_cube": ([P[i] for t in T for i in t], [(3 * k, 3 * k + 1, 3 * k + 2) for k in range(len(T))]),
        "terrain": grid(8, lambda i, j: 0.3 * math.sin(i) * math.cos(j)),
        "holed": grid(4, lambda i, j: 0.0, skip={(1, 1), (2, 1), (1, 2), (2, 2)}),
        "sliver": ([(0.0, 0.0, 0.0), (1.0, 1.0, 0.0), (0.0, 1.0, 0.0175), (1.0, 0.0, 0.0175)],
                   [(1, 2, 3), (0, 3, 2), (0, 1, 3), (0, 2, 1)]),
        "plate": ([(100.0 * x, 100.0 * y, 0.05 * z) for (x, y, z) in P], T),
        "double_sided": (P, T + [(a, c, b) for (a, b, c) in T]),
        "collapsed": ([(float(k), 0.0, 0.0) for k in range(50) for _ in range(3)],
                      [(3 * k, 3 * k + 1, 3 * k + 2) for k in range(50)]),
        "wavy": wavy_plate(16, 0.002),
        "ridge": ([(x, y, z + (1e-4 if z == 1 and x + y == 1 else 0)) for (x, y, z) in P], T),
    }


def main(names):
    known = meshes()
    for name in names:
        if name not in known:
            sys.exit(f"cli_meshes.py: unknown mesh '{name}'; known: {', '.join(known)}")
        pts, tris = known[name]
        with open(name + ".off", "w") as f:
            f.write(f"OFF\n{len(pts)} {len(tris)} 0\n")
            for p in pts:
                f.write("%r %r %r\n" % p)
            for t in tris:
                f.write("3 %d %d %d\n" % t)


if __name__ == "__main__":
    main(sys.argv[1:])
