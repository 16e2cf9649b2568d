#pragma once
/// \file self_intersections.h
/// Pairs of faces of a soup that intersect although they are not neighbours. Faces sharing an
/// edge intersect only if they fold onto each other (coplanar, on the same side of the edge);
/// faces sharing a vertex only if an edge of one crosses the other (the rules of CGAL's
/// self_intersections, so the counts agree with the judge). Faces sharing three vertices
/// (duplicates) count as intersecting.

#include "meshprep/core/mesh.h"
#include "meshprep/core/soup_view.h"

#include <utility>
#include <vector>

namespace meshprep {

struct SelfIntersections {
  std::size_t count = 0;  ///< intersecting pairs found (at most the cap)
  bool capped = false;    ///< counting stopped at the cap
  std::vector<std::pair<std::size_t, std::size_t>> pairs;  ///< the pairs (face i < face j), sorted
  /// Face pairs the broad phase passed to the exact test: the work done, which grows with the
  /// number of faces (a few per face on a fine mesh), not with the square of a vertex's valence.
  std::size_t exact_tests = 0;
};

/// Find intersecting face pairs: faces with corners in common by the directions they cover around
/// each vertex, the others with a BVH and a certified floating-point plane test; then the exact
/// test (triangle_intersection.h). Degenerate faces (zero area) are skipped: they are reported as
/// degenerate, not as intersections. Stops after `cap` pairs (0 = no limit). `soup` is a TriangleSoup,
/// or a TriMesh through MeshSoupView (no copy of its points).
SelfIntersections find_self_intersections(const SoupView& soup, std::size_t cap = 0);

}  // namespace meshprep
