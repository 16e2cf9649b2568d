#pragma once
// Repair step 6 (repair.h), after the cuts: parts of the solid touching at a point or an edge, held apart.

#include "meshprep/core/mesh.h"

#include <cstddef>

namespace meshprep::detail {

/// Where split_nonmanifold left copies of one point (a bow-tie, two solids touching at a vertex or
/// along an edge), the copies' faces still touch there, which a tetrahedral mesher cannot take.
/// Each copy is moved into its own solid, against the area-weighted normal of its faces, by a
/// thousandth of its shortest edge: the solids then stay apart by a gap that small, and no face
/// turns over (that needs an angle under a thousandth of a radian). Returns the copies moved.
/// \pre consistently oriented, closed components outward
std::size_t separate_pinches(TriangleSoup& surface);

}  // namespace meshprep::detail
