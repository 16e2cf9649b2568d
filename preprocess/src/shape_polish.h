#pragma once
// After the collapses: edge flips and tangential relaxation that raise the smallest angles while
// the surface stays where the quadrics say the original was.

#include "collapse_quadrics.h"

#include "meshprep/core/mesh.h"

#include <cstddef>
#include <vector>

namespace meshprep::detail {

struct PolishCounts {
  std::size_t flips = 0, moves = 0;
};

/// One round of (1) flips of nearly flat interior edges (both dihedral angles, before and
/// after, under 10 degrees) that raise the smaller of the two faces' smallest angles and whose
/// two diagonals lie within `tolerance` of each other along the normal; then (2) a Gauss-Seidel
/// sweep moving each interior manifold vertex that is not on a feature (surface variation sigma
/// of its 1-ring over that of a 30-degree crease) to its 1-ring centroid in its tangent plane, then
/// along its normal to the minimum of its quadric, kept only if the smallest angle around it
/// improves, no face turns by more than 60 degrees, and the quadric's RMS plane distance stays
/// under `tolerance` (or does not grow). Without `flips`, only (2).
PolishCounts polish_shape(TriMesh& mesh, const std::vector<Quadric>& quadrics, double tolerance, bool flips = true);

}  // namespace meshprep::detail
