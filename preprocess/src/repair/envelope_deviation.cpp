#include "repair/envelope_deviation.h"

#include "repair/winding_number.h"

#include "meshprep/quality/triangle_bvh.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>

namespace meshprep::detail {

namespace {

// Listed places lie this many cells apart at least.
constexpr double kPlaceSpacing = 10;
// The soup's vertices are tested this fraction of a cell off the surface, each way.
constexpr double kSideOffset = 1e-3;

// The points of `surface` measured: vertices, face centres, edge middles (each edge from both faces).
std::vector<Vec3> surface_samples(const TriangleSoup& surface) {
  std::vector<Vec3> samples = surface.points;
  samples.reserve(surface.points.size() + 4 * surface.triangles.size());
  for (const Triangle& t : surface.triangles) {
    const Vec3 &a = surface.points[t[0]], &b = surface.points[t[1]], &c = surface.points[t[2]];
    samples.push_back((a + b + c) / 3);
    samples.push_back(0.5 * (a + b));
    samples.push_back(0.5 * (b + c));
    samples.push_back(0.5 * (c + a));
  }
  return samples;
}

// The soup's vertices on the boundary of what it encloses (the winding number crosses one half
// across them, along their area-weighted normal).
std::vector<Vec3> outer_vertices(const TriangleSoup& soup, double offset) {
  std::vector<Vec3> normal(soup.points.size(), Vec3::Zero());
  std::vector<char> used(soup.points.size(), 0);
  for (const Triangle& t : soup.triangles) {
    const Vec3 area_normal = (soup.points[t[1]] - soup.points[t[0]]).cross(soup.points[t[2]] - soup.points[t[0]]);
    for (const std::uint32_t v : t) {
      normal[v] += area_normal;
      used[v] = 1;
    }
  }
  const WindingNumber winding(soup);
  std::vector<char> outer(soup.points.size(), 0);
  tbb::parallel_for(std::size_t{0}, soup.points.size(), [&](std::size_t v) {
    const double length = normal[v].norm();
    if (!used[v] || !(length > 0)) return;
    const Vec3 step = normal[v] / length * offset;
    outer[v] = winding.at(soup.points[v] + step) < 0.5 && winding.at(soup.points[v] - step) >= 0.5;
  });
  std::vector<Vec3> points;
  for (std::size_t v = 0; v < soup.points.size(); ++v)
    if (outer[v]) points.push_back(soup.points[v]);
  return points;
}

// Distances from each point to the surface of `to`.
std::vector<double> distances(const std::vector<Vec3>& points, const TriangleSoup& to) {
  const TriangleBvh faces(to);
  std::vector<double> d(points.size());
  tbb::parallel_for(std::size_t{0}, points.size(),
                    [&](std::size_t i) { d[i] = std::sqrt(faces.closest_point(points[i]).squared_distance); });
  return d;
}

}  // namespace

EnvelopeDeviation envelope_deviation(const TriangleSoup& surface, const TriangleSoup& soup, double bound, double cell,
                                     std::size_t max_places) {
  std::vector<Vec3> points = surface_samples(surface);
  std::vector<double> d = distances(points, soup);
  const std::vector<Vec3> outer = outer_vertices(soup, kSideOffset * cell);
  const std::vector<double> back = distances(outer, surface);
  points.insert(points.end(), outer.begin(), outer.end());
  d.insert(d.end(), back.begin(), back.end());

  EnvelopeDeviation deviation;
  deviation.samples = d.size();
  double squares = 0;
  std::vector<std::size_t> over;
  for (std::size_t i = 0; i < d.size(); ++i) {
    deviation.max = std::max(deviation.max, d[i]);
    squares += d[i] * d[i];
    if (d[i] > bound) over.push_back(i);
  }
  deviation.rms = d.empty() ? 0 : std::sqrt(squares / static_cast<double>(d.size()));
  deviation.over_bound = over.size();
  std::sort(over.begin(), over.end(), [&](std::size_t a, std::size_t b) { return d[a] > d[b]; });
  const double apart = kPlaceSpacing * cell;
  for (const std::size_t i : over) {
    if (deviation.places.size() == max_places) break;
    const bool near_listed = std::any_of(deviation.places.begin(), deviation.places.end(), [&](const DeviationPlace& p) {
      return (p.point - points[i]).norm() < apart;
    });
    if (!near_listed) deviation.places.push_back({points[i], d[i]});
  }
  return deviation;
}

}  // namespace meshprep::detail
