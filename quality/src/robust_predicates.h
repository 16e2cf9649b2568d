#pragma once
// Exact orientation predicates: a floating-point filter that settles almost every call, and an
// exact evaluation in integers (GMP) for the rest. Exact signs make the self-intersection test
// agree with CGAL's exact predicates on the near-degenerate configurations decimated meshes are
// full of (needles sharing a vertex, coplanar folds on CAD faces). Private to quality/; pure
// functions without global state, safe from any thread.

#include "meshprep/core/mesh.h"

namespace meshprep::detail {

/// Positive if d lies below the plane through a, b, c (a, b, c counter-clockwise seen from above),
/// negative if above, exactly zero if coplanar: the sign of det(a - d, b - d, c - d), exact. The
/// magnitude approximates six times the volume; where the filter decides, it is the plain
/// floating-point determinant, bit for bit Shewchuk's (and TetGen's) orient3d.
/// \pre finite coordinates
double orient3d(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d);

/// Positive if a, b, c are counter-clockwise, negative if clockwise, exactly zero if collinear: the
/// sign of det(a - c, b - c), exact; the magnitude as for orient3d (twice the signed area).
/// \pre finite coordinates
double orient2d(const Eigen::Vector2d& a, const Eigen::Vector2d& b, const Eigen::Vector2d& c);

/// The exact evaluations behind the filters (tests reach them to check them on their own): the
/// determinant rounded towards zero to a double, never zero unless the determinant is.
double orient3d_exact(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d);
double orient2d_exact(const Eigen::Vector2d& a, const Eigen::Vector2d& b, const Eigen::Vector2d& c);

}  // namespace meshprep::detail
