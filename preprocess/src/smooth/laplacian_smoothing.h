#pragma once
// The baselines of meshprep smooth: Taubin's lambda|mu smoothing and OpenMesh's Laplace smoother.

#include "meshprep/core/mesh.h"

#include <cstddef>

namespace meshprep {

/// Taubin (1995): per iteration a step lambda = 0.5 then mu = -0.53 along the uniform Laplacian
/// (the mean of the 1-ring minus the vertex), Jacobi; boundary vertices stay.
void taubin_smooth(TriMesh& mesh, std::size_t iterations);

/// OpenMesh's JacobiLaplaceSmootherT (uniform weights, tangential and normal, C0).
void laplace_smooth(TriMesh& mesh, std::size_t iterations);

}  // namespace meshprep
