#!/usr/bin/env python3
"""Reads every tetrahedral mesh file in a directory back with third-party readers.

Usage: fem_readback.py DIR POINTS TETS VOLUME

Each file is read with meshio (.msh 4.1/2.2 ASCII and binary, .vtu, .vtk, .mesh, .inp, .node with
its .ele sibling, .xdmf with its .h5: each of its grids, see read_xdmf_grid) and must have POINTS points, TETS cells of type "tetra", every tet positively
oriented and a total signed volume equal to VOLUME (relative tolerance 1e-9). .vtu and .vtk files
must carry the cell data "region" and the per-tet quality min_dihedral_deg, max_dihedral_deg,
radius_edge_ratio and scaled_jacobian, equal to the values computed here independently (dihedral
angles from the two faces' directions normal to each edge, the circumcentre from its linear system,
Verdict's scaled Jacobian from each corner's edges), to the Float32 rounding the files hold them in. .msh files are also checked by Gmsh itself (`gmsh FILE -check`): exit code 0, no warning or error, and the node and
element counts it prints must match. An .xdmf's tag grids must hold one tag per cell. .ele and .face files are covered by their .node file.
A .vtu's boundary-faces file X_boundary.vtu (beside X.vtu) must hold triangles only, each an outward
face of one tet of X.vtu, on the points of X.vtu that its point data "mesh_point_id"
names, with one cell data "patch" value per triangle and its field data naming the patches as
[tag, 2]; an empty one is checked by its header alone (meshio reads no grid without cells).

Prints one line per file; exits 1 if any file fails (with the reason), 2 on bad usage.
"""
import copy
import itertools
import pathlib
import re
import subprocess
import sys
import tempfile
import xml.etree.ElementTree as ET

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
    ".xdmf": "xdmf",
}
SIBLINGS = {".ele": ".node", ".face": ".node", ".h5": ".xdmf"}  # read through the other file
RELATIVE_TOLERANCE = 1e-9
QUALITY_ARRAYS = ("min_dihedral_deg", "max_dihedral_deg", "radius_edge_ratio", "scaled_jacobian")
# Differences of the two computations' round-off (their inputs are the same doubles): angles to
# 1e-9 degree, ratios to 1e-9 relative (the circumcentre's 3x3 solve is the least accurate part).
QUALITY_TOLERANCE = 1e-9
# The files hold the quality as Float32: rounded to nearest, each value is off by at most half a
# unit in its last place, 2^-24 of the value (IEEE 754 binary32 has 24 significant bits).
FLOAT32_ROUNDING = 2.0 ** -24


class Failure(Exception):
    pass


def signed_volumes(points, tets):
    p0, p1, p2, p3 = (points[tets[:, k]] for k in range(4))
    return np.einsum("ij,ij->i", p1 - p0, np.cross(p2 - p0, p3 - p0)) / 6.0


def norms(vectors):
    return np.linalg.norm(vectors, axis=1)


def expected_quality(points, tets):
    """Per-tet quality, computed another way than meshprep's (which uses the faces' normals)."""
    p = [points[tets[:, k]] for k in range(4)]
    dihedral = []
    for i, j in itertools.combinations(range(4), 2):
        k, l = (m for m in range(4) if m not in (i, j))
        edge = (p[j] - p[i]) / norms(p[j] - p[i])[:, None]
        u, v = p[k] - p[i], p[l] - p[i]
        u = u - np.einsum("ij,ij->i", u, edge)[:, None] * edge  # towards k, normal to the edge
        v = v - np.einsum("ij,ij->i", v, edge)[:, None] * edge
        dihedral.append(np.degrees(np.arctan2(norms(np.cross(u, v)), np.einsum("ij,ij->i", u, v))))
    dihedral = np.array(dihedral)
    # Circumcentre c: 2 (p_m - p_0) . c = |p_m|^2 - |p_0|^2, m = 1, 2, 3 (relative to p_0).
    rows = np.stack([p[m] - p[0] for m in (1, 2, 3)], axis=1)
    centre = np.linalg.solve(2 * rows, np.einsum("imj,imj->im", rows, rows)[:, :, None])[:, :, 0]
    lengths = {(a, b): norms(p[b] - p[a]) for a, b in itertools.combinations(range(4), 2)}
    shortest = np.min(np.array(list(lengths.values())), axis=0)
    jacobian = np.einsum("ij,ij->i", p[1] - p[0], np.cross(p[2] - p[0], p[3] - p[0]))
    corners = [np.prod([lengths[tuple(sorted((c, m)))] for m in range(4) if m != c], axis=0) for c in range(4)]
    scaled = np.min([np.sqrt(2.0) * jacobian / product for product in corners], axis=0)  # positive tets
    return {"min_dihedral_deg": dihedral.min(axis=0), "max_dihedral_deg": dihedral.max(axis=0),
            "radius_edge_ratio": norms(centre) / shortest, "scaled_jacobian": scaled}


