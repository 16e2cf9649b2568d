#pragma once
// The guard every vertex-moving stage shares: moves that make the surface cross itself are taken back.

#include "meshprep/core/mesh.h"

#include <cstddef>
#include <functional>
#include <vector>

namespace meshprep::detail {

/// The vertices of faces that intersect (beyond the `allowed` pairs the input already had) go back
/// to `before`, until no new pair is left (at most 8 rounds). `mesh` must have no deleted
/// elements (its soup keeps the vertex and face numbering). Returns the number of vertices put back.
std::size_t undo_new_intersections(TriMesh& mesh, const std::vector<TriMesh::Point>& before, std::size_t allowed);

/// As above, with the allowed count asked for only when the surface crosses itself at all (a
/// full check of the input saved whenever the moves leave none).
std::size_t undo_new_intersections(TriMesh& mesh, const std::vector<TriMesh::Point>& before,
                                   const std::function<std::size_t()>& allowed);

}  // namespace meshprep::detail
