#pragma once
// One Jacobi iteration of the paper's RBF smoothing with feature lines (smooth.h).

#include "meshprep/core/mesh.h"
#include "meshprep/preprocess/smooth/smooth.h"

#include <vector>

namespace meshprep {

struct RbfIterationCounts {
  std::size_t feature_line = 0, corners = 0, boundary = 0, unfitted = 0, noise_creases = 0;
  std::size_t not_moved = 0;  // adaptive: no fit beat staying
  double noise = 0;           // adaptive: the noise level used
};

/// The new position of every vertex (indexed by vertex index); `mesh` is not changed.
std::vector<Vec3> rbf_smoothing_step(const TriMesh& mesh, const SmoothParams& params, RbfIterationCounts& counts);

}  // namespace meshprep
