#include "meshprep/quality/surface_distance.h"

#include "meshprep/core/errors.h"
#include "meshprep/core/origin_shift.h"
#include "meshprep/quality/triangle_bvh.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <numeric>
#include <random>

namespace meshprep {
namespace {

double triangle_area(const SoupView& s, const Triangle& t) {
  return 0.5 * (s.points[t[1]] - s.points[t[0]]).cross(s.points[t[2]] - s.points[t[0]]).norm();
}

Vec3 barycentric_point(const SoupView& s, const Triangle& t, double w1, double w2) {
  return (1 - w1 - w2) * s.points[t[0]] + w1 * s.points[t[1]] + w2 * s.points[t[2]];
}

// Exact distance of every point to the surface behind `bvh` (parallel; results in input order).
std::vector<double> distances_to(const TriangleBvh& bvh, const std::vector<Vec3>& points) {
  std::vector<double> d(points.size());
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, points.size(), 2048), [&](const auto& range) {
    for (std::size_t i = range.begin(); i != range.end(); ++i) d[i] = std::sqrt(bvh.closest_point(points[i]).squared_distance);
  });
  return d;
}

DirectedDistance one_direction(const SoupView& from, const TriangleBvh& to, const DistanceParams& params,
                               unsigned seed) {
  // 1. Area-weighted stratified random samples: face i gets floor(N A_i / A + u) points.
  const std::size_t n_faces = from.triangles.size();
  std::vector<double> areas(n_faces);
  for (std::size_t f = 0; f < n_faces; ++f) areas[f] = triangle_area(from, from.triangles[f]);
  const double total_area = std::accumulate(areas.begin(), areas.end(), 0.0);
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> uniform(0.0, 1.0);
  // Measured in chunks, so that memory does not grow with the sample count (10^6 by default);
  // the sums run in sample order, as they would over one array.
  constexpr std::size_t kChunk = 1 << 16;
  std::vector<Vec3> samples;
  std::vector<std::uint32_t> sample_face;
  samples.reserve(kChunk);
  sample_face.reserve(kChunk);
  std::vector<double> face_worst(n_faces, 0.0);
  std::size_t sampled = 0;
  double sum = 0, sum_sq = 0;
  DirectedDistance result;
  const auto measure_chunk = [&] {
    const std::vector<double> d = distances_to(to, samples);
    for (std::size_t i = 0; i < d.size(); ++i) {
      sum += d[i];
      sum_sq += d[i] * d[i];
      result.max = std::max(result.max, d[i]);
      face_worst[sample_face[i]] = std::max(face_worst[sample_face[i]], d[i]);
    }
    sampled += d.size();
    samples.clear();
    sample_face.clear();
  };
  for (std::size_t f = 0; f < n_faces; ++f) {
    const auto count = static_cast<std::size_t>(
        std::floor(static_cast<double>(params.samples) * areas[f] / total_area + uniform(rng)));
    for (std::size_t k = 0; k < count; ++k) {
      const double r1 = std::sqrt(uniform(rng)), r2 = uniform(rng);  // uniform on the triangle
      samples.push_back(barycentric_point(from, from.triangles[f], r1 * (1 - r2), r1 * r2));
      sample_face.push_back(static_cast<std::uint32_t>(f));
      if (samples.size() == kChunk) measure_chunk();
    }
  }
  measure_chunk();
  if (sampled > 0) {
    result.mean = sum / static_cast<double>(sampled);
    result.rms = std::sqrt(sum_sq / static_cast<double>(sampled));
  }

  // 2. Every referenced vertex, and 3. a dense grid on the faces with the worst samples:
  //    these only sharpen the maximum (they are not area-weighted).
  std::vector<Vec3> extra;
  std::vector<char> used(from.points.size(), 0);
  for (const Triangle& t : from.triangles)
    for (auto v : t) used[v] = 1;
  for (std::size_t v = 0; v < from.points.size(); ++v)
    if (used[v]) extra.push_back(from.points[v]);
  std::vector<std::uint32_t> order(n_faces);
  std::iota(order.begin(), order.end(), 0u);
  const std::size_t refine = std::min(params.refine_faces, n_faces);
  std::partial_sort(order.begin(), order.begin() + static_cast<std::ptrdiff_t>(refine), order.end(),
                    [&](std::uint32_t x, std::uint32_t y) { return face_worst[x] > face_worst[y] || (face_worst[x] == face_worst[y] && x < y); });
  const int g = params.refine_grid;
  for (std::size_t k = 0; k < refine; ++k)
    for (int i = 0; i <= g; ++i)
      for (int j = 0; i + j <= g; ++j)
        extra.push_back(barycentric_point(from, from.triangles[order[k]], double(i) / g, double(j) / g));
  for (double x : distances_to(to, extra)) result.max = std::max(result.max, x);
  result.points = sampled + extra.size();
  return result;
}

// The soup without zero-area triangles (they carry no surface and would attract no samples),
// moved by -shift: the soup itself where that changes nothing, else a copy kept in `copy`.
SoupView without_degenerate(const SoupView& s, const Vec3& shift, TriangleSoup& copy) {
  const auto has_area = [&](const Triangle& t) { return triangle_area(s, t) > 0; };
  if (shift.isZero() && std::all_of(s.triangles.begin(), s.triangles.end(), has_area)) return s;
  copy.points.reserve(s.points.size());
  for (std::size_t v = 0; v < s.points.size(); ++v) copy.points.push_back(s.points[v] - shift);
  for (const Triangle& t : s.triangles)
    if (has_area(t)) copy.triangles.push_back(t);
  return copy;
}

}  // namespace

double SurfaceDistance::rms() const { return std::sqrt(0.5 * (a_to_b.rms * a_to_b.rms + b_to_a.rms * b_to_a.rms)); }

SurfaceDistance surface_distance(const SoupView& a, const SoupView& b, const DistanceParams& params) {
  // Far from the origin, point-triangle distances are measured next to it (origin_shift.h).
  const Vec3 shift = origin_shift(a.points);
  TriangleSoup copy_a, copy_b;
  const SoupView sa = without_degenerate(a, shift, copy_a), sb = without_degenerate(b, shift, copy_b);
  if (sa.triangles.empty() || sb.triangles.empty())
    throw InvalidInput("surface distance: a surface has no triangle of positive area");
  const TriangleBvh bvh_a(sa), bvh_b(sb);
  SurfaceDistance result;
  result.a_to_b = one_direction(sa, bvh_b, params, params.seed);
  result.b_to_a = one_direction(sb, bvh_a, params, params.seed + 1);
  return result;
}

double bbox_diagonal(const SoupView& soup) {
  const Box3 box = bounding_box(soup);
  return box.isEmpty() ? 0.0 : box.diagonal().norm();
}

}  // namespace meshprep
