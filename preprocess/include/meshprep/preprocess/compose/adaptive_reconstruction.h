#pragma once
/// \file adaptive_reconstruction.h
/// Adaptive remeshing by local features (the paper's stated next step), a composition of two
/// stages: the reconstruction (reconstruct.h) on a grid twice as fine along each axis (four times
/// the faces), simplified back (simplify.h, bending-energy edge collapse) to the uniform grid's
/// face count. Vertices stay dense where the surface bends (high sigma, high curvature) and thin
/// out where it is flat; the simplifier pins boundary vertices, so the rim keeps the fine spacing.

#include "meshprep/core/mesh.h"
#include "meshprep/preprocess/reconstruct/reconstruct.h"

#include <functional>
#include <vector>

namespace meshprep {

struct AdaptiveReconstructParams {
  ReconstructParams reconstruct;  ///< the uniform grid whose face count is kept, the fit, gaps and holes
  std::function<void(double)> progress;  ///< called with the fraction done (the simplification)
};

/// The reconstruction of `points` with vertices placed by local features. The result is
/// reconstruct_surface's for the finer grid, but: `mesh` and `vertex_variation` (the partition of
/// unity's sigma at the new vertices) are the simplified mesh's; `filled_faces` is empty (the
/// faces are new; filled_triangles still counts the grid's); columns and rows are the uniform
/// grid's. \throws InvalidInput as reconstruct_surface does.
ReconstructResult reconstruct_adaptive(const std::vector<Vec3>& points, const AdaptiveReconstructParams& params = {});

}  // namespace meshprep
