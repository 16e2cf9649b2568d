#pragma once
/// \file triangle_metrics.h
/// Shape measures of one triangle. Definitions (the names are the JSON keys):
/// - radius_ratio = R / (2 r), circumradius over twice the inradius: 1 for an equilateral
///   triangle, +inf for a degenerate one. With edge lengths a, b, c and area A,
///   R = abc / (4A) and r = 2A / (a+b+c), so R/(2r) = abc (a+b+c) / (16 A^2).
/// - aspect_ratio = l_max (a+b+c) / (4 sqrt(3) A) (the Verdict/VTK triangle aspect ratio; 1 for
///   equilateral, +inf for degenerate).
/// - min_angle_deg, max_angle_deg: interior angles in degrees, from atan2(|u x v|, u.v) (accurate
///   for angles near 0 and 180 degrees, unlike acos).
/// - area.

#include "meshprep/core/mesh.h"
#include "meshprep/core/soup_view.h"

#include <limits>
#include <vector>

namespace meshprep {

struct TriangleShape {
  double radius_ratio = 0;
  double aspect_ratio = 0;
  double min_angle_deg = 0;
  double max_angle_deg = 0;
  double area = 0;
  /// Zero area (collinear or repeated corners): the ratios are +inf and the angles are those of
  /// the flat triangle (0 and 180 for distinct collinear corners, NaN for repeated corners).
  bool degenerate = false;
};

/// Shape of the triangle (a, b, c).
TriangleShape triangle_shape(const Vec3& a, const Vec3& b, const Vec3& c);

/// R / (2 r) from the side lengths and the area (> 0): R = abc / (4A), r = 2A / (a + b + c).
inline double radius_ratio_of(double la, double lb, double lc, double area) {
  return la * lb * lc * (la + lb + lc) / (16.0 * area * area);
}

/// TriangleShape::radius_ratio alone (no angles: for hot paths), +inf for a degenerate triangle.
inline double radius_ratio(const Vec3& a, const Vec3& b, const Vec3& c) {
  const double area = 0.5 * (b - a).cross(c - a).norm();
  if (!(area > 0)) return std::numeric_limits<double>::infinity();
  return radius_ratio_of((b - a).norm(), (c - b).norm(), (a - c).norm(), area);
}

/// A point just off a triangle, on the side its normal (a, b, c counter-clockwise) points to, and
/// the triangle's inradius r = 2A / (a + b + c).
struct PointOffFace {
  Vec3 point;
  double inradius = 0;  ///< 0 for a degenerate triangle (point is then a)
};

/// The centroid moved r / 1000 along the unit normal: far enough that which side of the surface
/// it is on is certain (a solid angle from it is accurate to ~1e-13; TetGen locates it), near
/// enough that no other sheet of a valid surface passes between the face and it.
inline PointOffFace point_off_face(const Vec3& a, const Vec3& b, const Vec3& c) {
  const Vec3 n = (b - a).cross(c - a);
  const double perimeter = (b - a).norm() + (c - b).norm() + (a - c).norm();
  const double inradius = perimeter > 0 ? n.norm() / perimeter : 0;
  if (!(inradius > 0)) return {a, 0};
  return {(a + b + c) / 3 + n.normalized() * (1e-3 * inradius), inradius};
}

/// Signed volume enclosed by the surface's faces, sum of (p0 - o) . ((p1 - o) x (p2 - o)) / 6 with o a
/// corner of the first face (divergence theorem; o near the surface keeps the figure exact far
/// from the origin); meaningful for a closed, consistently oriented surface (positive for outward normals).
double signed_volume(const SoupView& soup);

/// Shape of every triangle of a surface (a TriangleSoup, or a TriMesh through MeshSoupView), in face
/// order (parallel over faces).
std::vector<TriangleShape> triangle_shapes(const SoupView& soup);

}  // namespace meshprep