def check_cell_quality(mesh, points, tets):
    """The VTK files' cell data: the region and the four quality arrays, one value per tet."""
    for name in ("region",) + QUALITY_ARRAYS:
        if name not in mesh.cell_data:
            raise Failure(f"no cell data '{name}' (has {sorted(mesh.cell_data)})")
        if sum(len(block) for block in mesh.cell_data[name]) != len(tets):
            raise Failure(f"cell data '{name}' has {sum(len(b) for b in mesh.cell_data[name])} values for {len(tets)} tets")
    expected = expected_quality(points, tets)
    for name in QUALITY_ARRAYS:
        # meshio gives legacy VTK scalars as (n, 1) columns, XML arrays as (n,).
        written = np.concatenate([np.asarray(block, dtype=float).reshape(-1) for block in mesh.cell_data[name]])
        scale = 1.0 if name.endswith("_deg") or name == "scaled_jacobian" else np.abs(expected[name])
        allowed = QUALITY_TOLERANCE * scale + FLOAT32_ROUNDING * np.abs(expected[name])
        worst = np.max(np.abs(written - expected[name]) / np.maximum(allowed, 1e-300))
        if not worst <= 1:
            raise Failure(f"cell data '{name}' differs from the tets' own by {worst:.3g} times the tolerance")


XINCLUDE = "{http://www.w3.org/2001/XInclude}include"


def read_xdmf_grid(path, grid_name):
    """One grid of an XDMF file, read by meshio.

    meshio (5.0 and later) reads XDMF files of one grid only ("Only supports one grid right now");
    the layout dolfinx writes, and meshprep with it, has three: "mesh", "facet_tags", "cell_tags".
    So meshio reads a copy of the file that holds the grid alone, with the XInclude of the mesh's
    geometry replaced by that geometry, without its <Information> elements (meshprep's tag names,
    which meshio would parse as its own field data), and with its HDF5 paths made absolute.
    """
    path = pathlib.Path(path).resolve()
    tree = ET.parse(path)
    domain = tree.getroot().find("Domain")
    grids = {grid.get("Name"): grid for grid in domain.findall("Grid")}
    if grid_name not in grids:
        raise Failure(f"no grid named {grid_name!r} (grids {sorted(grids)})")
    grid = grids[grid_name]
    for child in list(grid):
        if child.tag == XINCLUDE:  # xpointer(/Xdmf/Domain/Grid/Geometry): the first grid's
            grid.insert(list(grid).index(child), copy.deepcopy(domain.find("Grid").find("Geometry")))
            grid.remove(child)
        elif child.tag == "Information":
            grid.remove(child)
    for other in list(domain):
        if other is not grid:
            domain.remove(other)
    for item in grid.iter("DataItem"):
        if item.get("Format") == "HDF":
            file, dataset = item.text.strip().rsplit(":", 1)
            item.text = f"{path.parent / file}:{dataset}"
    with tempfile.TemporaryDirectory() as folder:
        alone = pathlib.Path(folder) / path.name
        tree.write(alone)
        return meshio.read(alone, file_format="xdmf")


def check_xdmf_tags(path, num_tets):
    """The tag grids: one value per cell, the cell tags one per tet."""
    counts = []
    for name, cell_type in (("facet_tags", "triangle"), ("cell_tags", "tetra")):
        mesh = read_xdmf_grid(path, name)
        cells = sum(len(block.data) for block in mesh.cells if block.type == cell_type)
        values = sum(len(block) for block in mesh.cell_data.get(name, []))
        if values != cells:
            raise Failure(f"grid {name}: {values} tags for {cells} {cell_type} cells")
        counts.append(cells)
    if counts[1] != num_tets:
        raise Failure(f"grid cell_tags: {counts[1]} tets, expected {num_tets}")
    return f"{counts[0]} facet tags, {counts[1]} cell tags"


def check_with_meshio(path, file_format, num_points, num_tets, volume):
    """Returns the number of cells of every type (for the Gmsh comparison) and a summary."""
    try:
        if file_format == "xdmf":
            mesh = read_xdmf_grid(path, "mesh")
        else:
            mesh = meshio.read(path, file_format=file_format)
    except Failure:
        raise
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
    summary = f"meshio ok: {len(mesh.points)} points, {len(tets)} tets, volume {total:.12g}"
    if file_format in ("vtu", "vtk"):
        check_cell_quality(mesh, np.asarray(mesh.points, dtype=float), tets)
        summary += ", per-tet quality as cell data"
    return num_cells, summary


