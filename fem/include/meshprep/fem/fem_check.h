#pragma once
/// \file fem_check.h
/// A finite-element sanity check of a tetrahedral mesh: assemble the linear (P1) stiffness matrix
/// K_ij = int grad phi_i . grad phi_j of the Poisson problem -lap u = f with Eigen's sparse
/// matrices and solve two problems whose exact solutions are known. The Dirichlet nodes are the
/// vertices of boundary_faces (of the faces used by exactly one tet when boundary_faces is empty)
/// and get the exact values; the other nodes of the tets are the unknowns. The one matrix is solved
/// for both problems by Jacobi-preconditioned conjugate gradients to a relative residual of 1e-14
/// (a sparse LDL^T factorisation takes over if CG does not converge):
/// - the patch test: u = 1 + 2x - 3y + 0.5z (f = 0) must be reproduced to round-off at every
///   node (P1 contains linear functions);
/// - u = x^2 + y^2 + z^2 (f = -6, load f V/4 per vertex of each tet): the L2 error of the
///   discrete solution, integrated tet by tet with a symmetric 14-point rule of degree 5 (exact for
///   the degree-4 integrand), falls ~4x when the mesh is refined 2x (second order).
/// It proves the mesh works in a real solve, which no peer tool reports.

#include "meshprep/fem/tet_mesh.h"

#include <nlohmann/json.hpp>

namespace meshprep {

struct FemCheckResult {
  double patch_test_max_error = 0;  ///< max nodal |u_h - u| for the linear field, / max |u|
  double poisson_l2_error = 0;      ///< ||u_h - u||_L2 for u = x^2 + y^2 + z^2
  double poisson_l2_relative = 0;   ///< / ||u||_L2
  double h_max = 0;                 ///< longest edge
  std::size_t unknowns = 0;         ///< nodes of the tets that are not Dirichlet nodes
  bool solver_converged = false;    ///< true whenever run_fem_check returns (it throws otherwise)
};

/// \throws InvalidInput if the mesh has no tets, a tet of volume <= 0 or an index past the points;
///         SolverError if neither the factorisation nor conjugate gradients solve the system.
FemCheckResult run_fem_check(const TetMesh& mesh);

nlohmann::ordered_json to_json(const FemCheckResult& result);

}  // namespace meshprep
