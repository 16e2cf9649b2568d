"""Every CAD part's patches, in every tet format, read back by Gmsh, meshio, VTK and meshprep (issue 44).

For each part of ../shared/data/cad (binary STL, no names: the patches are found along the sharp
edges), `meshprep pipeline --no-improve` writes its tets as part.msh (a raw CAD export can crash
TetGen, animation.stl does: the pipeline's enhancement gives it a surface TetGen takes; the tets'
quality is not the point here); `meshprep convert` writes them again in every
format; then each file is read back and must hold the tets and the patches of part.msh, as
`meshprep quality --json` counts them there (faces_per_tag, faces_per_patch by name):
- meshprep's own readers (`meshprep quality FILE --json`): the same tets; the same faces per tag in
  every format that stores boundary tags, and per name in those that store names (.msh, .xdmf,
  .vtu);
- meshio: the same tets; the boundary faces per tag (.msh physical tags, Medit references, the
  XDMF facet tags, the .vtu boundary file's `patch`), the patches' node sets by name in .inp;
- Gmsh (its Python API) for the .msh files: one named physical surface per patch with its faces,
  and the part as a physical volume;
- VTK (vtkXMLUnstructuredGridReader, vtkUnstructuredGridReader): the tets of .vtu and .vtk, and the
  patch array of the .vtu's boundary file.
Then a multi-solid ASCII STL and an OBJ with groups keep their names through tetrahedralize.

Skipped when ../shared/data/cad is missing (a fresh clone: the data lives beside it in CI), or when
a reader is not installed (python3-meshio, python3-gmsh, python3-vtk9).
"""
import collections
import json
import os
import pathlib
import subprocess
import sys

import numpy as np
import pytest

meshio = pytest.importorskip("meshio", reason="meshio is not importable (apt-get install python3-meshio)")
gmsh = pytest.importorskip("gmsh", reason="gmsh is not importable (apt-get install python3-gmsh)")
vtk = pytest.importorskip("vtk", reason="vtk is not importable (apt-get install python3-vtk9)")
from vtk.util.numpy_support import vtk_to_numpy  # noqa: E402

gmsh.initialize()
gmsh.option.setNumber("General.Verbosity", 0)

TESTS = pathlib.Path(__file__).resolve().parents[1]
sys.path.insert(0, str(TESTS))
from fem_readback import read_xdmf_grid  # noqa: E402

BINARY = os.environ.get("MESHPREP_BIN", str(TESTS.parent / "build" / "bin" / "meshprep"))
CAD = pathlib.Path(os.environ.get("MESHPREP_SHARED_DATA", TESTS.parents[1] / "shared" / "data")) / "cad"
PARTS = sorted(CAD.glob("*.stl"))

# Each format's file and convert flags; what it stores: tags, names.
FORMATS = {
    "msh 4.1": ("part.msh", [], True, True),
    "msh 2.2": ("part22.msh", ["--msh-version", "2.2"], True, True),
    "msh binary": ("partb.msh", ["--binary"], True, True),
    "vtu": ("part.vtu", [], True, True),
    "vtk": ("part.vtk", [], False, False),
    "mesh": ("part.mesh", [], True, False),
    "inp": ("part.inp", [], True, True),
    "node": ("part.node", [], True, False),
    "xdmf": ("part.xdmf", [], True, True),
}
MESHIO_FORMATS = {".msh": "gmsh", ".vtu": "vtu", ".vtk": "vtk", ".mesh": "medit", ".inp": "abaqus", ".node": "tetgen"}


def meshprep(*args, allowed=(0,)):
    run = subprocess.run([BINARY, *map(str, args)], capture_output=True, text=True, timeout=600)
    assert run.returncode in allowed, f"meshprep {' '.join(map(str, args))}: exit {run.returncode}\n{run.stderr}"
    return run


def our_reading(path):
    report = json.loads(meshprep("quality", path, "--json", "-").stdout)
    return report["tet_quality"]["tetrahedra"], report["boundary"]


def counts(values):
    return {int(k): int(v) for k, v in collections.Counter(np.asarray(values).ravel().tolist()).items()}


def meshio_tets_and_tags(path):
    """The tets and the boundary faces per tag meshio reads (None where meshio has no tags)."""
    if path.suffix == ".xdmf":
        tets = sum(len(block.data) for block in read_xdmf_grid(path, "mesh").cells if block.type == "tetra")
        facets = read_xdmf_grid(path, "facet_tags")
        return tets, counts(facets.cell_data["facet_tags"][0])
    mesh = meshio.read(path, file_format=MESHIO_FORMATS[path.suffix])
    tets = sum(len(block.data) for block in mesh.cells if block.type == "tetra")
    key = {".msh": "gmsh:physical", ".mesh": "medit:ref"}.get(path.suffix)
    if key is None:
        return tets, None
    tags = collections.Counter()
    for block, values in zip(mesh.cells, mesh.cell_data[key]):
        if block.type == "triangle":
            tags.update(counts(values))
    return tets, dict(tags)


