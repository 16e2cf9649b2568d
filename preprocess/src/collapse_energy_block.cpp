#include "collapse_energy_block.h"

#include "meshprep/core/errors.h"

#include <Eigen/Core>

#include <algorithm>
#include <cmath>
#include <string>
#include <utility>

namespace meshprep::detail {
namespace {

constexpr int kMax = kMaxBlockCentres;
using Bordered = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, 0, kMax + 4, kMax + 4>;
using Basis = Eigen::Matrix<double, Eigen::Dynamic, 4, 0, kMax, 4>;
using Column = Eigen::Matrix<double, Eigen::Dynamic, 1, 0, kMax, 1>;
// Same rank threshold as thin_plate_spline.cpp: unit-size centres within ~1e-10 of a plane are coplanar.
constexpr double kRankThreshold = 1e-10;
constexpr double kEightPi = 8.0 * M_PI;

// Gaussian elimination with partial pivoting of `matrix` (size x size, overwritten) for two
// right-hand sides, solved in place. Eigen's PartialPivLU on a runtime-sized matrix goes through
// its blocked GEMM path, which at this size (~18) costs 6 us a solve against ~1.5 us here, and
// the simplifier does ~10^5 of them (bench/RESULTS.md). Returns false if a pivot vanishes.
bool solve_two(Bordered& matrix, int size, double (*rhs)[2]) {
  for (int k = 0; k < size; ++k) {
    int pivot = k;
    for (int i = k + 1; i < size; ++i)
      if (std::abs(matrix(i, k)) > std::abs(matrix(pivot, k))) pivot = i;
    if (!(std::abs(matrix(pivot, k)) > 0)) return false;
    if (pivot != k) {
      matrix.row(k).swap(matrix.row(pivot));
      std::swap(rhs[k][0], rhs[pivot][0]);
      std::swap(rhs[k][1], rhs[pivot][1]);
    }
    const double inverse = 1.0 / matrix(k, k);
    for (int i = k + 1; i < size; ++i) {
      matrix(i, k) *= inverse;  // the multipliers, kept in column k
      rhs[i][0] -= matrix(i, k) * rhs[k][0];
      rhs[i][1] -= matrix(i, k) * rhs[k][1];
    }
    for (int j = k + 1; j < size; ++j) {  // column by column: contiguous in Eigen's column-major storage
      const double pivot_row = matrix(k, j);
      if (pivot_row == 0) continue;
      for (int i = k + 1; i < size; ++i) matrix(i, j) -= matrix(i, k) * pivot_row;
    }
  }
  for (int k = size - 1; k >= 0; --k) {  // back substitution, also column by column
    rhs[k][0] /= matrix(k, k);
    rhs[k][1] /= matrix(k, k);
    if (!std::isfinite(rhs[k][0]) || !std::isfinite(rhs[k][1])) return false;
    for (int i = 0; i < k; ++i) {
      rhs[i][0] -= matrix(i, k) * rhs[k][0];
      rhs[i][1] -= matrix(i, k) * rhs[k][1];
    }
  }
  return true;
}

}  // namespace

EnergyBlock collapse_energy_block(const Vec3* centres, int n, int a, int b) {
  constexpr const char* who = "collapse_energy_block";
  if (n < 4 || n > kMax) throw InvalidInput(std::string(who) + ": " + std::to_string(n) + " centres");
  Vec3 centroid = Vec3::Zero();
  for (int i = 0; i < n; ++i) centroid += centres[i];
  centroid /= n;
  double scale = 0;
  for (int i = 0; i < n; ++i) scale = std::max(scale, (centres[i] - centroid).norm());
  if (!(scale > 0) || !std::isfinite(scale)) throw InvalidInput(std::string(who) + ": degenerate centres");

  // An orthonormal basis of range(B), B_i = (1, q_i): the centred coordinates are already
  // orthogonal to the constant column, so Gram-Schmidt on the three coordinate columns;
  // a column with (almost) nothing left is dropped (coplanar centres: rank 3).
  Basis basis(n, 4);
  basis.col(0).setConstant(1.0 / std::sqrt(static_cast<double>(n)));
  int rank = 1;
  for (int axis = 0; axis < 3; ++axis) {
    Column column(n);
    for (int i = 0; i < n; ++i) column[i] = (centres[i][axis] - centroid[axis]) / scale;
    const double original = column.norm();
    for (int pass = 0; pass < 2; ++pass)  // twice: orthogonal to round-off even for nearly dependent columns
      for (int k = 1; k < rank; ++k) column -= basis.col(k).dot(column) * basis.col(k);
    const double remaining = column.norm();
    if (remaining <= kRankThreshold * std::max(original, 1.0)) continue;
    basis.col(rank++) = column / remaining;
  }
  if (rank < 3) throw InvalidInput(std::string(who) + ": the centres are collinear");
  if (rank == n) return {};  // every deformation of the centres is affine: E = 0
  const int size = n + rank;
  Bordered bordered = Bordered::Zero(size, size);
  for (int i = 0; i < n; ++i) {
    for (int j = 0; j < i; ++j) {
      const double r = (centres[i] - centres[j]).norm() / scale;  // phi(r) = r on the unit-size centres
      if (r == 0) throw InvalidInput(std::string(who) + ": two centres coincide");
      bordered(i, j) = bordered(j, i) = r;
    }
  }
  bordered.topRightCorner(n, rank) = basis.leftCols(rank);
  bordered.bottomLeftCorner(rank, n) = basis.leftCols(rank).transpose();
  double columns[kMax + 4][2] = {};
  columns[a][0] = 1;
  columns[b][1] = 1;
  if (!solve_two(bordered, size, columns)) throw SolverError(std::string(who) + ": the bordered system is singular");
  // E = -8 pi M / scale (the volume kernel's sign; J scales as 1/length in R^3).
  const double factor = -kEightPi / scale;
  return {factor * columns[a][0], factor * columns[a][1], factor * columns[b][1]};
}

}  // namespace meshprep::detail
