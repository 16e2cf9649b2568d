#pragma once
// Repair step 5a (fill_holes.h): the first triangulation of a hole, Liepa's dynamic programme.

#include "meshprep/core/mesh.h"

#include <cstdint>
#include <unordered_set>
#include <vector>

namespace meshprep::detail {

/// The undirected edge a-b as one number (smaller index << 32 | larger), as FaceEdge keys it.
inline std::uint64_t edge_key(std::uint32_t a, std::uint32_t b) {
  return a < b ? std::uint64_t{a} << 32 | b : std::uint64_t{b} << 32 | a;
}

/// A boundary loop: its vertices in the order the surface's faces run the border, and for each
/// edge vertices[i] -> vertices[i + 1] (cyclically) the unit normal of the face that runs it.
struct HoleRim {
  std::vector<std::uint32_t> vertices;
  std::vector<Vec3> face_normals;
};

/// The triangulation of the rim's polygon, without new vertices, that minimises first the largest
/// dihedral angle between adjacent faces (patch-patch and patch-surface), then the total area
/// (Liepa 2003, "Filling holes in meshes", sec. 3; Barequet & Sharir's O(n^3) programme); with
/// `dihedral` false, the area alone. Faces that are degenerate or would add an edge `edges`
/// already holds (a second sheet on it) are not considered. The faces run each rim edge against
/// the surface's face, so the patch is oriented like the surface. Empty if no triangulation is left.
std::vector<Triangle> triangulate_hole(const std::vector<Vec3>& points, const HoleRim& rim,
                                       const std::unordered_set<std::uint64_t>& edges, bool dihedral);

}  // namespace meshprep::detail
