#pragma once
// The broad phase for faces that have corners in common (private to quality/): around each
// vertex, the faces whose directions from it overlap.

#include "meshprep/core/soup_view.h"

#include <functional>
#include <vector>

namespace meshprep::detail {

/// Calls `visit(i, j)` (i < j) once for every pair of faces, both `usable`, that have two or three
/// corners in common, and for every pair with exactly one corner v in common whose directions from
/// v overlap. A pair of the latter kind that meets anywhere but at v is among them; around a
/// vertex whose faces turn once around it (a fan, a manifold vertex) no such pair is visited, so
/// the work grows with the number of faces, not with the squares of the vertices' valences.
/// `usable` faces must have area. Runs in parallel over the vertices: `visit` must be thread-safe.
void for_each_neighbour_pair(const SoupView& soup, const std::vector<char>& usable,
                             const std::function<void(std::size_t, std::size_t)>& visit);

}  // namespace meshprep::detail
