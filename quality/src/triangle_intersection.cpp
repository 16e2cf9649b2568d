#include "meshprep/quality/triangle_intersection.h"

#include "robust_predicates.h"

#include <algorithm>
#include <array>
#include <cmath>

namespace meshprep {
namespace {

using Vec2 = Eigen::Vector2d;
using Corners = std::array<Vec3, 3>;

int sign_of(double value) { return (value > 0) - (value < 0); }

int orient2d(const Vec2& a, const Vec2& b, const Vec2& c) { return sign_of(detail::orient2d(a, b, c)); }

// The two coordinates left when the axis `drop` is dropped: an exact projection (no arithmetic).
struct AxisProjection {
  int u, v;
  explicit AxisProjection(int drop) : u((drop + 1) % 3), v((drop + 2) % 3) {}
  Vec2 operator()(const Vec3& p) const { return {p[u], p[v]}; }
};

// The component along axis k of the normal (b - a) x (c - a) is the orientation of the triangle
// projected along k, so its sign is exact. The axis whose component is largest (the projection
// that keeps the most area), or -1 if all three vanish: a, b, c are collinear.
int dominant_normal_axis(const Vec3& a, const Vec3& b, const Vec3& c) {
  int axis = -1;
  double largest = 0;
  for (int k = 0; k < 3; ++k) {
    const AxisProjection project(k);
    const double component = std::abs(detail::orient2d(project(a), project(b), project(c)));
    if (component > largest) {
      largest = component;
      axis = k;
    }
  }
  return axis;
}

// Projection of the plane of a non-degenerate triangle along an axis its normal is not orthogonal
// to: an affine bijection of that plane onto a coordinate plane, so points of the plane meet, and
// lie on either side of one another's lines, exactly as their projections do.
AxisProjection plane_projection(const Vec3& a, const Vec3& b, const Vec3& c) {
  return AxisProjection(std::max(dominant_normal_axis(a, b, c), 0));
}

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

std::array<Vec2, 3> projected(const Corners& t, const AxisProjection& project) {
  return {project(t[0]), project(t[1]), project(t[2])};
}

bool coplanar_triangles_intersect(const Corners& a, const Corners& b) {
  const AxisProjection project = plane_projection(a[0], a[1], a[2]);
  const std::array<Vec2, 3> a2 = projected(a, project), b2 = projected(b, project);
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      if (segments_intersect_2d(a2[i], a2[(i + 1) % 3], b2[j], b2[(j + 1) % 3])) return true;
  return point_in_triangle_2d(a2[0], b2) || point_in_triangle_2d(b2[0], a2);
}

// Does the closed segment pq meet the closed triangle t, given the exact sides sp, sq of p and q
// with respect to t's plane?
bool segment_meets_triangle(const Vec3& p, const Vec3& q, int sp, int sq, const Corners& t) {
  if (sp * sq > 0) return false;
  if (sp == 0 && sq == 0) {
    const AxisProjection project = plane_projection(t[0], t[1], t[2]);
    const std::array<Vec2, 3> t2 = projected(t, project);
    const Vec2 p2 = project(p), q2 = project(q);
    for (int i = 0; i < 3; ++i)
      if (segments_intersect_2d(p2, q2, t2[i], t2[(i + 1) % 3])) return true;
    return point_in_triangle_2d(p2, t2);
  }
  // The segment crosses (or touches) the plane at one point; the line pq passes through the closed
  // triangle iff it turns the same way around all three edges (signed volumes, zero allowed).
  const int s0 = orientation_sign(p, q, t[0], t[1]), s1 = orientation_sign(p, q, t[1], t[2]),
            s2 = orientation_sign(p, q, t[2], t[0]);
  return (s0 >= 0 && s1 >= 0 && s2 >= 0) || (s0 <= 0 && s1 <= 0 && s2 <= 0);
}

bool strictly_on_one_side(const std::array<int, 3>& s) {
  return (s[0] > 0 && s[1] > 0 && s[2] > 0) || (s[0] < 0 && s[1] < 0 && s[2] < 0);
}

bool all_zero(const std::array<int, 3>& s) { return s[0] == 0 && s[1] == 0 && s[2] == 0; }

// Does an edge of `t` (whose corners lie on the sides `sides` of the plane of `other`) meet `other`?
bool an_edge_meets(const Corners& t, const std::array<int, 3>& sides, const Corners& other) {
  for (int i = 0; i < 3; ++i) {
    const int j = (i + 1) % 3;
    if (segment_meets_triangle(t[i], t[j], sides[i], sides[j], other)) return true;
  }
  return false;
}

}  // namespace

int orientation_sign(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) {
  return sign_of(detail::orient3d(a, b, c, d));
}

bool triangle_has_area(const Vec3& a, const Vec3& b, const Vec3& c) { return dominant_normal_axis(a, b, c) >= 0; }

bool triangles_intersect(const Vec3& a0, const Vec3& a1, const Vec3& a2, const Vec3& b0, const Vec3& b1,
                         const Vec3& b2) {
  const Corners a{a0, a1, a2}, b{b0, b1, b2};
  std::array<int, 3> sa{}, sb{};  // the sides of a's corners of b's plane, and of b's corners of a's
  for (int i = 0; i < 3; ++i) {
    sa[i] = orientation_sign(b0, b1, b2, a[i]);
    sb[i] = orientation_sign(a0, a1, a2, b[i]);
  }
  if (strictly_on_one_side(sa) || strictly_on_one_side(sb)) return false;
  if (all_zero(sa) || all_zero(sb)) return coplanar_triangles_intersect(a, b);
  // The planes cross along a line that holds the intersection, a segment (or a point). Each end of
  // it lies on an edge of a or of b (a point inside both triangles has some of the line on either
  // side of it in both), so the triangles meet iff an edge of one meets the other: exact signs
  // only, as in the orientation-based tests of Guigue and Devillers (JGT 8(1), 2003).
  return an_edge_meets(a, sa, b) || an_edge_meets(b, sb, a);
}

bool neighbours_fold(const Vec3& s0, const Vec3& s1, const Vec3& oa, const Vec3& ob) {
  if (orientation_sign(s0, s1, oa, ob) != 0) return false;
  const AxisProjection project = plane_projection(s0, s1, oa);
  const int side_a = orient2d(project(s0), project(s1), project(oa));
  return side_a != 0 && side_a == orient2d(project(s0), project(s1), project(ob));
}

bool segment_intersects_triangle(const Vec3& p, const Vec3& q, const Vec3& a, const Vec3& b, const Vec3& c) {
  return segment_meets_triangle(p, q, orientation_sign(a, b, c, p), orientation_sign(a, b, c, q), {a, b, c});
}

}  // namespace meshprep
