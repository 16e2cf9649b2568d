#pragma once
// Repair steps 1 and 2 (repair.h): welding, and the faces and vertices it leaves without use.

#include "meshprep/core/mesh.h"

#include <cstddef>

namespace meshprep::detail {

struct WeldCounts {
  std::size_t welded_vertices = 0, degenerate_faces = 0, duplicate_faces = 0, unused_vertices = 0;
};

/// Welds vertices within `distance` of each other (each cluster onto its lowest index, which does
/// not move), then removes faces naming a vertex twice and faces repeating another's vertices
/// (all copies of faces on the same vertices facing both ways whose edges have two other faces
/// each: a wall two solids share), and drops
/// the vertices no face uses.
WeldCounts weld_vertices(TriangleSoup& soup, double distance);

}  // namespace meshprep::detail
