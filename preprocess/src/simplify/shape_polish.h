#pragma once
// After the collapses: edge flips and tangential relaxation that raise the smallest angles while
// the surface stays where the quadrics say the original was.

#include "simplify/collapse_quadrics.h"
#include "shared/triangle_angles.h"
#include "shared/vertex_relaxation.h"

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
/// sweep over the vertices (those of the `tail`'s faces; all if it is null) not on a feature: each moves
/// towards its 1-ring centroid in its tangent plane, the step halved until the quadric's RMS plane
/// distance is under `tolerance` (or no larger than before), kept only if the smallest angle
/// around it improves and no face turns by more than 60 degrees. Without `flips`, only (2). Neither
/// turns a face away from `field`'s up direction.
PolishCounts polish_shape(TriMesh& mesh, const std::vector<Quadric>& quadrics, double tolerance, bool flips,
                          const ShapeTail* tail, const HeightField& field);

}  // namespace meshprep::detail
