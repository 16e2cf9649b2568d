#!/usr/bin/env python3
"""Checks the node order of second-order tet meshes with third-party readers.

Usage: p2_readback.py DIR TETS

Every .msh .vtu .vtk .inp .xdmf file in DIR is read with meshio, every .mesh (Medit TetrahedraP2,
which meshio 5 does not read) is first converted to .vtk by Gmsh when it is on PATH. Each must hold
TETS cells of type "tetra10" (meshio's order: VTK's, into which its Gmsh reader permutes type 11)
whose nodes 4-9 lie at the midpoints of the edges (0,1) (1,2) (2,0) (0,3) (1,3) (2,3), every tet
positively oriented; "triangle6" cells, where a file has them, must have nodes 3-5 at the midpoints
of (0,1) (1,2) (2,0). The meshes must be straight (every mid-edge node at its midpoint): the edge
each node sits on is then known from the geometry alone, whatever program wrote it.

Prints one line per file; exits 1 if any file fails, 2 on bad usage.
"""
import pathlib
import shutil
import subprocess
import sys
import tempfile

import meshio
import numpy as np

from fem_readback import read_xdmf_grid  # meshio reads one XDMF grid at a time


FORMATS = {".msh": "gmsh", ".vtu": "vtu", ".vtk": "vtk", ".inp": "abaqus", ".xdmf": "xdmf"}
XDMF_GRIDS = ("mesh", "cell_tags", "facet_tags")  # what export_xdmf.cpp writes, as dolfinx does
TET_EDGES = [(0, 1), (1, 2), (2, 0), (0, 3), (1, 3), (2, 3)]  # vtkQuadraticTetra
TRIANGLE_EDGES = [(0, 1), (1, 2), (2, 0)]  # vtkQuadraticTriangle
RELATIVE_TOLERANCE = 1e-9  # of the edge's length: the files hold the coordinates to 17 digits


def midpoint_errors(points, cells, edges, first_node):
    """The largest distance of each cell's mid-edge nodes from their edges' midpoints, over the edge's length."""
    worst = 0.0
    for k, (a, b) in enumerate(edges):
        pa, pb, node = points[cells[:, a]], points[cells[:, b]], points[cells[:, first_node + k]]
        length = np.linalg.norm(pb - pa, axis=1)
        worst = max(worst, float(np.max(np.linalg.norm(node - 0.5 * (pa + pb), axis=1) / length)))
    return worst


def check(mesh, tets):
    blocks = {block.type: block.data for block in mesh.cells}
    if "triangle6" in blocks and "tetra10" not in blocks:  # an XDMF file's facet_tags grid
        error = midpoint_errors(mesh.points, blocks["triangle6"], TRIANGLE_EDGES, 3)
        return None if error <= RELATIVE_TOLERANCE else "a triangle's mid-edge node is %.3g edge lengths off" % error
    if "tetra10" not in blocks:
        return "no tetra10 cells (cell types: %s)" % ", ".join(blocks)
    cells = np.vstack([block.data for block in mesh.cells if block.type == "tetra10"])
    if len(cells) != tets:
        return "%d tetra10 cells, expected %d" % (len(cells), tets)
    p = mesh.points
    volumes = np.einsum("ij,ij->i", p[cells[:, 1]] - p[cells[:, 0]],
                        np.cross(p[cells[:, 2]] - p[cells[:, 0]], p[cells[:, 3]] - p[cells[:, 0]]))
    if np.any(volumes <= 0):
        return "%d tets not positively oriented" % int(np.sum(volumes <= 0))
    error = midpoint_errors(p, cells, TET_EDGES, 4)
    if error > RELATIVE_TOLERANCE:
        return "a tet's mid-edge node is %.3g edge lengths off its edge's midpoint: another node order" % error
    if "triangle6" in blocks:
        error = midpoint_errors(p, blocks["triangle6"], TRIANGLE_EDGES, 3)
        if error > RELATIVE_TOLERANCE:
            return "a triangle's mid-edge node is %.3g edge lengths off its edge's midpoint" % error
    return None


def read(path, scratch):
    """The meshes of the file, as (name, meshio mesh)."""
    if path.suffix == ".xdmf":
        return [(path.name + ":" + grid, read_xdmf_grid(path, grid)) for grid in XDMF_GRIDS]
    if path.suffix == ".mesh":
        converted = scratch / (path.stem + "_from_medit.vtk")
        subprocess.run(["gmsh", str(path), "-o", str(converted), "-save", "-v", "0"], check=True,
                       stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
        return [(path.name, meshio.read(converted, file_format="vtk"))]
    return [(path.name, meshio.read(path, file_format=FORMATS[path.suffix]))]


def main():
    if len(sys.argv) != 3:
        print(__doc__, file=sys.stderr)
        return 2
    directory, tets = pathlib.Path(sys.argv[1]), int(sys.argv[2])
    failed = False
    with tempfile.TemporaryDirectory() as scratch:
        for path in sorted(directory.iterdir()):
            if path.suffix not in FORMATS and path.suffix != ".mesh":
                continue
            if path.suffix == ".mesh" and not shutil.which("gmsh"):
                print("%s: skipped (no gmsh to convert Medit's TetrahedraP2)" % path.name)
                continue
            for name, mesh in read(path, pathlib.Path(scratch)):
                problem = check(mesh, tets)
                print("%s: %s" % (name, problem or "ok"))
                failed = failed or problem is not None
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
