#pragma once
// The exact sign of a tet's orientation, from Shewchuk's adaptive-precision orient3d ("Adaptive
// precision floating-point arithmetic and fast robust geometric predicates", 1997) as TetGen 1.5
// ships it: no move of the improvement is kept unless every tet it makes is positive by this test.

#include "meshprep/core/mesh.h"

namespace meshprep::improve {

/// True when (b - a) . ((c - a) x (d - a)) > 0 exactly (the tet a, b, c, d is positively oriented).
bool positively_oriented(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d);

}  // namespace meshprep::improve
