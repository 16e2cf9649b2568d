#!/usr/bin/env python3
"""The share of a tet mesh's edges whose length lies within [0.7, 1.4] x H (a uniform size H),
their median over H, and the tets: the same figures for any tool's tets (meshio reads them).

Usage: size_conformity.py TETS H [LABEL]     (run with /usr/bin/python3: numpy and meshio)
"""
import sys

import meshio
import numpy as np


def main():
    mesh = meshio.read(sys.argv[1])
    h = float(sys.argv[2])
    label = sys.argv[3] if len(sys.argv) > 3 else sys.argv[1]
    tets, p = mesh.cells_dict["tetra"], mesh.points
    edges = np.unique(np.sort(np.concatenate([tets[:, [i, j]] for i in range(4) for j in range(i + 1, 4)]), axis=1), axis=0)
    r = np.linalg.norm(p[edges[:, 0]] - p[edges[:, 1]], axis=1) / h
    print("%-28s %8d tets %8d edges  length/H median %.3f p05 %.3f p95 %.3f  within [0.7, 1.4]: %.1f %%" %
          (label, len(tets), len(r), np.median(r), np.percentile(r, 5), np.percentile(r, 95),
           100 * np.mean((r >= 0.7) & (r <= 1.4))))


if __name__ == "__main__":
    main()
