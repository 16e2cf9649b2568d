#pragma once
// What the Gmsh writer and reader (export_gmsh.cpp, import_gmsh.cpp) share: the element types they
// write and read, and where the mid-edge nodes of a 10-node tet are.
//
// Gmsh reference manual, "Node ordering" (https://gmsh.info/doc/texinfo/gmsh.html#Node-ordering):
// a 10-node tet (type 11) lists its corners 0-3, then the nodes of edges (0,1) (1,2) (2,0) (3,0)
// (3,2) (3,1); a 6-node triangle (type 9) its corners, then (0,1) (1,2) (2,0). Checked on what
// gmsh 4.8 writes for `gmsh -3 -order 2` (and what meshio's gmsh reader permutes: the last two).

#include <array>
#include <cstdint>

namespace meshprep::detail {

constexpr int gmsh_triangle = 2;
constexpr int gmsh_tetrahedron = 4;
constexpr int gmsh_triangle_6 = 9;
constexpr int gmsh_tetrahedron_10 = 11;

/// Gmsh's 10-node tet's node 4 + k is on the edge kTetEdges[kGmshTetEdges[k]] (tet_mesh.h):
/// kTetEdges' order with its last two swapped.
constexpr std::array<int, 6> kGmshTetEdges{0, 1, 2, 3, 5, 4};

}  // namespace meshprep::detail
