#pragma once
// Repair step 5 (repair.h): each boundary loop filled with a refined, faired patch.

#include "meshprep/core/mesh.h"
#include "meshprep/preprocess/repair/repair.h"

#include <vector>

namespace meshprep::detail {

/// Fills each boundary loop no longer than `max_rim_length` (in the surface's units) after Liepa
/// 2003: triangulate_hole, refine_patch, fair_patch. The faces and vertices are appended to
/// `soup`; every loop is reported, filled or not (and why not).
/// \pre the surface is oriented and manifold (split_nonmanifold, orient_components).
std::vector<RepairHole> fill_holes(TriangleSoup& soup, double max_rim_length);

}  // namespace meshprep::detail
