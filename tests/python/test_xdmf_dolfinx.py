"""meshprep's XDMF + HDF5 output in dolfinx and meshio (issue 44, point 5).

`meshprep tetrahedralize` meshes a small terrain closed into a block (an open height field
extruded: boundary patches "top", "sides" and "bottom", fem/extrude.h) into block.xdmf + block.h5;
then
- dolfinx reads it (XDMFFile.read_mesh, read_meshtags "facet_tags" and "cell_tags") with the counts
  and tags of the HDF5 data (h5py), and the patches' tags are found by their names in the XDMF;
- dolfinx solves -laplace(u) = 1 with u = 0 on the bottom, du/dn = 0 elsewhere: by the
  maximum principle u >= 0, and comparing u with the slab solutions w(z) = s (H - s / 2),
  s = z - base, for the lowest and highest top H, its maximum lies between Hmin^2 / 2 and Hmax^2 / 2
  (w is a sub- or supersolution: -laplace(w) = 1, w = 0 on the base, dw/dn = 0 on the vertical
  walls and n_z (H - s), of one sign, on the top);
- meshio reads each grid (through fem_readback.read_xdmf_grid: meshio reads one grid per file);
- a mesh dolfinx wrote goes through `meshprep convert` to .msh and back to .xdmf, and dolfinx reads
  the same tags again.

Run by ctest (tests/CMakeLists.txt) as `/usr/bin/python3 -m pytest`, with MESHPREP_BIN naming the
binary. Skipped when dolfinx is not importable (apt-get install python3-dolfinx).
"""
import os
import pathlib
import subprocess
import sys
import xml.etree.ElementTree as ET

import numpy as np
import pytest

dolfinx = pytest.importorskip("dolfinx", reason="dolfinx is not importable (apt-get install python3-dolfinx)")
h5py = pytest.importorskip("h5py", reason="h5py is not importable (apt-get install python3-h5py)")
pytest.importorskip("meshio", reason="meshio is not importable (apt-get install python3-meshio)")

import dolfinx.fem.petsc  # noqa: E402  (LinearProblem)
import ufl  # noqa: E402
from dolfinx import fem, io  # noqa: E402
from dolfinx import mesh as dmesh  # noqa: E402
from mpi4py import MPI  # noqa: E402
from petsc4py import PETSc  # noqa: E402

TESTS = pathlib.Path(__file__).resolve().parents[1]
sys.path.insert(0, str(TESTS))
from fem_readback import read_xdmf_grid  # noqa: E402

BINARY = os.environ.get("MESHPREP_BIN", str(TESTS.parent / "build" / "bin" / "meshprep"))
BASE_DEPTH = 0.5  # the base lies this far below the lowest point of the terrain


def terrain_off(path, n=8):
    """An (n + 1)^2-point height field over the unit square, z = 0.1 sin(2 pi x) cos(pi y)."""
    x, y = np.meshgrid(np.linspace(0, 1, n + 1), np.linspace(0, 1, n + 1), indexing="ij")
    z = 0.1 * np.sin(2 * np.pi * x) * np.cos(np.pi * y)
    points = np.column_stack([x.ravel(), y.ravel(), z.ravel()])
    faces = []
    for i in range(n):
        for j in range(n):
            a, b, c, d = i * (n + 1) + j, (i + 1) * (n + 1) + j, (i + 1) * (n + 1) + j + 1, i * (n + 1) + j + 1
            faces += [(a, b, c), (a, c, d)]  # counter-clockwise seen from above: normals up
    with open(path, "w") as out:
        out.write(f"OFF\n{len(points)} {len(faces)} 0\n")
        out.writelines(f"{p[0]!r} {p[1]!r} {p[2]!r}\n" for p in points)
        out.writelines(f"3 {a} {b} {c}\n" for a, b, c in faces)
    return points


