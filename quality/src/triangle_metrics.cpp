#include "meshprep/quality/triangle_metrics.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace meshprep {
namespace {

constexpr double kRadToDeg = 180.0 / M_PI;

// Interior angle between u and v, accurate near 0 and 180 degrees.
double angle_deg(const Vec3& u, const Vec3& v) { return std::atan2(u.cross(v).norm(), u.dot(v)) * kRadToDeg; }

}  // namespace

TriangleShape triangle_shape(const Vec3& a, const Vec3& b, const Vec3& c) {
  TriangleShape s;
  const Vec3 ab = b - a, bc = c - b, ca = a - c;
  const double la = ab.norm(), lb = bc.norm(), lc = ca.norm();
  s.area = 0.5 * ab.cross(-ca).norm();
  const double angle_a = angle_deg(ab, -ca), angle_b = angle_deg(-ab, bc), angle_c = angle_deg(-bc, ca);
  s.min_angle_deg = std::min({angle_a, angle_b, angle_c});
  s.max_angle_deg = std::max({angle_a, angle_b, angle_c});
  if (!(s.area > 0)) {
    constexpr double inf = std::numeric_limits<double>::infinity();
    s.degenerate = true;
    s.radius_ratio = s.aspect_ratio = inf;
    if (la == 0 || lb == 0 || lc == 0) s.min_angle_deg = s.max_angle_deg = std::numeric_limits<double>::quiet_NaN();
    return s;
  }
  const double perimeter = la + lb + lc;
  s.radius_ratio = radius_ratio_of(la, lb, lc, s.area);
  s.aspect_ratio = std::max({la, lb, lc}) * perimeter / (4.0 * std::sqrt(3.0) * s.area);
  return s;
}

double signed_volume(const SoupView& soup) {
  if (soup.triangles.empty()) return 0;
  // Cones from a corner of the surface, not from the origin: far from the origin (a survey at
  // 1e9 m) the products of absolute coordinates cancel to nothing.
  const Vec3 apex = soup.points[soup.triangles.front()[0]];
  double six_volume = 0;
  for (const Triangle& t : soup.triangles) {
    const Vec3 a = soup.points[t[0]] - apex, b = soup.points[t[1]] - apex, c = soup.points[t[2]] - apex;
    six_volume += a.dot(b.cross(c));
  }
  return six_volume / 6.0;
}

std::vector<TriangleShape> triangle_shapes(const SoupView& soup) {
  std::vector<TriangleShape> shapes(soup.triangles.size());
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, shapes.size(), 4096), [&](const auto& range) {
    for (std::size_t f = range.begin(); f != range.end(); ++f) {
      const Triangle& t = soup.triangles[f];
      shapes[f] = triangle_shape(soup.points[t[0]], soup.points[t[1]], soup.points[t[2]]);
    }
  });
  return shapes;
}

}  // namespace meshprep
