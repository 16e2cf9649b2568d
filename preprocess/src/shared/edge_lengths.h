#pragma once
// A mesh's typical edge length: the unit of the simplifier's costs and of the enhancement's
// shortest crease.

#include "meshprep/core/mesh.h"

#include <algorithm>
#include <cstddef>
#include <vector>

namespace meshprep::detail {

/// Median length of the mesh's edges (deleted ones skipped); 0 if it has none.
inline double median_edge_length(const TriMesh& mesh) {
  std::vector<double> lengths;
  lengths.reserve(mesh.n_edges());
  for (const auto e : mesh.edges()) lengths.push_back(mesh.calc_edge_length(e));
  if (lengths.empty()) return 0;
  const auto middle = lengths.begin() + static_cast<std::ptrdiff_t>(lengths.size() / 2);
  std::nth_element(lengths.begin(), middle, lengths.end());
  return *middle;
}

}  // namespace meshprep::detail
