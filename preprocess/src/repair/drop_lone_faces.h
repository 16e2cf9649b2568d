#pragma once
// Repair step 3b (repair.h): faces with no neighbour, which bound no solid.

#include "meshprep/core/mesh.h"
#include "meshprep/quality/face_edges.h"

#include <cstddef>
#include <vector>

namespace meshprep::detail {

/// Removes the faces none of whose edges another face uses (a fin the non-manifold split took off
/// a solid's edge, a stray triangle), unless the surface is nothing else: such a face encloses
/// nothing, no hole patch can close it (the patch would repeat it), and it touches the solid it
/// hung from, with the corners no other face uses. `uses` is sorted_face_edges(soup). Returns the
/// faces removed.
std::size_t drop_lone_faces(TriangleSoup& soup, const std::vector<FaceEdge>& uses);

}  // namespace meshprep::detail
