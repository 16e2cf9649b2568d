#include "rbf/bordered_solve.h"

#include "meshprep/core/errors.h"

#include <Eigen/Cholesky>
#include <Eigen/QR>

#include <cmath>
#include <string>

namespace meshprep::detail {
namespace {

using Eigen::Index;
using Eigen::MatrixXd;
using Eigen::VectorXd;

// The Cholesky factor L of a symmetric positive definite matrix, in its lower triangle (the upper
// one is not read), column by column. Eigen's LLT works in blocks from 32 rows on, which at these
// sizes costs twice as much. False if the matrix is not positive definite.
bool cholesky_in_place(Eigen::Ref<MatrixXd> a) {
  const Index n = a.rows();
  for (Index j = 0; j < n; ++j) {
    const double pivot = a(j, j) - a.row(j).head(j).squaredNorm();
    if (!(pivot > 0)) return false;
    a(j, j) = std::sqrt(pivot);
    const Index below = n - j - 1;
    a.col(j).tail(below).noalias() -= a.bottomLeftCorner(below, j) * a.row(j).head(j).transpose();
    a.col(j).tail(below) /= a(j, j);
  }
  return true;
}

}  // namespace

BorderedSolution solve_bordered(const MatrixXd& a, const MatrixXd& b, const VectorXd& h, double rank_threshold,
                                const char* degenerate, const char* who) {
  Eigen::ColPivHouseholderQR<MatrixXd> qr;
  qr.setThreshold(rank_threshold);
  qr.compute(b);
  if (qr.rank() < b.cols()) throw InvalidInput(std::string(who) + ": the points are " + degenerate);
  // Q^T A Q = H_r ... H_1 A H_1 ... H_r, and Z^T A Z is its lower right block. H_k = I - tau v v^T
  // leaves the first k rows and columns alone, so it is applied to the trailing block only, to
  // both sides at once: H A H = A - v w^T - w v^T, w = tau A v - (tau^2 / 2) (v^T A v) v
  // (Golub & Van Loan, Matrix Computations, 5.1.4). Z^T h comes with it.
  const Index n = a.rows(), free = n - b.cols();
  MatrixXd rotated = a;
  VectorXd rotated_h = h;
  for (Index k = 0; k < b.cols(); ++k) {
    const Index m = n - k;
    VectorXd v(m);
    v << 1.0, qr.matrixQR().col(k).tail(m - 1);
    const double tau = qr.hCoeffs()[k];
    auto trailing = rotated.bottomRightCorner(m, m);
    VectorXd w = tau * (trailing.selfadjointView<Eigen::Lower>() * v);
    w -= (0.5 * tau * w.dot(v)) * v;
    trailing.selfadjointView<Eigen::Lower>().rankUpdate(v, w, -1.0);
    rotated_h.tail(m) -= (tau * v.dot(rotated_h.tail(m))) * v;
  }
  const auto reduced = rotated.bottomRightCorner(free, free);
  if (!cholesky_in_place(reduced)) throw SolverError(std::string(who) + ": kernel matrix not definite");
  VectorXd delta = rotated_h.tail(free);  // (Z^T A Z) delta = Z^T h
  reduced.triangularView<Eigen::Lower>().solveInPlace(delta);
  reduced.triangularView<Eigen::Lower>().adjoint().solveInPlace(delta);
  VectorXd padded = VectorXd::Zero(n);
  padded.tail(free) = delta;
  BorderedSolution s;
  s.gamma = qr.householderQ() * padded;  // Z delta
  s.polynomial = qr.solve(h - a * s.gamma);
  return s;
}

}  // namespace meshprep::detail