def meshprep(*args):
    run = subprocess.run([BINARY, *map(str, args)], capture_output=True, text=True, timeout=300)
    assert run.returncode == 0, f"meshprep {' '.join(map(str, args))}: exit {run.returncode}\n{run.stdout}{run.stderr}"
    return run


@pytest.fixture(scope="module")
def block(tmp_path_factory):
    folder = tmp_path_factory.mktemp("xdmf")
    points = terrain_off(folder / "terrain.off")
    meshprep("tetrahedralize", folder / "terrain.off", "-o", folder / "block.xdmf", "--extrude-base", BASE_DEPTH)
    assert sorted(p.name for p in folder.iterdir()) == ["block.h5", "block.xdmf", "terrain.off"]
    return folder / "block.xdmf", points


def read_with_dolfinx(path):
    with io.XDMFFile(MPI.COMM_WORLD, str(path), "r") as xdmf:
        mesh = xdmf.read_mesh(name="mesh")
        mesh.topology.create_connectivity(mesh.topology.dim - 1, mesh.topology.dim)
        facet_tags = xdmf.read_meshtags(mesh, name="facet_tags")
        cell_tags = xdmf.read_meshtags(mesh, name="cell_tags")
    return mesh, facet_tags, cell_tags


def tag_names(path, grid_name):
    """The names meshprep writes in a tag grid: <Information Name="<name>" Value="<tag>"/>."""
    grid = ET.parse(path).getroot().find(f"Domain/Grid[@Name='{grid_name}']")
    return {info.get("Name"): int(info.get("Value")) for info in grid.findall("Information")}


def test_dolfinx_reads_the_mesh_and_its_tags(block):
    path, _ = block
    mesh, facet_tags, cell_tags = read_with_dolfinx(path)
    with h5py.File(path.with_suffix(".h5"), "r") as h5:
        num_points = h5["/Mesh/mesh/geometry"].shape[0]
        num_tets = h5["/Mesh/mesh/topology"].shape[0]
        facet_values = h5["/MeshTags/facet_tags/Values"][:].ravel()
        cell_values = h5["/MeshTags/cell_tags/Values"][:].ravel()
        assert h5["/MeshTags/cell_tags/topology"] == h5["/Mesh/mesh/topology"]  # one dataset, two names
    assert mesh.topology.index_map(0).size_global == num_points
    assert mesh.topology.index_map(3).size_global == num_tets
    assert len(cell_values) == num_tets and set(cell_values) == {1}
    # Every exterior facet is tagged, once, with the tag meshprep gave it.
    exterior = dmesh.exterior_facet_indices(mesh.topology)
    assert np.array_equal(np.sort(facet_tags.indices), np.sort(exterior))
    assert sorted(facet_tags.values) == sorted(facet_values)
    names = tag_names(path, "facet_tags")
    assert {"sides", "bottom"} <= set(names) and set(facet_tags.values) == set(names.values()), names
    assert np.array_equal(np.sort(cell_tags.indices), np.arange(num_tets))
    assert set(cell_tags.values) == {1}
    # The bottom's facets lie in the plane BASE_DEPTH below the terrain's lowest point.
    base_z = dmesh.compute_midpoints(mesh, 2, facet_tags.indices[facet_tags.values == names["bottom"]])[:, 2]
    assert np.allclose(base_z, -0.1 - BASE_DEPTH, atol=1e-12)
    assert tag_names(path, "cell_tags") == {"region_1": 1}


