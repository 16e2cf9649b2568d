#include "repair/separate_pinches.h"

#include "repair/same_place.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

namespace meshprep::detail {

std::size_t separate_pinches(TriangleSoup& surface) {
  const std::size_t n = surface.points.size();
  std::vector<Vec3> normal_sum(n, Vec3::Zero());
  std::vector<double> shortest(n, std::numeric_limits<double>::infinity());
  std::vector<char> used(n, 0);
  for (const Triangle& t : surface.triangles) {
    const Vec3 &a = surface.points[t[0]], &b = surface.points[t[1]], &c = surface.points[t[2]];
    const Vec3 area_normal = (b - a).cross(c - a);
    for (int i = 0; i < 3; ++i) {
      const std::uint32_t v = t[i];
      used[v] = 1;
      normal_sum[v] += area_normal;
      const double edge = (surface.points[t[(i + 1) % 3]] - surface.points[v]).norm();
      shortest[v] = std::min(shortest[v], edge);
      shortest[t[(i + 1) % 3]] = std::min(shortest[t[(i + 1) % 3]], edge);
    }
  }
  // A used vertex is a copy if another used vertex sits at its place.
  const std::vector<std::uint32_t> first = first_at_same_place(surface.points);
  std::vector<std::uint32_t> used_here(n, 0);
  for (std::uint32_t v = 0; v < n; ++v) used_here[first[v]] += used[v];
  std::vector<std::uint32_t> copies;
  for (std::uint32_t v = 0; v < n; ++v)
    if (used[v] && used_here[first[v]] > 1) copies.push_back(v);
  std::size_t moved = 0;
  for (const std::uint32_t v : copies) {
    const double length = normal_sum[v].norm();
    if (!(length > 0) || !std::isfinite(shortest[v])) continue;
    surface.points[v] -= normal_sum[v] / length * (1e-3 * shortest[v]);
    ++moved;
  }
  return moved;
}

}  // namespace meshprep::detail
