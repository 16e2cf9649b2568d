#include "rbf/collapse_energy_block.h"

#include "meshprep/core/errors.h"

#include <Eigen/Core>

#include <algorithm>
#include <cmath>
#include <string>

namespace meshprep::detail {
namespace {

constexpr int kMax = kMaxBlockCentres;
using Basis = Eigen::Matrix<double, Eigen::Dynamic, 4, 0, kMax, 4>;
using Column = Eigen::Matrix<double, Eigen::Dynamic, 1, 0, kMax, 1>;
// Same rank threshold as thin_plate_spline.cpp: unit-size centres within ~1e-10 of a plane are coplanar.
constexpr double kRankThreshold = 1e-10;
constexpr double kEightPi = 8.0 * M_PI;

// Plain arrays and loops: at this size (n ~ 8-13) Eigen's runtime-sized blocks cost more in
// dispatch than in arithmetic. S is the arrays' size; the kernel below is compiled for each common
// centre count n = S, so that every loop bound is a constant (bunny00 to 10 %: 19 % fewer
// instructions in this kernel, the same results to the bit).
template <int S>
using Square = double[S][S];
template <int S>
using Vector = double[S];

template <int S>
double dot(const Vector<S>& x, const Vector<S>& y, int from, int to) {
  double sum = 0;
  for (int i = from; i < to; ++i) sum += x[i] * y[i];
  return sum;
}

// x <- (I - 2 v v^T) x on [from, n) (|v| = 1, v zero before `from`).
template <int S>
void reflect(Vector<S>& x, const Vector<S>& v, int from, int n) {
  const double t = 2 * dot<S>(v, x, from, n);
  for (int i = from; i < n; ++i) x[i] -= t * v[i];
}

// The Householder vector taking x (on [k, n)) onto the k-th axis. (Inlined into each compiled
// size so that its bounds are constants there too: GCC otherwise keeps one copy for all.)
template <int S>
[[gnu::always_inline]] inline void householder(const Vector<S>& x, int k, int n, Vector<S>& v) {
  for (int i = 0; i < k; ++i) v[i] = 0;
  for (int i = k; i < n; ++i) v[i] = x[i];
  const double norm = std::sqrt(dot<S>(v, v, k, n));
  v[k] = x[k] + (x[k] >= 0 ? norm : -norm);
  const double length = std::sqrt(dot<S>(v, v, k, n));
  for (int i = k; i < n; ++i) v[i] /= length;
}

// A <- H A H with H = I - 2 v v^T, on the trailing block [k, n) only: the later reflectors and
// Z^T A Z read nothing else.
template <int S>
void reflect_both_sides(Square<S>& a, const Vector<S>& v, int k, int n) {
  Vector<S> p;
  for (int i = k; i < n; ++i) {
    double sum = 0;
    for (int j = k; j < n; ++j) sum += a[i][j] * v[j];
    p[i] = sum;
  }
  const double vp = dot<S>(v, p, k, n);
  for (int i = k; i < n; ++i) p[i] -= vp * v[i];  // w = p - (v.p) v
  for (int i = k; i < n; ++i)
    for (int j = k; j < n; ++j) a[i][j] -= 2 * (v[i] * p[j] + p[i] * v[j]);
}

// E_aa, E_ab, E_bb from the n unit-size centres (scaled by 1 / scale) and the first `rank`
// columns of an orthonormal basis of range(B).
//
// M = Z (Z^T A Z)^-1 Z^T with Z an orthonormal basis of the null space of B^T (the block
// inverse of eq. 2's bordered matrix). The reflectors that complete range(B) to an orthonormal
// basis give Z as their last n - rank columns; -Z^T A Z is positive definite (the distance
// kernel is conditionally negative definite), so one small Cholesky gives the three entries:
// E = -8 pi M / scale, E_ab = (8 pi / scale) (L^-1 Z^T e_a) . (L^-1 Z^T e_b). Half the work of
// an LU of the whole (n + rank)-square bordered matrix.
template <int S>
EnergyBlock energy_entries(const Vec3* centres, const int n, int a, int b, double scale, const Basis& range, int rank) {
  constexpr const char* who = "collapse_energy_block";
  Square<S> kernel;
  for (int i = 0; i < n; ++i) {
    kernel[i][i] = 0;
    for (int j = 0; j < i; ++j) {
      const double r = (centres[i] - centres[j]).norm() / scale;  // phi(r) = r on the unit-size centres
      if (r == 0) throw InvalidInput(std::string(who) + ": two centres coincide");
      kernel[i][j] = kernel[j][i] = r;
    }
  }
  Vector<S> columns[4] = {}, za = {}, zb = {};  // (zeroed: the compiler cannot see that n > rank)
  for (int c = 0; c < rank; ++c)
    for (int i = 0; i < n; ++i) columns[c][i] = range(i, c);
  za[a] = 1;
  zb[b] = 1;
  for (int k = 0; k < rank; ++k) {
    Vector<S> v;
    householder<S>(columns[k], k, n, v);
    for (int c = k + 1; c < rank; ++c) reflect<S>(columns[c], v, k, n);
    reflect_both_sides<S>(kernel, v, k, n);
    reflect<S>(za, v, k, n);
    reflect<S>(zb, v, k, n);
  }
  // Cholesky L L^T = -Z^T A Z (the trailing block), then u = L^-1 Z^T e_a, w = L^-1 Z^T e_b.
  Square<S> l;
  for (int j = rank; j < n; ++j) {
    double d = -kernel[j][j];
    for (int k = rank; k < j; ++k) d -= l[j][k] * l[j][k];
    if (!(d > 0)) throw SolverError(std::string(who) + ": the bordered system is singular");
    l[j][j] = std::sqrt(d);
    for (int i = j + 1; i < n; ++i) {
      double sum = -kernel[i][j];
      for (int k = rank; k < j; ++k) sum -= l[i][k] * l[j][k];
      l[i][j] = sum / l[j][j];
    }
  }
  for (int i = rank; i < n; ++i) {
    for (int k = rank; k < i; ++k) {
      za[i] -= l[i][k] * za[k];
      zb[i] -= l[i][k] * zb[k];
    }
    za[i] /= l[i][i];
    zb[i] /= l[i][i];
  }
  const double factor = kEightPi / scale;
  return {factor * dot<S>(za, za, rank, n), factor * dot<S>(za, zb, rank, n), factor * dot<S>(zb, zb, rank, n)};
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

  switch (n) {  // the union of two 1-rings: 9-11 centres for most edges of a mesh
    case 8: return energy_entries<8>(centres, 8, a, b, scale, basis, rank);
    case 9: return energy_entries<9>(centres, 9, a, b, scale, basis, rank);
    case 10: return energy_entries<10>(centres, 10, a, b, scale, basis, rank);
    case 11: return energy_entries<11>(centres, 11, a, b, scale, basis, rank);
    case 12: return energy_entries<12>(centres, 12, a, b, scale, basis, rank);
    case 13: return energy_entries<13>(centres, 13, a, b, scale, basis, rank);
    default: return energy_entries<kMax>(centres, n, a, b, scale, basis, rank);
  }
}

}  // namespace meshprep::detail
