#pragma once
// The first step of the tet improvement: tets flat to rounding that sit on the boundary, removed.

#include "meshprep/fem/tet_mesh.h"

#include <cstddef>

namespace meshprep::improve {

/// Removes every tet that is flat to rounding (certainly_positive neither way round, tet_quality.h:
/// its volume, of either sign, within the rounding of its evaluation) and has two
/// faces on the boundary: its four corners are boundary points in one plane, between the
/// boundary's two triangles and the two the tets inside use. TetGen leaves such tets where a
/// planar CAD face's points are coplanar only to rounding (a part rotated, or in metres), and no
/// move of the improvement can touch them (all their corners are on the boundary). Removing one
/// is a 2-2 flip of the boundary: the same (to rounding) plane, the same patch (both boundary
/// faces must have one tag), triangulated by the other diagonal; the volume changes by the flat
/// tet's, which is zero to rounding. Skipped (and left to the writers' refusal) where the other
/// diagonal is an edge of the boundary already (the boundary would stop being a manifold) or the
/// two faces' tags differ. Of two flat tets sharing a face one is removed per call: call again
/// until it returns 0. Returns the number removed.
std::size_t remove_flat_boundary_tets(TetMesh& mesh);

}  // namespace meshprep::improve
