#!/usr/bin/env python3
"""Reads every tetrahedral mesh file in a directory back with third-party readers.

Usage: fem_readback.py DIR POINTS TETS VOLUME

Each file is read with meshio (.msh 4.1/2.2 ASCII and binary, .vtu, .vtk, .mesh, .inp, .node with
its .ele sibling) and must have POINTS points, TETS cells of type "tetra", every tet positively
oriented and a total signed volume equal to VOLUME (relative tolerance 1e-9). .msh files are also
checked by Gmsh itself (`gmsh FILE -check`): exit code 0, no warning or error, and the node and
element counts it prints must match. .ele and .face files are covered by their .node file.

Prints one line per file; exits 1 if any file fails (with the reason), 2 on bad usage.
"""
import pathlib
import re
import subprocess
import sys

import meshio
import numpy as np

# Explicit meshio formats: from the extension alone meshio also tries other readers for .msh
# (ANSYS), prints their errors and calls sys.exit when none succeeds.
MESHIO_FORMATS = {
    ".msh": "gmsh",
    ".vtu": "vtu",
    ".vtk": "vtk",
    ".mesh": "medit",
    ".inp": "abaqus",
    ".node": "tetgen",
}
SIBLINGS = {".ele", ".face"}  # read through the .node file
RELATIVE_TOLERANCE = 1e-9


class Failure(Exception):
    pass


def signed_volumes(points, tets):
    p0, p1, p2, p3 = (points[tets[:, k]] for k in range(4))
    return np.einsum("ij,ij->i", p1 - p0, np.cross(p2 - p0, p3 - p0)) / 6.0


def check_with_meshio(path, file_format, num_points, num_tets, volume):
    """Returns the number of cells of every type (for the Gmsh comparison) and a summary."""
    try:
        mesh = meshio.read(path, file_format=file_format)
    except Exception as error:  # meshio raises ReadError, ValueError, KeyError, ...
        raise Failure(f"meshio cannot read it: {type(error).__name__}: {error}") from error
    if len(mesh.points) != num_points:
        raise Failure(f"meshio reads {len(mesh.points)} points, expected {num_points}")
    blocks = [block.data for block in mesh.cells if block.type == "tetra"]
    tets = np.vstack(blocks) if blocks else np.empty((0, 4), dtype=int)
    if len(tets) != num_tets:
        types = sorted({block.type for block in mesh.cells})
        raise Failure(f"meshio reads {len(tets)} tetra cells (cell types {types}), expected {num_tets}")
    volumes = signed_volumes(np.asarray(mesh.points, dtype=float), tets)
    if np.any(volumes <= 0):
        raise Failure(f"{int(np.sum(volumes <= 0))} tets are not positively oriented")
    total = float(np.sum(volumes))
    if abs(total - volume) > RELATIVE_TOLERANCE * abs(volume):
        raise Failure(f"total volume {total!r}, expected {volume!r}")
    num_cells = sum(len(block.data) for block in mesh.cells)
    return num_cells, f"meshio ok: {len(mesh.points)} points, {len(tets)} tets, volume {total:.12g}"


def check_with_gmsh(path, num_points, num_cells):
    command = ["gmsh", str(path), "-check", "-nopopup"]
    try:
        run = subprocess.run(command, capture_output=True, text=True, timeout=120)
    except (OSError, subprocess.TimeoutExpired) as error:
        raise Failure(f"cannot run {' '.join(command)}: {error}") from error
    output = run.stdout + run.stderr
    problems = [line for line in output.splitlines() if line.startswith(("Warning", "Error"))]
    if run.returncode != 0 or problems:
        raise Failure(f"gmsh -check exit code {run.returncode}: {'; '.join(problems) or output.strip()}")
    counts = {"nodes": num_points, "elements": num_cells}
    for what, expected in counts.items():
        printed = re.findall(rf"^Info\s*:\s*(\d+) {what}$", output, re.MULTILINE)
        if not printed:
            raise Failure(f"gmsh -check did not print the number of {what}: {output.strip()}")
        if int(printed[0]) != expected:
            raise Failure(f"gmsh reads {printed[0]} {what}, expected {expected}")
    return f"gmsh ok: {num_points} nodes, {num_cells} elements"


def check_file(path, num_points, num_tets, volume):
    suffix = path.suffix.lower()
    if suffix in SIBLINGS:
        if not path.with_suffix(".node").exists():
            raise Failure("no .node file beside it")
        return "read with its .node file"
    if suffix not in MESHIO_FORMATS:
        raise Failure(f"no read-back check for '{suffix}' files")
    num_cells, summary = check_with_meshio(path, MESHIO_FORMATS[suffix], num_points, num_tets, volume)
    if suffix == ".msh":
        summary += "; " + check_with_gmsh(path, num_points, num_cells)
    return summary


def main(argv):
    if len(argv) != 5:
        print(__doc__, file=sys.stderr)
        return 2
    directory = pathlib.Path(argv[1])
    num_points, num_tets, volume = int(argv[2]), int(argv[3]), float(argv[4])
    files = sorted(p for p in directory.iterdir() if p.is_file())
    if not files:
        print(f"FAIL {directory}: no files", file=sys.stderr)
        return 1
    failures = 0
    for path in files:
        try:
            print(f"ok   {path.name}: {check_file(path, num_points, num_tets, volume)}")
        except Failure as failure:
            failures += 1
            print(f"FAIL {path.name}: {failure}")
    print(f"{len(files) - failures} of {len(files)} files ok (meshio {meshio.__version__})")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
