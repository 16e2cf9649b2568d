#pragma once
// Repair step 5b (fill_holes.h): a hole's patch refined to the density of the surface around it.

#include "meshprep/core/mesh.h"

#include <cstdint>
#include <unordered_map>
#include <unordered_set>
#include <vector>

namespace meshprep::detail {

/// Liepa 2003, sec. 4: splits each patch face at its centroid while the centroid lies farther
/// than the local edge length / sqrt 2 from all three corners, and flips the patch's inner edges
/// until each is locally Delaunay (its two opposite angles add up to at most pi), until no face
/// splits. `scale` gives each rim vertex its edge length (the mean of its edges on the surface);
/// a new vertex takes its face's mean, and is appended to `points` and `scale`. Rim edges and
/// the edges in `edges` (the surface's) are never flipped or created.
void refine_patch(std::vector<Vec3>& points, std::unordered_map<std::uint32_t, double>& scale,
                  std::vector<Triangle>& patch, const std::unordered_set<std::uint64_t>& edges);

}  // namespace meshprep::detail
