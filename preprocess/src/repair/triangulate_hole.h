#pragma once
// Repair step 5a (fill_holes.h): the first triangulation of a hole, Liepa's dynamic programme.

#include "meshprep/core/mesh.h"
#include "meshprep/quality/face_edges.h"

#include <cstdint>
#include <unordered_set>
#include <vector>

namespace meshprep::detail {

/// Whether the triangle with sides u and w from one corner, |u x w| = twice_area, is too thin to
/// be a face (collinear corners of a straight stretch of rim): the test of the programme and of
/// the patch's refinement alike.
inline bool too_thin(double twice_area, const Vec3& u, const Vec3& w) {
  return !(twice_area > 1e-12 * (u.squaredNorm() + w.squaredNorm()));
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
