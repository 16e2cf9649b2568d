#pragma once
// Repair step 6 (repair.h): which vertices are copies of one point (split_nonmanifold's copies,
// the cut's points rounded onto an input vertex).

#include "meshprep/core/mesh.h"

#include <algorithm>
#include <cstdint>
#include <numeric>
#include <tuple>
#include <vector>

namespace meshprep::detail {

/// For each vertex, the first vertex (in position order, then index) at exactly its place: equal
/// for copies of one point, its own index for a vertex alone at its place.
inline std::vector<std::uint32_t> first_at_same_place(const std::vector<Vec3>& points) {
  std::vector<std::uint32_t> order(points.size());
  std::iota(order.begin(), order.end(), 0u);
  const auto position = [&points](std::uint32_t v) { return std::tie(points[v].x(), points[v].y(), points[v].z(), v); };
  std::sort(order.begin(), order.end(), [&](std::uint32_t a, std::uint32_t b) { return position(a) < position(b); });
  std::vector<std::uint32_t> first(points.size());
  for (std::size_t i = 0; i < order.size(); ++i)
    first[order[i]] = i > 0 && points[order[i]] == points[order[i - 1]] ? first[order[i - 1]] : order[i];
  return first;
}

}  // namespace meshprep::detail
