#pragma once
/// \file triangle_intersection.h
/// Closed triangle-triangle and segment-triangle intersection tests (touching counts). Every
/// answer is exact: it rests on orientation signs alone (Shewchuk's adaptive predicates), never on
/// a constructed point or a tolerance. The triangles given must have area (`triangle_has_area`).

#include "meshprep/core/mesh.h"

namespace meshprep {

/// Exact sign of the orientation of d with respect to the plane (a, b, c): +1, -1, or 0 when the
/// four points are coplanar.
int orientation_sign(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d);

/// Exact: do a, b, c span a triangle with area (are they not collinear)?
bool triangle_has_area(const Vec3& a, const Vec3& b, const Vec3& c);

/// Do the closed triangles (a0,a1,a2) and (b0,b1,b2) share a point?
bool triangles_intersect(const Vec3& a0, const Vec3& a1, const Vec3& a2, const Vec3& b0, const Vec3& b1,
                         const Vec3& b2);

/// Does the closed segment (p, q) meet the closed triangle (a, b, c)?
bool segment_intersects_triangle(const Vec3& p, const Vec3& q, const Vec3& a, const Vec3& b, const Vec3& c);

/// Do the faces (s0, s1, oa) and (s1, s0, ob), neighbours across the edge s0-s1, fold onto each
/// other (coplanar, with oa and ob on the same side of the edge)?
bool neighbours_fold(const Vec3& s0, const Vec3& s1, const Vec3& oa, const Vec3& ob);

}  // namespace meshprep
