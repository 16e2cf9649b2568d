#include "neighbour_pairs.h"

#include <Eigen/Geometry>
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <array>
#include <limits>

namespace meshprep::detail {
namespace {

using Box3 = Eigen::AlignedBox3d;

// Unit vector along d, scaled by its largest coordinate first so that no square under- or
// overflows: each coordinate is then within a few units of 2^-53 of the exact one.
Vec3 unit(const Vec3& d) { return (d / d.cwiseAbs().maxCoeff()).normalized(); }

// Covers the rounding of the unit vectors many times over. It is a length on the unit sphere of
// directions, so it does not depend on the mesh's scale, and it only widens a filter: the answers
// come from the exact tests.
constexpr double kRoundingMargin = 0x1p-40;

// The directions from corner v of the face (v, b, c) are the shorter great-circle arc between the
// unit vectors u and w towards b and c. Each point of the arc lies within the sagitta
// 1 - cos(alpha / 2) <= sin^2(alpha / 2) = |u - w|^2 / 4 of the chord [u, w] (alpha the angle
// between u and w), so the chord's box grown by that much holds the arc.
Box3 direction_box(const Vec3& v, const Vec3& b, const Vec3& c) {
  const Vec3 to_b = b - v, to_c = c - v;
  if (!to_b.allFinite() || !to_c.allFinite()) {  // beyond the double range: every direction
    const double infinity = std::numeric_limits<double>::infinity();
    return Box3(Vec3::Constant(-infinity), Vec3::Constant(infinity));
  }
  const Vec3 u = unit(to_b), w = unit(to_c);
  const double margin = (u - w).squaredNorm() / 4 + kRoundingMargin;
  return Box3(u.cwiseMin(w) - Vec3::Constant(margin), u.cwiseMax(w) + Vec3::Constant(margin));
}

// The corners the faces have in common, ascending, padded with the largest value.
std::array<std::uint32_t, 3> common_corners(const Triangle& f, const Triangle& g) {
  std::array<std::uint32_t, 3> common;
  common.fill(std::numeric_limits<std::uint32_t>::max());
  int n = 0;
  for (auto u : f)
    if (std::find(g.begin(), g.end(), u) != g.end()) common[n++] = u;
  std::sort(common.begin(), common.end());
  return common;
}

// Sweep and prune (Baraff 1992; Cohen, Lin, Manocha and Ponamgi, I-COLLIDE 1995): the boxes in
// the order they start along the axis where they spread most, each compared with those that
// start before it ends. Calls visit(k, l) for every overlapping pair of boxes.
template <class Visit>
void for_each_overlapping_box_pair(const std::vector<Box3>& boxes, std::vector<std::uint32_t>& order, Visit visit) {
  Box3 starts;
  starts.setEmpty();
  for (const Box3& box : boxes)
    if (box.min().allFinite()) starts.extend(box.min());
  int axis = 0;
  if (!starts.isEmpty()) starts.sizes().maxCoeff(&axis);
  order.resize(boxes.size());
  for (std::uint32_t k = 0; k < order.size(); ++k) order[k] = k;
  std::sort(order.begin(), order.end(),
            [&](std::uint32_t k, std::uint32_t l) { return boxes[k].min()[axis] < boxes[l].min()[axis]; });
  for (std::size_t i = 0; i < order.size(); ++i) {
    const Box3& box = boxes[order[i]];
    for (std::size_t j = i + 1; j < order.size() && boxes[order[j]].min()[axis] <= box.max()[axis]; ++j)
      if (box.intersects(boxes[order[j]])) visit(order[i], order[j]);
  }
}

}  // namespace

void for_each_neighbour_pair(const SoupView& soup, const std::vector<char>& usable,
                             const std::function<void(std::size_t, std::size_t)>& visit) {
  // The usable faces around each vertex, vertex by vertex (compressed rows).
  const std::size_t points = soup.points.size();
  std::vector<std::size_t> first(points + 1, 0);
  for (std::size_t f = 0; f < soup.triangles.size(); ++f)
    if (usable[f])
      for (auto v : soup.triangles[f]) ++first[v + 1];
  for (std::size_t v = 0; v < points; ++v) first[v + 1] += first[v];
  std::vector<std::uint32_t> around(first[points]);
  std::vector<std::size_t> next(first.begin(), first.end() - 1);
  for (std::size_t f = 0; f < soup.triangles.size(); ++f)
    if (usable[f])
      for (auto v : soup.triangles[f]) around[next[v]++] = static_cast<std::uint32_t>(f);

  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, points), [&](const tbb::blocked_range<std::size_t>& range) {
    std::vector<Box3> boxes;
    std::vector<std::uint32_t> order;
    for (std::size_t v = range.begin(); v < range.end(); ++v) {
      const std::uint32_t* faces = around.data() + first[v];
      const std::size_t count = first[v + 1] - first[v];
      if (count < 2) continue;
      boxes.resize(count);
      for (std::size_t k = 0; k < count; ++k) {
        const Triangle& t = soup.triangles[faces[k]];
        const int at = t[0] == v ? 0 : t[1] == v ? 1 : 2;
        boxes[k] = direction_box(soup.points[v], soup.points[t[(at + 1) % 3]], soup.points[t[(at + 2) % 3]]);
      }
      // Faces with an edge in common both hold its direction, so their boxes always overlap. A pair
      // with several corners in common is seen around each of them and taken around the first.
      for_each_overlapping_box_pair(boxes, order, [&](std::uint32_t k, std::uint32_t l) {
        const std::uint32_t f = faces[k], g = faces[l];
        if (common_corners(soup.triangles[f], soup.triangles[g])[0] == v) visit(std::min(f, g), std::max(f, g));
      });
    }
  });
}

}  // namespace meshprep::detail
