#pragma once
// Shape tests of the simplifier's guards and polish, without trigonometry.

#include "meshprep/core/mesh.h"

#include <algorithm>

namespace meshprep::detail {

/// Cosine of the triangle's smallest angle (the largest of its three angle cosines; the smallest
/// angle faces the shortest side); 1 for a triangle with a zero-length side.
inline double smallest_angle_cosine(const Vec3& a, const Vec3& b, const Vec3& c) {
  const Vec3 ab = b - a, bc = c - b, ca = a - c;
  const double lab = ab.norm(), lbc = bc.norm(), lca = ca.norm();
  if (lab == 0 || lbc == 0 || lca == 0) return 1.0;
  const double at_a = -ab.dot(ca) / (lab * lca), at_b = -bc.dot(ab) / (lbc * lab), at_c = -ca.dot(bc) / (lca * lbc);
  return std::max({at_a, at_b, at_c});
}

/// (b - a) x (c - a): twice the area times the unit normal.
inline Vec3 area_normal(const Vec3& a, const Vec3& b, const Vec3& c) { return (b - a).cross(c - a); }

}  // namespace meshprep::detail
