#include "meshprep/quality/triangle_intersection.h"

#include "robust_predicates.h"

#include <algorithm>
#include <array>
#include <cmath>

namespace meshprep {
namespace {

using Vec2 = Eigen::Vector2d;

int sign_of(double value) { return (value > 0) - (value < 0); }

int orient2d(const Vec2& a, const Vec2& b, const Vec2& c) { return sign_of(detail::orient2d(a, b, c)); }

// c on the closed segment [a, b], given that the three are collinear.
bool within_segment(const Vec2& a, const Vec2& b, const Vec2& c) {
  return std::min(a.x(), b.x()) <= c.x() && c.x() <= std::max(a.x(), b.x()) && std::min(a.y(), b.y()) <= c.y() &&
         c.y() <= std::max(a.y(), b.y());
}

bool segments_intersect_2d(const Vec2& p1, const Vec2& q1, const Vec2& p2, const Vec2& q2) {
  const int o1 = orient2d(p1, q1, p2), o2 = orient2d(p1, q1, q2);
  const int o3 = orient2d(p2, q2, p1), o4 = orient2d(p2, q2, q1);
  if (o1 * o2 < 0 && o3 * o4 < 0) return true;
  return (o1 == 0 && within_segment(p1, q1, p2)) || (o2 == 0 && within_segment(p1, q1, q2)) ||
         (o3 == 0 && within_segment(p2, q2, p1)) || (o4 == 0 && within_segment(p2, q2, q1));
}

bool point_in_triangle_2d(const Vec2& p, const std::array<Vec2, 3>& t) {
  const int s0 = orient2d(t[0], t[1], p), s1 = orient2d(t[1], t[2], p), s2 = orient2d(t[2], t[0], p);
  return (s0 >= 0 && s1 >= 0 && s2 >= 0) || (s0 <= 0 && s1 <= 0 && s2 <= 0);
}

// Drops the coordinate along which the plane normal is largest (the best-conditioned projection).
struct PlaneProjection {
  int u = 0, v = 1;
  explicit PlaneProjection(const Vec3& normal) {
    int drop = 0;
    normal.cwiseAbs().maxCoeff(&drop);
    u = (drop + 1) % 3;
    v = (drop + 2) % 3;
  }
  Vec2 operator()(const Vec3& p) const { return {p[u], p[v]}; }
};

bool coplanar_triangles_intersect(const std::array<Vec3, 3>& a, const std::array<Vec3, 3>& b) {
  const PlaneProjection project((a[1] - a[0]).cross(a[2] - a[0]));
  std::array<Vec2, 3> a2, b2;
  for (int i = 0; i < 3; ++i) {
    a2[i] = project(a[i]);
    b2[i] = project(b[i]);
  }
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      if (segments_intersect_2d(a2[i], a2[(i + 1) % 3], b2[j], b2[(j + 1) % 3])) return true;
  return point_in_triangle_2d(a2[0], b2) || point_in_triangle_2d(b2[0], a2);
}

// The part of triangle t that lies in the plane whose sides are given by `signs` and signed
// distances `dist`, as an interval along `direction`.
std::pair<double, double> plane_cut_interval(const std::array<Vec3, 3>& t, const std::array<int, 3>& signs,
                                             const std::array<double, 3>& dist, const Vec3& direction) {
  double lo = INFINITY, hi = -INFINITY;
  auto add = [&](const Vec3& p) {
    const double s = p.dot(direction);
    lo = std::min(lo, s);
    hi = std::max(hi, s);
  };
  for (int i = 0; i < 3; ++i) {
    const int j = (i + 1) % 3;
    if (signs[i] == 0) add(t[i]);
    if (signs[i] * signs[j] < 0) add(t[i] + (dist[i] / (dist[i] - dist[j])) * (t[j] - t[i]));
  }
  return {lo, hi};
}

}  // namespace

int orientation_sign(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) {
  return sign_of(detail::orient3d(a, b, c, d));
}

bool triangles_intersect(const Vec3& a0, const Vec3& a1, const Vec3& a2, const Vec3& b0, const Vec3& b1,
                         const Vec3& b2) {
  const std::array<Vec3, 3> a{a0, a1, a2}, b{b0, b1, b2};
  // orient3d values are proportional to the signed distances to the other plane (exact sign).
  std::array<int, 3> sb{}, sa{};
  std::array<double, 3> db{}, da{};
  for (int i = 0; i < 3; ++i) {
    db[i] = detail::orient3d(a0, a1, a2, b[i]);
    da[i] = detail::orient3d(b0, b1, b2, a[i]);
    sb[i] = sign_of(db[i]);
    sa[i] = sign_of(da[i]);
  }
  auto all_one_side = [](const std::array<int, 3>& s) {
    return (s[0] > 0 && s[1] > 0 && s[2] > 0) || (s[0] < 0 && s[1] < 0 && s[2] < 0);
  };
  if (all_one_side(sa) || all_one_side(sb)) return false;
  auto all_zero = [](const std::array<int, 3>& s) { return s[0] == 0 && s[1] == 0 && s[2] == 0; };
  if (all_zero(sa) || all_zero(sb)) return coplanar_triangles_intersect(a, b);
  // Both triangles cross the other's plane: compare their cuts along the planes' common line.
  const Vec3 direction = (a1 - a0).cross(a2 - a0).cross((b1 - b0).cross(b2 - b0));
  const auto [a_lo, a_hi] = plane_cut_interval(a, sa, da, direction);
  const auto [b_lo, b_hi] = plane_cut_interval(b, sb, db, direction);
  return a_lo <= b_hi && b_lo <= a_hi;
}

bool neighbours_fold(const Vec3& s0, const Vec3& s1, const Vec3& oa, const Vec3& ob) {
  if (orientation_sign(s0, s1, oa, ob) != 0) return false;
  const PlaneProjection project((s1 - s0).cross(oa - s0));
  const int side_a = orient2d(project(s0), project(s1), project(oa));
  return side_a != 0 && side_a == orient2d(project(s0), project(s1), project(ob));
}

bool segment_intersects_triangle(const Vec3& p, const Vec3& q, const Vec3& a, const Vec3& b, const Vec3& c) {
  const int sp = orientation_sign(a, b, c, p), sq = orientation_sign(a, b, c, q);
  if (sp * sq > 0) return false;
  if (sp == 0 && sq == 0) {
    const PlaneProjection project((b - a).cross(c - a));
    const std::array<Vec2, 3> t{project(a), project(b), project(c)};
    const Vec2 p2 = project(p), q2 = project(q);
    for (int i = 0; i < 3; ++i)
      if (segments_intersect_2d(p2, q2, t[i], t[(i + 1) % 3])) return true;
    return point_in_triangle_2d(p2, t);
  }
  // The segment crosses (or touches) the plane; the line pq passes through the closed triangle
  // iff it turns the same way around all three edges (signed volumes, zero allowed).
  const int s0 = orientation_sign(p, q, a, b), s1 = orientation_sign(p, q, b, c), s2 = orientation_sign(p, q, c, a);
  return (s0 >= 0 && s1 >= 0 && s2 >= 0) || (s0 <= 0 && s1 <= 0 && s2 <= 0);
}

}  // namespace meshprep