def gmsh_physical_groups(path):
    """{name: (dimension, element count)} of a .msh file's physical groups, read by Gmsh."""
    gmsh.clear()
    gmsh.open(str(path))
    groups = {}
    for dim, tag in gmsh.model.getPhysicalGroups():
        elements = 0
        for entity in gmsh.model.getEntitiesForPhysicalGroup(dim, tag):
            for tags in gmsh.model.mesh.getElements(dim, entity)[1]:
                elements += len(tags)
        groups[gmsh.model.getPhysicalName(dim, tag)] = (dim, elements)
    return groups


def vtk_cells(path):
    reader = vtk.vtkXMLUnstructuredGridReader() if path.suffix == ".vtu" else vtk.vtkUnstructuredGridReader()
    reader.SetFileName(str(path))
    reader.Update()
    return reader.GetOutput()


@pytest.mark.skipif(not PARTS, reason=f"{CAD} has no parts (the shared data lives beside the clone in CI)")
@pytest.mark.parametrize("part", PARTS, ids=[p.stem for p in PARTS])
def test_every_format_holds_the_parts_patches(tmp_path, part):
    meshprep("pipeline", part, "-o", tmp_path / "run", "--no-improve", "--quiet", allowed=(0, 1))  # 1: not FEM-ready
    source = tmp_path / "part.msh"
    (tmp_path / "run" / "tets.msh").rename(source)
    tets, boundary = our_reading(source)
    per_tag = {int(k): v for k, v in boundary["faces_per_tag"].items()}
    per_patch = boundary["faces_per_patch"]
    assert len(per_patch) >= 1 and sum(per_patch.values()) == boundary["faces"]
    for name, (file, flags, has_tags, has_names) in FORMATS.items():
        path = tmp_path / file
        if path != source:
            meshprep("convert", source, "-o", path, *flags)
        if path.suffix != ".inp":  # meshprep reads no .inp
            our_tets, our_boundary = our_reading(path)
            assert our_tets == tets, name
            if has_tags:
                assert {int(k): v for k, v in our_boundary["faces_per_tag"].items()} == per_tag, name
            if has_names:
                assert our_boundary["faces_per_patch"] == per_patch, name
        meshio_tets, meshio_tags = meshio_tets_and_tags(path)
        assert meshio_tets == tets, name
        if meshio_tags is not None:
            assert meshio_tags == per_tag, name
        if path.suffix == ".inp":
            point_sets = meshio.read(path, file_format="abaqus").point_sets
            assert set(per_patch) <= {key for key in point_sets}, (name, sorted(point_sets)[:10])
        if path.suffix == ".msh":
            groups = gmsh_physical_groups(path)
            assert {n: e for n, (d, e) in groups.items() if d == 2} == per_patch, name
            assert [e for d, e in groups.values() if d == 3] == [tets], name
        if path.suffix in (".vtu", ".vtk"):
            grid = vtk_cells(path)
            assert grid.GetNumberOfCells() == tets, name
            assert set(vtk_to_numpy(grid.GetCellTypesArray()).tolist()) == {vtk.VTK_TETRA}, name
        if path.suffix == ".vtu":
            faces = vtk_cells(path.with_name(path.stem + "_boundary.vtu"))
            assert counts(vtk_to_numpy(faces.GetCellData().GetArray("patch"))) == per_tag, name


def multi_solid_stl(path):
    """A unit cube as an ASCII STL with two solids: 'lid' (z = 1) and 'body' (the other sides)."""
    corners = np.array([(x, y, z) for x in (0, 1) for y in (0, 1) for z in (0, 1)], dtype=float)
    quads = {"x0": (0, 1, 3, 2), "x1": (4, 6, 7, 5), "y0": (0, 4, 5, 1), "y1": (2, 3, 7, 6), "z0": (0, 2, 6, 4),
             "z1": (1, 5, 7, 3)}
    solids = {"body": ["x0", "x1", "y0", "y1", "z0"], "lid": ["z1"]}
    with open(path, "w") as out:
        for solid, sides in solids.items():
            out.write(f"solid {solid}\n")
            for side in sides:
                a, b, c, d = quads[side]
                for tri in ((a, b, c), (a, c, d)):
                    p = corners[list(tri)]
                    n = np.cross(p[1] - p[0], p[2] - p[0])
                    out.write(f"facet normal {n[0]:g} {n[1]:g} {n[2]:g}\nouter loop\n")
                    out.writelines(f"vertex {q[0]:g} {q[1]:g} {q[2]:g}\n" for q in p)
                    out.write("endloop\nendfacet\n")
            out.write(f"endsolid {solid}\n")


def test_a_multi_solid_stl_and_an_obj_with_groups_keep_their_names(tmp_path):
    multi_solid_stl(tmp_path / "cube.stl")
    subprocess.run([sys.executable, str(TESTS.parent / "examples" / "solvers" / "parts.py"), "beam",
                    str(tmp_path / "beam.obj")], check=True)
    for surface, names in (("cube.stl", {"body", "lid"}), ("beam.obj", {"fixed", "free", "loaded", "bottom", "sides"})):
        out = tmp_path / (pathlib.Path(surface).stem + ".msh")
        meshprep("tetrahedralize", tmp_path / surface, "-o", out)
        groups = gmsh_physical_groups(out)
        assert {n for n, (d, _) in groups.items() if d == 2} == names, surface
        assert set(json.loads(meshprep("quality", out, "--json", "-").stdout)["boundary"]["faces_per_patch"]) == names
