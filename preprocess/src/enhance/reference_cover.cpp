#include "enhance/reference_cover.h"

#include "shared/triangle_angles.h"

#include "meshprep/quality/face_edges.h"
#include "meshprep/quality/triangle_bvh.h"

#include <algorithm>
#include <cmath>

namespace meshprep::detail {
namespace {

// Points along a bent edge are this fraction of the patch's size apart, and at most this many.
constexpr double kSamplesPerPatch = 8;
constexpr int kMostEdgeSamples = 16;

double distance_to_patch(const Vec3& p, const std::vector<Corners>& faces) {
  double nearest = INFINITY;
  for (const Corners& c : faces) nearest = std::min(nearest, (closest_point_on_triangle(p, c[0], c[1], c[2]) - p).squaredNorm());
  return std::sqrt(nearest);
}

// Which corner k of `face` starts the edge {a, b}.
int edge_index(const SoupView& soup, std::uint32_t face, std::uint32_t a, std::uint32_t b) {
  const auto& t = soup.triangles[face];
  for (int k = 0; k < 3; ++k) {
    const std::uint32_t p = t[static_cast<std::size_t>(k)], q = t[static_cast<std::size_t>((k + 1) % 3)];
    if ((p == a && q == b) || (p == b && q == a)) return k;
  }
  return -1;
}

// Calls visit(uses) for each bent edge of the reference, with the FaceEdge entries of its faces.
template <class Visit>
void for_each_bent_edge(const SoupView& reference, Visit visit) {
  const std::vector<FaceEdge> edges = sorted_face_edges(reference);
  for (std::size_t i = 0; i < edges.size();) {
    std::size_t j = i;
    while (j < edges.size() && edges[j].key == edges[i].key) ++j;
    if (j - i != 2 || unit_normal(reference, edges[i].face).dot(unit_normal(reference, edges[i + 1].face)) < kCoplanarCosine)
      visit(edges.data() + i, edges.data() + j);
    i = j;
  }
}

}  // namespace

std::vector<std::uint8_t> bent_reference_edges(const SoupView& reference) {
  std::vector<std::uint8_t> bent(reference.triangles.size(), 0);
  for_each_bent_edge(reference, [&](const FaceEdge* begin, const FaceEdge* end) {
    for (const FaceEdge* use = begin; use != end; ++use) {
      const int index = edge_index(reference, use->face, use->lo(), use->hi());
      if (index >= 0) bent[use->face] |= static_cast<std::uint8_t>(1u << index);
    }
  });
  return bent;
}

std::vector<Vec3> reference_probes(const SoupView& reference, double spacing) {
  std::vector<Vec3> probes(reference.points.size());
  for (std::size_t i = 0; i < probes.size(); ++i) probes[i] = reference.points[i];
  if (!(spacing > 0)) return probes;
  for_each_bent_edge(reference, [&](const FaceEdge* use, const FaceEdge*) {
    const Vec3 a = reference.points[use->lo()], b = reference.points[use->hi()];
    const auto pieces = static_cast<std::size_t>(std::ceil((b - a).norm() / spacing));
    for (std::size_t k = 1; k < pieces; ++k) probes.push_back(a + (b - a) * (static_cast<double>(k) / static_cast<double>(pieces)));
  });
  return probes;
}

bool keeps_reference_covered(const SurfaceConstraints& constraints, const std::vector<Corners>& before,
                             const std::vector<Corners>& after, const std::vector<std::pair<Vec3, Vec3>>& rim,
                             double limit, const std::vector<std::uint8_t>* bent) {
  Box3 box;
  box.setEmpty();
  for (const Corners& c : before)
    for (const Vec3& q : c) box.extend(q);
  const double spacing = box.diagonal().norm() / kSamplesPerPatch;
  box.min().array() -= limit;
  box.max().array() += limit;
  const SoupView& reference = constraints.reference_bvh().surface();
  bool covered = true;
  const auto check = [&](const Vec3& p) {
    if (!covered || !box.contains(p)) return;
    const double old_distance = distance_to_patch(p, before);
    if (old_distance > limit) return;
    double to_rim = INFINITY;
    for (const auto& [a, b] : rim) to_rim = std::min(to_rim, (closest_point_on_segment(p, a, b) - p).norm());
    if (to_rim <= old_distance) return;
    if (distance_to_patch(p, after) > limit) covered = false;
  };
  constraints.reference_bvh().for_each_overlapping(box, [&](std::size_t face) {
    const auto& t = reference.triangles[face];
    for (const std::uint32_t corner : t) check(reference.points[corner]);
    if (!bent || !(*bent)[face] || !(spacing > 0)) return;
    for (int k = 0; k < 3; ++k) {
      if (!((*bent)[face] & (1u << k))) continue;
      const Vec3 a = reference.points[t[static_cast<std::size_t>(k)]], b = reference.points[t[static_cast<std::size_t>((k + 1) % 3)]];
      // The part of the edge inside the box (slab clipping), sampled.
      double t0 = 0, t1 = 1;
      for (int axis = 0; axis < 3 && t0 <= t1; ++axis) {
        const double d = b[axis] - a[axis];
        if (d == 0) {
          if (a[axis] < box.min()[axis] || a[axis] > box.max()[axis]) t1 = -1;
          continue;
        }
        double enter = (box.min()[axis] - a[axis]) / d, leave = (box.max()[axis] - a[axis]) / d;
        if (enter > leave) std::swap(enter, leave);
        t0 = std::max(t0, enter);
        t1 = std::min(t1, leave);
      }
      if (t0 > t1) continue;
      const int samples = std::clamp(static_cast<int>(std::ceil((t1 - t0) * (b - a).norm() / spacing)), 1, kMostEdgeSamples);
      for (int s = 0; s <= samples; ++s) check(a + (b - a) * (t0 + (t1 - t0) * s / samples));
    }
  });
  return covered;
}

}  // namespace meshprep::detail
