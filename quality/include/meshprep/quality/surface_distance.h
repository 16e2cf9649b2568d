#pragma once
/// \file surface_distance.h
/// Distances between two surfaces by dense sampling, with the exact point-triangle distance
/// through a BVH. Per direction: `samples` area-weighted stratified random points (face i gets
/// floor(N A_i / A + u) points), every vertex, and a dense barycentric grid on the faces that hold
/// the worst random samples (so the sampled Hausdorff distance approaches the true one).

#include "meshprep/core/mesh.h"
#include "meshprep/core/soup_view.h"

namespace meshprep {

struct DistanceParams {
  std::size_t samples = 1000000;  ///< random samples per direction
  std::size_t refine_faces = 256;  ///< faces re-sampled densely per direction (Hausdorff refinement)
  int refine_grid = 40;            ///< grid resolution per refined face: (g+1)(g+2)/2 points
  unsigned seed = 12345;
};

/// One direction: distances from points of `from` to the surface `to`.
struct DirectedDistance {
  double max = 0;   ///< over random samples, vertices and refinement points
  double mean = 0;  ///< over the random samples (area-weighted estimate)
  double rms = 0;
  std::size_t points = 0;
};

struct SurfaceDistance {
  DirectedDistance a_to_b, b_to_a;
  double hausdorff() const { return a_to_b.max > b_to_a.max ? a_to_b.max : b_to_a.max; }
  double mean() const { return 0.5 * (a_to_b.mean + b_to_a.mean); }
  double rms() const;  ///< sqrt of the mean of both directions' mean squared distance
};

/// Symmetric distance between surfaces a and b (deterministic for a seed, whatever the threads).
/// \throws InvalidInput if either surface has no triangle of positive area.
SurfaceDistance surface_distance(const SoupView& a, const SoupView& b, const DistanceParams& params = {});

/// Bounding-box diagonal of the referenced vertices of a soup.
double bbox_diagonal(const SoupView& soup);

}  // namespace meshprep
