#pragma once
// Procedural tetrahedral meshes for the FEM tests.

#include "meshprep/fem/tet_mesh.h"

namespace meshprep::test {

/// The cube [0, size]^3 cut into n^3 cells of 6 tets each (Freudenthal/Kuhn subdivision: every
/// tet shares the cell diagonal), all positively oriented. Tets with centroid x < size/2 are in
/// region 1, the others in region 2 (when n is even the split is exact). Boundary faces are
/// outward oriented and tagged by side: 1 x=0, 2 x=size, 3 y=0, 4 y=size, 5 z=0, 6 z=size.
/// Volume size^3, 6 n^3 tets, (n+1)^3 points, 12 n^2 boundary faces.
TetMesh cube_tets(int n, double size = 1.0);

}  // namespace meshprep::test
