#pragma once
// Renumbering a mesh so that neighbours in space are neighbours in memory.

#include "meshprep/core/mesh.h"

#include <cstdint>
#include <vector>

namespace meshprep::detail {

/// The indices of `points` in Morton (Z-curve) order of their positions: work done in this order
/// finds the neighbours of the previous item still in the cache.
std::vector<std::uint32_t> morton_order(const std::vector<Vec3>& points);

/// The same surface with its vertices in Morton (Z-curve) order of their positions and its faces
/// ordered by their smallest vertex index (each keeping its patch). The collapse loop walks 1-rings and 2-rings ~10^6 times
/// in what is otherwise the file's order; on bunny00 at 10 % this order is ~12 % faster.
TriangleSoup in_spatial_order(const TriangleSoup& soup);

}  // namespace meshprep::detail
