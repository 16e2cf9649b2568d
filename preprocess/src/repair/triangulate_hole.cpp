#include "repair/triangulate_hole.h"

#include <algorithm>
#include <cstddef>
#include <utility>

namespace meshprep::detail {
namespace {

constexpr double kTie = 1e-9;  // relative; rounding leaves ~1e-15

}  // namespace

// O(n^2) memory, O(n^3) time: weight(i, k) is the best triangulation of the rim's
// sub-polygon i, i + 1, ..., k closed by the chord k -> i, made of that of (i, m), that of
// (m, k) and the face (k, m, i), over every m in between. The dihedral angle is compared through
// its cosine (the largest angle is the smallest cosine).
std::vector<Triangle> triangulate_hole(const std::vector<Vec3>& points, const HoleRim& rim,
                                       const std::unordered_set<std::uint64_t>& edges, bool dihedral) {
  const std::vector<std::uint32_t>& v = rim.vertices;
  const std::size_t n = v.size();
  if (n < 3) return {};
  const auto at = [n](std::size_t i, std::size_t k) { return i * n + k; };
  std::vector<double> cosine(n * n, 1.0), area(n * n, 0.0);
  std::vector<std::uint32_t> split(n * n, UINT32_MAX);
  std::vector<Vec3> normal(dihedral ? n * n : 0);
  const auto solved = [&](std::size_t i, std::size_t k) { return k == i + 1 || split[at(i, k)] != UINT32_MAX; };
  // The normal across the side i-k of the sub-polygon: the surface's face on a rim edge, else
  // the face the sub-polygon's triangulation puts there.
  const auto across = [&](std::size_t i, std::size_t k) -> const Vec3& {
    return k == i + 1 ? rim.face_normals[i] : normal[at(i, k)];
  };
  for (std::size_t length = 2; length < n; ++length)
    for (std::size_t i = 0; i + length < n; ++i) {
      const std::size_t k = i + length;
      const bool last = i == 0 && k == n - 1;  // the chord n-1 -> 0 is the rim's last edge
      if (!last && edges.count(edge_key(v[i], v[k]))) continue;
      double best_cosine = -2, best_area = 0;
      for (std::size_t m = i + 1; m < k; ++m) {
        if (!solved(i, m) || !solved(m, k)) continue;
        const Vec3 &pi = points[v[i]], &pm = points[v[m]], &pk = points[v[k]];
        const Vec3 twice = (pm - pk).cross(pi - pk);
        const double twice_area = twice.norm();
        // Collinear corners (a straight stretch of rim) make no face.
        if (too_thin(twice_area, pm - pk, pi - pk)) continue;
        const double face_area = area[at(i, m)] + area[at(m, k)] + twice_area / 2;
        double face_cosine = std::min(cosine[at(i, m)], cosine[at(m, k)]);
        if (dihedral) {
          const Vec3 unit = twice / twice_area;
          face_cosine = std::min({face_cosine, unit.dot(across(i, m)), unit.dot(across(m, k))});
          if (last) face_cosine = std::min(face_cosine, unit.dot(rim.face_normals[n - 1]));
        }
        // Ties within rounding (a planar hole: every cosine 1 and every area the same) go to the
        // first candidate, so that the choice does not depend on the scale.
        if (face_cosine > best_cosine + kTie ||
            (face_cosine >= best_cosine - kTie && face_area < best_area * (1 - kTie))) {
          best_cosine = face_cosine;
          best_area = face_area;
          split[at(i, k)] = static_cast<std::uint32_t>(m);
          if (dihedral) normal[at(i, k)] = twice / twice_area;
        }
      }
      cosine[at(i, k)] = best_cosine;
      area[at(i, k)] = best_area;
    }
  if (!solved(0, n - 1)) return {};
  std::vector<Triangle> faces;
  std::vector<std::pair<std::size_t, std::size_t>> pending{{0, n - 1}};
  while (!pending.empty()) {
    const auto [i, k] = pending.back();
    pending.pop_back();
    const std::size_t m = split[at(i, k)];
    faces.push_back({v[k], v[m], v[i]});
    if (m - i >= 2) pending.emplace_back(i, m);
    if (k - m >= 2) pending.emplace_back(m, k);
  }
  return faces;
}

}  // namespace meshprep::detail
