#include "shared/spatial_order.h"

#include <algorithm>
#include <cstdint>
#include <numeric>

namespace meshprep::detail {
namespace {

// The 21 low bits of x spread to every third bit (the interleaving step of a 3D Morton code).
std::uint64_t spread_bits(std::uint64_t x) {
  x &= 0x1fffff;
  x = (x | x << 32) & 0x1f00000000ffffULL;
  x = (x | x << 16) & 0x1f0000ff0000ffULL;
  x = (x | x << 8) & 0x100f00f00f00f00fULL;
  x = (x | x << 4) & 0x10c30c30c30c30c3ULL;
  x = (x | x << 2) & 0x1249249249249249ULL;
  return x;
}

}  // namespace

std::vector<std::uint32_t> morton_order(const std::vector<Vec3>& points) {
  const std::size_t n = points.size();
  std::vector<std::uint32_t> order(n);
  std::iota(order.begin(), order.end(), 0u);
  if (n == 0) return order;
  Vec3 low = points.front(), high = low;
  for (const Vec3& p : points) {
    low = low.cwiseMin(p);
    high = high.cwiseMax(p);
  }
  const Vec3 extent = (high - low).cwiseMax(Vec3::Constant(1e-300));
  std::vector<std::uint64_t> key(n);
  for (std::size_t i = 0; i < n; ++i) {
    const Vec3 cell = (points[i] - low).cwiseQuotient(extent) * 2097151.0;  // 21 bits an axis
    key[i] = spread_bits(static_cast<std::uint64_t>(cell.x())) | spread_bits(static_cast<std::uint64_t>(cell.y())) << 1 |
             spread_bits(static_cast<std::uint64_t>(cell.z())) << 2;
  }
  std::stable_sort(order.begin(), order.end(), [&](std::uint32_t a, std::uint32_t b) { return key[a] < key[b]; });
  return order;
}

TriangleSoup in_spatial_order(const TriangleSoup& soup) {
  const std::size_t n = soup.points.size();
  if (n == 0) return soup;
  const std::vector<std::uint32_t> order = morton_order(soup.points);
  TriangleSoup sorted;
  sorted.points.reserve(n);
  std::vector<std::uint32_t> new_index(n);
  for (std::size_t k = 0; k < n; ++k) {
    new_index[order[k]] = static_cast<std::uint32_t>(k);
    sorted.points.push_back(soup.points[order[k]]);
  }
  std::vector<Triangle> renumbered;
  renumbered.reserve(soup.triangles.size());
  for (const Triangle& t : soup.triangles) renumbered.push_back({new_index[t[0]], new_index[t[1]], new_index[t[2]]});
  std::vector<std::uint32_t> face_order(renumbered.size());
  std::iota(face_order.begin(), face_order.end(), 0u);
  std::stable_sort(face_order.begin(), face_order.end(), [&](std::uint32_t a, std::uint32_t b) {
    const Triangle &s = renumbered[a], &t = renumbered[b];
    return std::min({s[0], s[1], s[2]}) < std::min({t[0], t[1], t[2]});
  });
  sorted.triangles.reserve(renumbered.size());
  for (const std::uint32_t f : face_order) sorted.triangles.push_back(renumbered[f]);
  if (!soup.patches.empty())  // each face keeps its patch
    for (const std::uint32_t f : face_order) sorted.patches.push_back(soup.patches[f]);
  sorted.patch_names = soup.patch_names;
  return sorted;
}

}  // namespace meshprep::detail
