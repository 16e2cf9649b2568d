#pragma once
// Repair step 1b (repair.h): T-junctions, where one side of a seam has a vertex the other lacks.

#include "meshprep/core/mesh.h"

#include <cstddef>

namespace meshprep::detail {

/// Where a vertex of an open edge (an edge one face alone uses) lies on another open edge, within
/// `distance` of its inside and farther than `distance` from its ends, the face of that edge is
/// split in two there, so that both sides of the seam share the vertex and welding closes it (an
/// exporter that refined one side of an edge and not the other). Repeated until no such vertex is
/// left; the new faces keep the split face's orientation and patch. Returns the faces split.
std::size_t split_t_junctions(TriangleSoup& soup, double distance);

}  // namespace meshprep::detail
