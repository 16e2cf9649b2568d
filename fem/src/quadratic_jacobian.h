#pragma once
// The Jacobian of a second-order (10-node) tet's map from the reference tet: its scaled value at
// the nodes (the quality measure, tet_quality.h) and a lower bound over the whole element from its
// Bezier coefficients (the validity test of make_quadratic, quadratic.h). Shared by both.
//
// The map x(l) = sum_i l_i (2 l_i - 1) x_i + sum_{i<j} 4 l_i l_j m_ij in barycentric coordinates
// l (corners x_i, mid-edge nodes m_ij). Its derivative along the reference edge from corner c to
// corner k is G_k - G_c, with G_k = dx/dl_k = sum_j l_j g_kj, g_kk = 3 x_k, g_kj = 4 m_kj - x_k
// (j != k; the constant -x_k of (4 l_k - 1) x_k written as -x_k sum_j l_j on the simplex).

#include "meshprep/fem/tet_mesh.h"

#include <array>

namespace meshprep::detail {

/// The ten nodes of tet t of a second-order mesh: its corners, then its mid-edge nodes in
/// kTetEdges' order; for a linear mesh the mid-edge nodes are the edges' midpoints.
std::array<Vec3, 10> tet_nodes(const TetMesh& mesh, std::size_t t);

/// det J at the ten nodes, the smallest of it and of its scaled value.
struct NodalJacobian {
  /// The smallest scaled Jacobian over the ten nodes: at each node and for each corner c, the
  /// determinant of the derivatives along the three reference edges from c over the product of
  /// their lengths, times sqrt(2) (1 for the regular straight tet). For a straight tet every node
  /// gives Verdict's tet_scaled_jacobian (tet_quality.h). 0 where a derivative vanishes.
  double min_scaled = 0;
  /// The smallest det J (for the count of tets with a non-positive Jacobian).
  double min = 0;
};
NodalJacobian nodal_jacobian(const std::array<Vec3, 10>& x);

/// The smallest Bezier (Bernstein) coefficient of det J, a cubic polynomial on the element: a
/// lower bound of det J everywhere on it, equal to det J at the corners (Johnen, Remacle &
/// Geuzaine, "Geometrical validity of curvilinear finite elements", J. Comput. Phys. 233, 2013).
double jacobian_lower_bound(const std::array<Vec3, 10>& x);

/// det J of the straight tet of the corners, (x1 - x0) . ((x2 - x0) x (x3 - x0)) = 6 x its volume.
double straight_jacobian(const std::array<Vec3, 10>& x);

}  // namespace meshprep::detail
