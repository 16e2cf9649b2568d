#pragma once
// Repair step 6 (repair.h): a surface crossing itself, or made of overlapping or nested closed
// parts, turned into the boundary of the solid they enclose together.

#include "meshprep/core/mesh.h"
#include "meshprep/quality/face_edges.h"

#include <cstddef>
#include <functional>
#include <vector>

namespace meshprep::detail {

struct SelfIntersectionCounts {
  std::size_t intersecting_pairs = 0;  ///< pairs of faces crossing, overlapping or touching, as found
  std::size_t cut_faces = 0;           ///< faces triangulated again along where others meet them
  std::size_t removed_faces = 0;       ///< faces (after the cuts) dropped: inside the solid, or doubled
  std::size_t nested_components = 0;   ///< parts inside another that touch nothing, dropped
  std::size_t cavities = 0;            ///< such parts kept as the walls of voids (keep_cavities)
  std::size_t separated_pinches = 0;   ///< vertex copies moved apart (separate_pinches.h)
  bool found_none = false;  ///< the last search was on the surface as returned and found no pair
};

/// Cuts every face along the curves where other faces meet it (exactly: exact_geometry.h), then
/// keeps the pieces that bound the union of what the surface encloses: those just outside which
/// the winding number (winding_number.h) is 0. A region the surface wraps twice (an overlap of two
/// parts, a fold) loses its inner walls; a wall two parts share, faced both ways, goes; of two
/// coincident pieces faced the same way, one stays. A closed part that touches nothing and lies
/// inside another is dropped, or with `keep_cavities` kept facing inwards, the wall of a void
/// (and a part inside that void facing outwards again).
/// Where the union's parts touch at a point or along an edge, they are held apart by a hair
/// (separate_pinches.h). The output's new points are the exact ones rounded to doubles; if that rounding makes faces
/// cross again, the pass runs again on the result (at most three passes). `uses` is
/// sorted_face_edges(surface), for the first pass; `poll` is called before each pass and often within one (at each face it cuts; it may throw).
/// \pre consistently oriented, closed components outward (orient_components)
SelfIntersectionCounts remove_self_intersections(TriangleSoup& surface, const std::vector<FaceEdge>& uses,
                                                 bool keep_cavities, const std::function<void()>& poll);

}  // namespace meshprep::detail