def boundary_sibling_of(path):
    """X.vtu for X_boundary.vtu when X.vtu exists, else None."""
    if path.suffix.lower() != ".vtu" or not path.stem.endswith("_boundary"):
        return None
    tets_file = path.with_name(path.stem[: -len("_boundary")] + path.suffix)
    return tets_file if tets_file.exists() else None


def outward_tet_faces(tets):
    """The faces of one tet each, oriented away from it: sorted corners -> oriented corners."""
    count, oriented = {}, {}
    for tet in tets:
        for k in range(4):
            face = tuple(int(tet[(k + m) % 4]) for m in (1, 2, 3))
            # In a positive tet (0 1 2 3), 0 1 2 turns right-handed towards 3: the faces opposite
            # corners 0 and 2, (1 2 3) and (3 0 1), turn outward, those opposite 1 and 3 inward.
            if k % 2 == 1:
                face = (face[0], face[2], face[1])
            key = tuple(sorted(face))
            count[key] = count.get(key, 0) + 1
            oriented[key] = face
    return {key: oriented[key] for key, n in count.items() if n == 1}


def same_rotation(a, b):
    """Whether triangle b is triangle a started at another corner (the same orientation)."""
    return any(tuple(a[(k + m) % 3] for m in range(3)) == tuple(b) for k in range(3))


def check_boundary_vtu(path, tets_file):
    """X_boundary.vtu against X.vtu (see the module's doc)."""
    cells = re.search(rb'NumberOfCells="(\d+)"', path.read_bytes()[:4096])
    if cells is None:
        raise Failure("no NumberOfCells in its <Piece>")
    if int(cells.group(1)) == 0:
        return "no boundary faces (an empty grid: meshio reads none)"
    tets_mesh = meshio.read(tets_file, file_format="vtu")
    points = np.asarray(tets_mesh.points, dtype=float)
    faces = outward_tet_faces(np.vstack([b.data for b in tets_mesh.cells if b.type == "tetra"]))
    try:
        mesh = meshio.read(path, file_format="vtu")
    except Exception as error:
        raise Failure(f"meshio cannot read it: {type(error).__name__}: {error}") from error
    if any(block.type != "triangle" for block in mesh.cells):
        raise Failure(f"cell types {sorted({b.type for b in mesh.cells})}, expected triangles only")
    triangles = np.vstack([block.data for block in mesh.cells])
    ids = np.asarray(mesh.point_data.get("mesh_point_id", np.empty(0)), dtype=np.int64).reshape(-1)
    if len(ids) != len(mesh.points):
        raise Failure(f"{len(ids)} mesh_point_id values for {len(mesh.points)} points")
    if np.any(ids < 0) or np.any(ids >= len(points)) or not np.array_equal(mesh.points, points[ids]):
        raise Failure(f"its points are not the points of {tets_file.name} that mesh_point_id names")
    patches = np.concatenate([np.asarray(b).reshape(-1) for b in mesh.cell_data.get("patch", [])] or [np.empty(0)])
    if len(patches) != len(triangles) or np.any(patches < 1):
        raise Failure(f"{len(patches)} patch values (each >= 1) for {len(triangles)} triangles")
    for triangle in ids[triangles]:
        face = faces.get(tuple(sorted(int(v) for v in triangle)))
        if face is None or not same_rotation(face, [int(v) for v in triangle]):
            raise Failure(f"triangle {list(triangle)} is not an outward face of one tet of {tets_file.name}")
    named = {int(value.reshape(-1)[0]) for value in mesh.field_data.values() if value.reshape(-1)[1] == 2}
    if named != {int(tag) for tag in patches}:
        raise Failure(f"field data names the patches {sorted(named)}, the triangles have {sorted(set(patches))}")
    return f"meshio ok: {len(triangles)} outward boundary faces of {tets_file.name}, {len(named)} named patches"


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
        if not path.with_suffix(SIBLINGS[suffix]).exists():
            raise Failure(f"no {SIBLINGS[suffix]} file beside it")
        return f"read with its {SIBLINGS[suffix]} file"
    tets_file = boundary_sibling_of(path)
    if tets_file is not None:
        return check_boundary_vtu(path, tets_file)
    if suffix not in MESHIO_FORMATS:
        raise Failure(f"no read-back check for '{suffix}' files")
    num_cells, summary = check_with_meshio(path, MESHIO_FORMATS[suffix], num_points, num_tets, volume)
    if suffix == ".msh":
        summary += "; " + check_with_gmsh(path, num_points, num_cells)
    if suffix == ".xdmf":
        summary += " (grid mesh); " + check_xdmf_tags(path, num_tets)
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
