#pragma once
// Repair step 3 (repair.h): non-manifold edges and vertices split so that each sheet is manifold.

#include "meshprep/core/mesh.h"
#include "meshprep/quality/face_edges.h"

#include <cstddef>
#include <vector>

namespace meshprep::detail {

struct SplitCounts {
  std::size_t split_edges = 0, split_vertices = 0;
};

/// Gives each sheet meeting at a non-manifold edge (three or more faces) or vertex (faces forming
/// more than one fan) its own copy of the vertices there. The faces on such an edge are paired
/// geometrically, across the wedges they bound (see split_nonmanifold.cpp); a face no wedge pairs
/// keeps the edge as a border. Faces and positions are unchanged; only indices are renumbered
/// (none unless split_vertices > 0). `uses` is sorted_face_edges(soup).
/// \pre no face names a vertex twice (weld_vertices removes them).
SplitCounts split_nonmanifold(TriangleSoup& soup, const std::vector<FaceEdge>& uses);

}  // namespace meshprep::detail
