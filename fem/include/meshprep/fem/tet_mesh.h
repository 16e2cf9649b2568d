#pragma once
/// \file tet_mesh.h
/// A tetrahedral mesh, linear or second-order (10-node tets), with region tags on cells and named
/// tags (patches) on boundary faces: what TetGen produces and what the exporters write.

#include "meshprep/core/mesh.h"

#include <array>
#include <cstdint>
#include <vector>

namespace meshprep {

using Tetrahedron = std::array<std::uint32_t, 4>;

/// The six edges of a tet as pairs of its corners, in VTK's quadratic-tetra order (VTK_QUADRATIC_TETRA,
/// cell type 24), which is also Abaqus C3D10's, Medit TetrahedraP2's and XDMF Tetrahedron_10's:
/// the canonical order of TetMesh::tet_edge_nodes. (Gmsh's type 11 lists the last two the other
/// way round: its writer and reader permute.)
inline constexpr std::array<std::array<int, 2>, 6> kTetEdges{{{0, 1}, {1, 2}, {0, 2}, {0, 3}, {1, 3}, {2, 3}}};

/// The mid-edge nodes of one second-order tet: the node of edge kTetEdges[e] at e.
using TetEdgeNodes = std::array<std::uint32_t, 6>;

struct TetMesh {
  std::vector<Vec3> points;
  /// Positively oriented: (p1 - p0) . ((p2 - p0) x (p3 - p0)) > 0 for every tet.
  std::vector<Tetrahedron> tets;
  std::vector<int> tet_regions;  ///< one per tet, >= 1 (1 when the solid has a single region)
  /// Boundary triangles, oriented with outward normals (counter-clockwise seen from outside).
  std::vector<Triangle> boundary_faces;
  std::vector<int> boundary_tags;  ///< one per boundary face, >= 1 (1 = default surface tag)
  /// The names of the boundary tags (the surface's patches) and of the regions, where known.
  TagNames boundary_names = {};
  TagNames region_names = {};
  /// A second-order mesh's mid-edge nodes, one row per tet (indices into `points`, in kTetEdges'
  /// order); empty for a linear mesh. An edge has the same node in every tet that has it, and a
  /// mid-edge node is no tet's corner. A boundary face's three come from face_edge_nodes.
  std::vector<TetEdgeNodes> tet_edge_nodes = {};

  bool quadratic() const { return !tet_edge_nodes.empty(); }
};

/// Signed volume of tet t: (p1 - p0) . ((p2 - p0) x (p3 - p0)) / 6 (of its corners: the volume of
/// a second-order tet with straight edges).
double tet_volume(const TetMesh& mesh, std::size_t t);

/// Index into kTetEdges of the edge of `tet` between corners a and b (point indices, either order),
/// -1 if they are not two corners of it.
int tet_edge_index(const Tetrahedron& tet, std::uint32_t a, std::uint32_t b);

/// The mid-edge nodes of `face`, a face of `tet` (whose row of TetMesh::tet_edge_nodes is
/// `nodes`), in the order of a 6-node triangle (VTK 22, Gmsh 9, Medit TrianglesP2): those of the
/// edges (f0, f1), (f1, f2), (f2, f0).
/// \pre the face's corners are corners of `tet`.
std::array<std::uint32_t, 3> face_edge_nodes(const Tetrahedron& tet, const TetEdgeNodes& nodes, const Triangle& face);

/// The mid-edge nodes of every boundary face of a second-order mesh (face_edge_nodes, each from a
/// tet that has the face), one row per TetMesh::boundary_faces; empty for a linear mesh.
/// \throws InvalidInput if a boundary face is no face of any tet or tet_edge_nodes has not one row
///         per tet.
std::vector<std::array<std::uint32_t, 3>> boundary_face_edge_nodes(const TetMesh& mesh);

/// The linear mesh of `mesh`'s corners: tet_edge_nodes emptied and the points no tet or boundary
/// face uses as a corner (the mid-edge nodes) dropped, the others renumbered in their order.
TetMesh linear_mesh(const TetMesh& mesh);

}  // namespace meshprep
