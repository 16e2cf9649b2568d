#pragma once
// Repair step 5c (fill_holes.h): a hole's patch faired into the surface around it.

#include "meshprep/core/mesh.h"

#include <cstdint>
#include <vector>

namespace meshprep::detail {

/// Moves the patch's own vertices (index >= first_new) to the solution of the bi-Laplacian
/// equation Delta^2 x = 0 with the uniform (umbrella) Laplacian, the rim and its ring on the
/// surface fixed: the membrane-free thin-plate fairing of Liepa 2003, sec. 5 (there with the
/// scale-dependent umbrella), which meets the surface around with a continuous tangent plane.
/// `neighbours` is the surface's vertex adjacency (without the patch). Returns false, and moves
/// nothing, if the sparse LU solve fails.
bool fair_patch(std::vector<Vec3>& points, const std::vector<Triangle>& patch, std::uint32_t first_new,
                const std::vector<std::vector<std::uint32_t>>& neighbours);

}  // namespace meshprep::detail
