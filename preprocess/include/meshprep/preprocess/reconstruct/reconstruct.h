#pragma once
/// \file reconstruct.h
/// Scattered points -> a triangle mesh over their footprint (the paper's Section 3): the
/// partition of unity (partition_of_unity.h) evaluated on a regular grid of the reference plane,
/// two triangles per grid cell. Large missing areas are not papered over: a triangle whose centre
/// is farther than max_gap (in the plane) from every sample is left out and counted, and so are
/// the triangles that would then touch the rest at a single vertex (the mesh stays manifold).

#include "meshprep/core/mesh.h"
#include "meshprep/core/taken_back.h"
#include "meshprep/preprocess/reconstruct/partition_of_unity.h"

#include <nlohmann/json_fwd.hpp>

#include <cstddef>
#include <vector>

namespace meshprep {

struct ReconstructParams {
  PartitionOfUnityParams fit;
  std::size_t columns = 300, rows = 300;  ///< grid vertices along the footprint's x and y
  double spacing = 0;  ///< > 0: grid spacing in the plane instead of columns and rows
  std::size_t vertices = 0;  ///< > 0: about this many grid vertices on square cells (overrides the above)
  /// Largest distance from a triangle's centre to the nearest sample (in the plane); <= 0 = 3 x
  /// the median distance between a sample and its nearest neighbour.
  double max_gap = 0;
  /// Keep the triangles over interior gaps (holes in the data: left-out regions that do not reach
  /// the grid's border) and list them in ReconstructResult::filled_faces, and keep only the
  /// largest connected piece, so that a disc-like footprint gives one boundary loop (what closing
  /// the surface into a block needs). The surface over a filled gap is the partition of unity's
  /// extrapolation: flagged, never silent.
  bool fill_holes = false;
};

struct ReconstructResult {
  TriangleSoup mesh;
  std::size_t patches = 0;
  double max_gap = 0;            ///< the value used
  std::size_t columns = 0, rows = 0;  ///< the (uniform) grid's vertices along x and y
  std::size_t gap_triangles = 0;  ///< left out: over a gap, touching the rest at a vertex only, or (fill_holes) a smaller piece
  std::size_t filled_triangles = 0;       ///< fill_holes: kept over interior gaps (grid triangles)
  std::vector<std::size_t> filled_faces;  ///< fill_holes: those faces' indices in `mesh` (empty from reconstruct_adaptive)
  Vec3 normal = Vec3::UnitZ();    ///< of the reference plane (the PCA frame of the points)
  double variation_threshold = 0;  ///< the sigma threshold applied
  std::size_t grown_patches = 0;  ///< patches whose support grew (sigma above the threshold)
  std::vector<double> patch_variation;   ///< sigma of each patch
  std::vector<double> vertex_variation;  ///< sigma at each mesh vertex (the patches' sigma, blended)
  double seconds = 0;                    ///< the whole call (the fit and the grid)
  std::vector<TakenBack> taken_back;     ///< reconstruct_adaptive: what its simplification took back
};

/// \throws InvalidInput as PartitionOfUnity, if --vertices is given for points on a line, or if the grid has fewer than 2 x 2 vertices or more
///         than 10^8.
ReconstructResult reconstruct_surface(const std::vector<Vec3>& points, const ReconstructParams& params = {});

/// reconstruct_surface in its two steps, for compositions that use the fit again
/// (adaptive_reconstruction.h). The first: the partition of unity of `points`, after checking the
/// grid parameters. \throws InvalidInput as reconstruct_surface, for the same causes first.
PartitionOfUnity fit_surface(const std::vector<Vec3>& points, const ReconstructParams& params);

/// The second: `fit` meshed on the grid of `params`, `refinement` (>= 1) times finer along each
/// axis than params say (columns and rows in the result are those of the grid params say).
/// \throws InvalidInput as reconstruct_surface does for the grid.
ReconstructResult mesh_surface(const PartitionOfUnity& fit, const ReconstructParams& params, std::size_t refinement = 1);

/// The run as `meshprep reconstruct --json` writes it, in this order: vertices, faces, grid
/// {columns, rows}, patches, leaf_size, neighbors, variation {rule, threshold, growth,
/// grown_patches, patch_sigma, vertex_sigma}, max_gap, gap_faces_left_out, fill_holes,
/// filled_faces, reference_normal, guards_taken_back (json_values.h), time_seconds.
nlohmann::ordered_json to_json(const ReconstructResult& result, const ReconstructParams& params);

}  // namespace meshprep