def test_dolfinx_solves_poisson_on_it(block):
    path, points = block
    mesh, facet_tags, _ = read_with_dolfinx(path)
    space = fem.FunctionSpace(mesh, ("Lagrange", 1))
    bottom = tag_names(path, "facet_tags")["bottom"]
    base_dofs = fem.locate_dofs_topological(space, 2, facet_tags.indices[facet_tags.values == bottom])
    assert len(base_dofs) > 0
    u, v = ufl.TrialFunction(space), ufl.TestFunction(space)
    a = ufl.inner(ufl.grad(u), ufl.grad(v)) * ufl.dx
    rhs = fem.Constant(mesh, PETSc.ScalarType(1.0)) * v * ufl.dx
    problem = dolfinx.fem.petsc.LinearProblem(a, rhs, bcs=[fem.dirichletbc(PETSc.ScalarType(0), base_dofs, space)],
                                              petsc_options={"ksp_type": "preonly", "pc_type": "lu"})
    values = problem.solve().x.array
    base = points[:, 2].min() - BASE_DEPTH
    lowest_top, highest_top = points[:, 2].min() - base, points[:, 2].max() - base
    assert values.min() >= -1e-10, f"u < 0: {values.min()}"
    assert values.max() <= highest_top**2 / 2 * (1 + 1e-9), f"max u {values.max()} > Hmax^2/2 {highest_top**2 / 2}"
    # P1 on these tets is close to the continuous bound from below, not exactly on it.
    assert values.max() >= 0.95 * lowest_top**2 / 2, f"max u {values.max()} < Hmin^2/2 {lowest_top**2 / 2}"


def test_meshio_reads_each_grid(block):
    path, _ = block
    with h5py.File(path.with_suffix(".h5"), "r") as h5:
        geometry = h5["/Mesh/mesh/geometry"][:]
        topology = h5["/Mesh/mesh/topology"][:]
        facet_values = h5["/MeshTags/facet_tags/Values"][:].ravel()
    mesh = read_xdmf_grid(path, "mesh")
    assert np.array_equal(mesh.points, geometry)
    assert [block.type for block in mesh.cells] == ["tetra"]
    assert np.array_equal(mesh.cells[0].data, topology)
    facets = read_xdmf_grid(path, "facet_tags")
    assert [block.type for block in facets.cells] == ["triangle"]
    assert np.array_equal(np.asarray(facets.cell_data["facet_tags"][0]).ravel(), facet_values)


def test_a_dolfinx_mesh_goes_through_meshprep_and_back(tmp_path):
    cube = dmesh.create_unit_cube(MPI.COMM_WORLD, 3, 3, 3, dmesh.CellType.tetrahedron)
    tdim = cube.topology.dim
    cube.topology.create_connectivity(tdim - 1, tdim)
    x0 = dmesh.locate_entities_boundary(cube, tdim - 1, lambda x: np.isclose(x[0], 0.0))
    x1 = dmesh.locate_entities_boundary(cube, tdim - 1, lambda x: np.isclose(x[0], 1.0))
    facets = np.concatenate([x0, x1])
    order = np.argsort(facets)
    facet_tags = dmesh.meshtags(cube, tdim - 1, facets[order],
                                np.concatenate([np.full(len(x0), 4), np.full(len(x1), 5)]).astype(np.int32)[order])
    facet_tags.name = "facet_tags"
    with io.XDMFFile(MPI.COMM_WORLD, str(tmp_path / "dolfinx.xdmf"), "w") as xdmf:
        xdmf.write_mesh(cube)
        xdmf.write_meshtags(facet_tags)
    meshprep("convert", tmp_path / "dolfinx.xdmf", "-o", tmp_path / "cube.msh")
    meshprep("convert", tmp_path / "cube.msh", "-o", tmp_path / "back.xdmf")
    mesh, tags, cell_tags = read_with_dolfinx(tmp_path / "back.xdmf")
    assert mesh.topology.index_map(3).size_global == 6 * 27
    # The side x = 0 keeps tag 4, x = 1 tag 5; the other boundary faces, untagged in dolfinx's
    # file, get meshprep's default tag 1.
    counts = {int(tag): int(np.sum(tags.values == tag)) for tag in np.unique(tags.values)}
    assert counts == {1: 4 * 18, 4: 18, 5: 18}
    assert set(cell_tags.values) == {1}
