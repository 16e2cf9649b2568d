#pragma once
/// \file tet_mesh.h
/// A linear tetrahedral mesh with region tags on cells and named tags (patches) on boundary
/// faces: what TetGen produces and what the exporters write.

#include "meshprep/core/mesh.h"

#include <array>
#include <cstdint>
#include <vector>

namespace meshprep {

using Tetrahedron = std::array<std::uint32_t, 4>;

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
};

/// Signed volume of tet t: (p1 - p0) . ((p2 - p0) x (p3 - p0)) / 6.
double tet_volume(const TetMesh& mesh, std::size_t t);

}  // namespace meshprep
