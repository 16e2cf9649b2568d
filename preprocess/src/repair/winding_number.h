#pragma once
// Repair step 6 (repair.h): which side of a surface crossing itself is inside.

#include "meshprep/core/mesh.h"

namespace meshprep::detail {

/// The generalised winding number of `soup` at `q` (Jacobson et al. 2013): the solid angles its
/// faces subtend at q, summed and divided by 4 pi. For a closed, outward surface it counts how
/// many times the surface wraps q: 0 outside, 1 inside, 2 where two parts overlap; for an open
/// surface it changes by 1 across it. Each solid angle after Van Oosterom and Strackee 1983.
/// \pre q is not on the surface
double winding_number(const TriangleSoup& soup, const Vec3& q);

}  // namespace meshprep::detail
