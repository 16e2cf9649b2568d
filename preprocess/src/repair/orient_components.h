#pragma once
// Repair step 4 (repair.h): consistent orientation per component, closed components outward.

#include "meshprep/core/mesh.h"
#include "meshprep/quality/face_edges.h"

#include <cstddef>
#include <vector>

namespace meshprep::detail {

struct OrientCounts {
  std::size_t components = 0, flipped_faces = 0, inverted_components = 0;
};

/// Flips faces so that the two faces of each manifold edge traverse it in opposite directions,
/// spreading from each edge-connected component's first face (a non-orientable component keeps
/// what cannot agree), then turns every closed component that encloses negative volume outward.
/// `uses` is sorted_face_edges(soup); a flip reverses a face's edges, so it is stale after any.
OrientCounts orient_components(TriangleSoup& soup, const std::vector<FaceEdge>& uses);

}  // namespace meshprep::detail
