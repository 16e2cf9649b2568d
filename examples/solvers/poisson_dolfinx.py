#!/usr/bin/python3
"""Poisson in dolfinx on meshprep's XDMF, u = 0 on a named patch, and the error's rate of fall.

Usage: /usr/bin/python3 poisson_dolfinx.py [--meshprep BIN] [--part box|cylinder] [--order 1|2]
                                           [--levels N] [--work DIR]

For each level, meshprep makes the part's tets, their size h halving from one level to the next
(`--max-volume-relative` divided by 8), and writes them as XDMF + HDF5:
- box (parts.py box, flat faces): `meshprep tetrahedralize box.obj -o level<k>.msh`;
- cylinder (curved): parts.py writes it with 12 * 2^k segments, every vertex on the cylinder, and
  `meshprep tetrahedralize --keep-surface` keeps those vertices as the tets' boundary;
then `meshprep convert level<k>.msh -o level<k>.xdmf` (with --order 2: `--order 2 --reference` the
part, the cylinder with 1536 segments, so that the boundary's mid-edge nodes go onto the curved
surface). dolfinx then
- reads the tets and their facet tags (XDMFFile.read_mesh, read_meshtags) and finds the patch named
  "fixed" by its name in the .xdmf (<Information Name="fixed" Value="TAG"/>);
- solves -laplace(u) = f with u = 0 on "fixed" and du/dn = g elsewhere, f and g made from the
  manufactured solution u = sin(pi s / 2) (1 + a^2) exp(b), s the distance from "fixed" (x for the
  box, z for the cylinder; a, b the other two coordinates), with Lagrange elements of degree
  --order, the mesh's own;
- prints the L2 error and its rate, log(e_k-1 / e_k) / log(h_k-1 / h_k), h = (volume / tets)^(1/3).
A degree-p solution's L2 error falls as h^(p+1): rates near 2 for P1, near 3 for P2, on the
cylinder only if the geometry is P2 as well (straight tets leave an O(h^2) error of the domain).

dolfinx is Debian's python3-dolfinx (0.5.2 here), run with /usr/bin/python3.
"""
import argparse
import logging
import math
import pathlib
import subprocess
import sys
import xml.etree.ElementTree as ET

import numpy as np
import ufl
from dolfinx import fem, io
from dolfinx.fem.petsc import LinearProblem
from mpi4py import MPI
from petsc4py import PETSc

HERE = pathlib.Path(__file__).resolve().parent
COARSEST_VOLUME = 1e-2  # largest tet / the part's volume, at the first level
CYLINDER_SEGMENTS = 12  # at the first level, doubled at each
REFERENCE_SEGMENTS = 1536  # the curved surface the mid-edge nodes go onto: its chords' sag is 2e-6 of the radius


def tag_of(xdmf_path, grid, name):
    """The tag meshprep gave the patch `name` in the tag grid `grid` of an .xdmf."""
    found = ET.parse(xdmf_path).getroot().find(f"Domain/Grid[@Name='{grid}']/Information[@Name='{name}']")
    if found is None:
        sys.exit(f"{xdmf_path}: no patch named {name}")
    return int(found.get("Value"))


def solve(path, order, part):
    with io.XDMFFile(MPI.COMM_WORLD, str(path), "r") as xdmf:
        mesh = xdmf.read_mesh(name="mesh")
        mesh.topology.create_connectivity(2, 3)
        facets = xdmf.read_meshtags(mesh, name="facet_tags")
    fixed = facets.indices[facets.values == tag_of(path, "facet_tags", "fixed")]
    space = fem.FunctionSpace(mesh, ("Lagrange", order))
    x = ufl.SpatialCoordinate(mesh)
    s, a, b = (x[0], x[1], x[2]) if part == "box" else (x[2], x[0], x[1])
    exact = ufl.sin(math.pi * s / 2) * (1 + a**2) * ufl.exp(b)
    u, v = ufl.TrialFunction(space), ufl.TestFunction(space)
    normal = ufl.FacetNormal(mesh)
    quadrature = {"quadrature_degree": 2 * order + 2}
    rhs = (-ufl.div(ufl.grad(exact)) * v * ufl.dx(metadata=quadrature)
           + ufl.dot(ufl.grad(exact), normal) * v * ufl.ds(metadata=quadrature))
    zero = fem.dirichletbc(PETSc.ScalarType(0), fem.locate_dofs_topological(space, 2, fixed), space)
    problem = LinearProblem(ufl.inner(ufl.grad(u), ufl.grad(v)) * ufl.dx, rhs, bcs=[zero],
                            petsc_options={"ksp_type": "preonly", "pc_type": "lu"})
    uh = problem.solve()
    error = fem.assemble_scalar(fem.form((uh - exact) ** 2 * ufl.dx(metadata=quadrature)))
    volume = fem.assemble_scalar(fem.form(fem.Constant(mesh, PETSc.ScalarType(1)) * ufl.dx))
    tets = mesh.topology.index_map(3).size_global
    return math.sqrt(error), (volume / tets) ** (1 / 3), tets


def main():
    logging.getLogger().setLevel(logging.WARNING)  # dolfinx's JIT compiler logs every build at INFO
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--meshprep", default=str(HERE.parents[1] / "build" / "bin" / "meshprep"))
    parser.add_argument("--part", choices=("box", "cylinder"), default="box")
    parser.add_argument("--order", type=int, choices=(1, 2), default=1)
    parser.add_argument("--levels", type=int, default=3)
    parser.add_argument("--work", default="poisson")
    args = parser.parse_args()
    work = pathlib.Path(args.work)
    work.mkdir(exist_ok=True)
    parts = [sys.executable, str(HERE / "parts.py")]
    if args.part == "box":
        subprocess.run([*parts, "box", str(work / "box.obj")], check=True)
        reference = work / "box.obj"
    else:
        reference = work / "cylinder_reference.obj"
        subprocess.run([*parts, "cylinder", str(reference), str(REFERENCE_SEGMENTS)], check=True)
    print(f"{'level':>5} {'tets':>8} {'h':>9} {'L2 error':>10} {'rate':>5}")
    previous = None
    for level in range(args.levels):
        surface = work / "box.obj"
        tetrahedralize = [args.meshprep, "tetrahedralize", "--max-volume-relative", repr(COARSEST_VOLUME / 8**level)]
        if args.part == "cylinder":
            surface = work / f"cylinder{level}.obj"
            subprocess.run([*parts, "cylinder", str(surface), str(CYLINDER_SEGMENTS * 2**level)], check=True)
            tetrahedralize.append("--keep-surface")
        tets, path = work / f"level{level}.msh", work / f"level{level}.xdmf"
        subprocess.run([*tetrahedralize, str(surface), "-o", str(tets)], check=True, stdout=subprocess.DEVNULL)
        convert = [args.meshprep, "convert", str(tets), "-o", str(path)]
        if args.order == 2:
            convert += ["--order", "2", "--reference", str(reference)]
        subprocess.run(convert, check=True, stdout=subprocess.DEVNULL)
        error, h, count = solve(path, args.order, args.part)
        rate = "" if previous is None else f"{math.log(previous[0] / error) / math.log(previous[1] / h):5.2f}"
        print(f"{level:5d} {count:8d} {h:9.4f} {error:10.3e} {rate:>5}", flush=True)
        previous = (error, h)


if __name__ == "__main__":
    main()
