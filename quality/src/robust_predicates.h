#pragma once
// Shewchuk's adaptive exact orientation predicates, as compiled into Debian's TetGen library
// (predicates.cxx of TetGen 1.5). Private to quality/: the only place that sees tetgen.h.
// Exact signs make the self-intersection test agree with CGAL's exact predicates on the
// near-degenerate configurations decimated meshes are full of (needles sharing a vertex,
// coplanar folds on CAD faces).

#include "meshprep/core/mesh.h"

namespace meshprep::detail {

/// (Re)initialises the predicates' constants with TetGen's static filter off, so that results do
/// not depend on the bounding box of whatever TetGen meshed last. Call it before a batch of
/// predicate calls, from one thread, while TetGen is not running.
void reset_robust_predicates();

/// Positive if d lies below the plane through a, b, c (a, b, c counter-clockwise seen from above),
/// negative if above, exactly zero if coplanar; the magnitude approximates six times the volume.
double orient3d(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d);

/// Positive if a, b, c are counter-clockwise, negative if clockwise, exactly zero if collinear.
double orient2d(const Eigen::Vector2d& a, const Eigen::Vector2d& b, const Eigen::Vector2d& c);

}  // namespace meshprep::detail
