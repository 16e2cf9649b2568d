#pragma once
// The unknowns of a vertex during enhancement: coordinates in its tangent plane, lifted onto a
// quadratic height map of the surface around it (or a line for crease and boundary vertices).

#include "meshprep/core/mesh.h"

namespace meshprep::detail {

/// x(u, v) = origin + u t1 + v t2 + (c0 u^2 + c1 u v + c2 v^2 + c3 u + c4 v) normal.
/// A Line vertex has t2 = 0 and no height; a fixed vertex is a chart whose (u, v) stay 0.
struct VertexChart {
  Vec3 origin = Vec3::Zero(), t1 = Vec3::Zero(), t2 = Vec3::Zero(), normal = Vec3::Zero();
  double height[5] = {0, 0, 0, 0, 0};

  // Exact tests: the tangents are scaled to the mesh's units (in_units_of), so a relative
  // isZero() would call a chart on a part a micrometre wide fixed.
  bool fixed() const { return t1 == Vec3::Zero(); }
  bool on_line() const { return t2 == Vec3::Zero(); }

  template <typename T>
  void position(const T* uv, T* x) const {
    const T& u = uv[0];
    const T& v = uv[1];
    const T h = height[0] * u * u + height[1] * u * v + height[2] * v * v + height[3] * u + height[4] * v;
    for (int i = 0; i < 3; ++i) x[i] = origin[i] + t1[i] * u + t2[i] * v + normal[i] * h;
  }
};

/// A chart through `origin` with the given unit normal: t1, t2 complete it to a right-handed
/// orthonormal frame, and the height map is the least-squares quadratic through the origin that
/// fits `neighbours` (left flat when they do not determine it).
VertexChart surface_chart(const Vec3& origin, const Vec3& normal, const std::vector<Vec3>& neighbours);

/// A chart sliding along the unit `direction` through `origin`.
VertexChart line_chart(const Vec3& origin, const Vec3& direction);

/// A chart that cannot move.
VertexChart fixed_chart(const Vec3& origin);

/// The same chart with its unknowns in units of `length` (u' = u / length): the solver's
/// tolerances are absolute (Ceres stops on |step| <= (|x| + 1e-8) 1e-8 and on a gradient under
/// 1e-10), so unknowns in the mesh's own units made the result depend on millimetres vs metres.
VertexChart in_units_of(VertexChart chart, double length);

}  // namespace meshprep::detail
