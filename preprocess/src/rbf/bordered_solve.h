#pragma once
// One solve of eq. (2)'s bordered system, fast at the partition of unity's patch sizes.

#include <Eigen/Core>

namespace meshprep::detail {

struct BorderedSolution {
  Eigen::VectorXd gamma;       ///< the kernel weights
  Eigen::VectorXd polynomial;  ///< v, the polynomial's coefficients
};

/// [A B; B^T 0][gamma; v] = [h; 0] for a kernel conditionally positive definite with respect to
/// B's columns (Z^T A Z > 0, Z a basis of null(B^T)), by the null-space method as
/// thin_plate_spline.cpp's BorderedSystem, but for a single right-hand side and about twice as
/// fast at 40-90 rows: B's Householder reflectors go to both sides of A at once, on the part of A
/// that Z^T A Z comes from, and the Cholesky factor is unblocked. Results agree with
/// BorderedSystem's to ~1e-12 relative.
/// \throws InvalidInput "`who`: the points are `degenerate`" if B has not full column rank (pivots
///         below rank_threshold relative to the largest); SolverError if Z^T A Z is not definite.
BorderedSolution solve_bordered(const Eigen::MatrixXd& a, const Eigen::MatrixXd& b, const Eigen::VectorXd& h,
                                double rank_threshold, const char* degenerate, const char* who);

}  // namespace meshprep::detail
