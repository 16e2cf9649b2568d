#pragma once
// Repair step 5 (repair.h): each boundary loop filled with a refined, faired patch.

#include "meshprep/core/mesh.h"
#include "meshprep/preprocess/repair/repair.h"
#include "meshprep/quality/face_edges.h"

#include <optional>
#include <vector>

namespace meshprep::detail {

/// Fills boundary loops after Liepa 2003: triangulate_hole, refine_patch, fair_patch. Given
/// `max_hole` (RepairParams'), each loop no longer than max_hole x the bounding box's diagonal;
/// without it, each loop but an open sheet's outline (sheet_outlines.h). The faces and vertices are
/// appended to `soup`; every loop is reported, filled or not (and why not). `uses` is
/// sorted_face_edges(soup).
/// \pre the surface is oriented and manifold (split_nonmanifold, orient_components).
std::vector<RepairHole> fill_holes(TriangleSoup& soup, const std::vector<FaceEdge>& uses,
                                   std::optional<double> max_hole);

}  // namespace meshprep::detail
