#pragma once
// Step 3 of the enhancement (enhance.h): one Ceres least-squares problem that moves the vertices
// on their charts so that the weighted faces get closer to equilateral.

#include "enhance/surface_constraints.h"

#include "meshprep/core/mesh.h"

#include <vector>

namespace meshprep::detail {

struct RelocationWeights {
  std::vector<double> face;        ///< the statistic's weight of each face (by face index)
  double fidelity = 1;             ///< lambda of the face-fidelity residual
};

/// Where the vertices go (by vertex index), before they are put back onto the surface. Only the
/// corners of the statistic's tail (faces weighing more than 1) move, with every face around them
/// in the problem; the other vertices stay where they are. Runs on `threads` threads (Jacobian evaluation and factorisation).
std::vector<Vec3> relocate_on_surface(const TriMesh& mesh, const SurfaceConstraints& constraints,
                                      const RelocationWeights& weights, int threads);

}  // namespace meshprep::detail
