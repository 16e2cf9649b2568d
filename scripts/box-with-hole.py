#!/usr/bin/env python3
"""A box 10 x 6 x 2 with a through hole of radius 1.5 (Gmsh's OpenCASCADE kernel), meshed by Gmsh
at a uniform size H: the part of issue 49's size checks (bench/bench_size_field.sh).

Usage: box-with-hole.py H OUT [surface|volume]
  surface  the triangles only (OUT .stl: meshprep's input; a large H gives a CAD export's strips)
  volume   Gmsh's own tets at size H (OUT .msh: the peer's figures, side by side)
Needs python3-gmsh (scripts/install-deps.sh); run it with /usr/bin/python3.
"""
import sys

import gmsh

HOLE_RADIUS = 1.5


def main():
    h, out, kind = float(sys.argv[1]), sys.argv[2], sys.argv[3] if len(sys.argv) > 3 else "surface"
    gmsh.initialize()
    gmsh.option.setNumber("General.Terminal", 0)
    gmsh.model.add("box_with_hole")
    box = gmsh.model.occ.addBox(0, 0, 0, 10, 6, 2)
    hole = gmsh.model.occ.addCylinder(5, 3, -1, 0, 0, 4, HOLE_RADIUS)
    gmsh.model.occ.cut([(3, box)], [(3, hole)])
    gmsh.model.occ.synchronize()
    gmsh.option.setNumber("Mesh.MeshSizeMin", h)
    gmsh.option.setNumber("Mesh.MeshSizeMax", h)
    gmsh.option.setNumber("Mesh.MeshSizeFromPoints", 0)
    gmsh.option.setNumber("Mesh.MeshSizeExtendFromBoundary", 0)
    gmsh.model.mesh.generate(2 if kind == "surface" else 3)
    gmsh.write(out)
    gmsh.finalize()


if __name__ == "__main__":
    main()
