#pragma once
// A mesh's typical edge length: the unit of the simplifier's costs, of the enhancement's
// shortest crease and of the repair's welding distance.

#include "meshprep/core/mesh.h"

#include <algorithm>
#include <cstddef>
#include <vector>

namespace meshprep::detail {

/// The median of `lengths` (reordered); 0 if empty.
inline double median_of(std::vector<double>& lengths) {
  if (lengths.empty()) return 0;
  const auto middle = lengths.begin() + static_cast<std::ptrdiff_t>(lengths.size() / 2);
  std::nth_element(lengths.begin(), middle, lengths.end());
  return *middle;
}

/// Median length of the mesh's edges (deleted ones skipped); 0 if it has none.
inline double median_edge_length(const TriMesh& mesh) {
  std::vector<double> lengths;
  lengths.reserve(mesh.n_edges());
  for (const auto e : mesh.edges()) lengths.push_back(mesh.calc_edge_length(e));
  return median_of(lengths);
}

/// The same for a soup, which need not be a manifold: each face's three edges (a shared edge
/// counts once per face).
inline double median_edge_length(const TriangleSoup& soup) {
  std::vector<double> lengths;
  lengths.reserve(3 * soup.triangles.size());
  for (const Triangle& t : soup.triangles)
    for (int k = 0; k < 3; ++k) lengths.push_back((soup.points[t[k]] - soup.points[t[(k + 1) % 3]]).norm());
  return median_of(lengths);
}

}  // namespace meshprep::detail
