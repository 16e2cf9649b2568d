#pragma once
// A floating-point filter for the broad phase (private to quality/): triangles that the plane of
// one of them certainly separates, with a forward error bound, so that no exact predicate runs.

#include "meshprep/core/mesh.h"

#include <array>

namespace meshprep::detail {

/// True if a floating-point evaluation certifies that the plane of `t` or the plane of `u` has the
/// other triangle strictly on one side (so the closed triangles do not meet); false if neither is
/// certain, and then only the exact test can tell.
bool certainly_separated_by_a_plane(const std::array<Vec3, 3>& t, const std::array<Vec3, 3>& u);

}  // namespace meshprep::detail
