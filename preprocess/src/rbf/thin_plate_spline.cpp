#include "meshprep/preprocess/rbf/thin_plate_spline.h"

#include "rbf/bordered_solve.h"

#include "meshprep/core/errors.h"

#include <Eigen/Cholesky>
#include <Eigen/QR>

#include <cmath>
#include <string>
#include <utility>

namespace meshprep {
namespace {

using Eigen::Index;
using Eigen::MatrixXd;
using Eigen::VectorXd;

constexpr double kEightPi = 8.0 * M_PI;
// Pivot of the rank-revealing QR of B, relative to the largest, below which B is rank deficient:
// unit-size centres within ~1e-10 (rms) of a plane (3D) or a line (2D) are coplanar (collinear).
constexpr double kRankThreshold = 1e-10;

// The kernels as functions of the squared distance s = r^2: phi = r in 3D; phi = r^2 log r =
// (s / 2) log s in 2D (0 at s = 0). glibc's scalar log beats Eigen's SSE2 one here (7 against
// 11 ns), so these stay scalar.
double volume_kernel(double squared) { return std::sqrt(squared); }
double thin_plate_kernel(double squared) { return squared > 0 ? 0.5 * squared * std::log(squared) : 0.0; }
// Duchon's phi = r^(5/2) = t sqrt(sqrt(t)), t = r^2 (a lambda, so that kernel_matrix inlines it).
constexpr auto duchon_kernel = [](double squared) { return squared * std::sqrt(std::sqrt(squared)); };

// Centres as columns, translated to their centroid and divided by their largest distance from it.
template <int D>
struct UnitCentres {
  Eigen::Matrix<double, D, 1> centre;
  double scale = 1;
  Eigen::Matrix<double, D, Eigen::Dynamic> points;
};

template <int D>
UnitCentres<D> unit_centres(const std::vector<Eigen::Matrix<double, D, 1>>& points, const char* who) {
  UnitCentres<D> unit;
  unit.points.resize(D, static_cast<Index>(points.size()));
  for (std::size_t i = 0; i < points.size(); ++i) unit.points.col(static_cast<Index>(i)) = points[i];
  if (!unit.points.allFinite()) throw InvalidInput(std::string(who) + ": a coordinate is not finite");
  unit.centre = unit.points.rowwise().mean();
  unit.points.colwise() -= unit.centre;
  unit.scale = unit.points.colwise().norm().maxCoeff();
  if (!(unit.scale > 0)) throw InvalidInput(std::string(who) + ": all points coincide");
  unit.points /= unit.scale;
  return unit;
}

// A_ij = phi(|q_i - q_j|), phi taking the squared distance.
template <int D, class Kernel>
MatrixXd kernel_matrix(const Eigen::Matrix<double, D, Eigen::Dynamic>& q, Kernel phi, const char* who) {
  const Index n = q.cols();
  MatrixXd a(n, n);
  for (Index i = 0; i < n; ++i) {
    a(i, i) = phi(0.0);
    for (Index j = 0; j < i; ++j) {
      const double squared = (q.col(i) - q.col(j)).squaredNorm();
      if (squared == 0) throw InvalidInput(std::string(who) + ": two points coincide");
      a(i, j) = a(j, i) = phi(squared);
    }
  }
  return a;
}

// B_i = (1, q_i^T): the linear polynomial of eq. (1).
MatrixXd volume_polynomial_matrix(const Eigen::Matrix3Xd& q) {
  MatrixXd b(q.cols(), 4);
  b.col(0).setOnes();
  b.rightCols(3) = q.transpose();
  return b;
}

// 1, x, y, x^2, xy, y^2, x^3, x^2 y, x y^2, y^3: the first 3 (linear), 6 (quadratic) or all 10
// (cubic) span a height map's polynomial.
Eigen::Matrix<double, 10, 1> monomials(const Eigen::Vector2d& q) {
  const double x = q.x(), y = q.y();
  Eigen::Matrix<double, 10, 1> m;
  m << 1.0, x, y, x * x, x * y, y * y, x * x * x, x * x * y, x * y * y, y * y * y;
  return m;
}

// The polynomial with these coefficients (3, 6 or 10 of them, in the order of monomials) at q.
double polynomial_at(const Eigen::Vector2d& q, const VectorXd& coefficients) {
  const double x = q.x(), y = q.y();
  double value = coefficients[0] + coefficients[1] * x + coefficients[2] * y;
  if (coefficients.size() > 3)
    value += coefficients[3] * x * x + coefficients[4] * x * y + coefficients[5] * y * y;
  if (coefficients.size() > 6)
    value += x * (x * (coefficients[6] * x + coefficients[7] * y) + coefficients[8] * y * y) + coefficients[9] * y * y * y;
  return value;
}

Index term_count(HeightMapPolynomial polynomial) {
  switch (polynomial) {
    case HeightMapPolynomial::linear: return 3;
    case HeightMapPolynomial::quadratic: return 6;
    case HeightMapPolynomial::cubic: return 10;
  }
  return 3;
}

MatrixXd height_map_polynomial_matrix(const Eigen::Matrix2Xd& q, Index terms) {
  MatrixXd b(q.cols(), terms);
  for (Index i = 0; i < q.cols(); ++i) b.row(i) = monomials(q.col(i)).head(terms).transpose();
  return b;
}

// The doubly bordered system of eq. (2), [A B; B^T 0][gamma; v] = [h; 0], solved by the
// null-space method (see thin_plate_spline.h). `sign` is +1 when Z^T A Z is positive definite
// (thin plate), -1 when it is negative definite (volume spline); the Cholesky factor is of
// sign * Z^T A Z.
class BorderedSystem {
 public:
  BorderedSystem(MatrixXd kernel, const MatrixXd& polynomial, double sign, Index min_rank, const char* degenerate,
                 const char* who)
      : kernel_(std::move(kernel)), sign_(sign) {
    polynomial_.setThreshold(kRankThreshold);
    polynomial_.compute(polynomial);
    if (polynomial_.rank() < min_rank) throw InvalidInput(std::string(who) + ": the points are " + degenerate);
    // B = Q [R; 0] P^T, so the last n - rank columns of Q span null(B^T): Z^T A Z is the lower
    // right block of Q^T A Q, got by applying Q's few reflectors on both sides (no dense Q, no
    // matrix products).
    MatrixXd rotated = kernel_;
    rotated.applyOnTheLeft(polynomial_.householderQ().adjoint());
    rotated.applyOnTheRight(polynomial_.householderQ());
    const Index free = kernel_.rows() - polynomial_.rank();
    reduced_.compute(sign_ * rotated.bottomRightCorner(free, free));
    if (reduced_.info() != Eigen::Success) throw SolverError(std::string(who) + ": kernel matrix not definite");
  }

  struct Solution {
    VectorXd gamma;
    VectorXd polynomial;  // v, the coefficients of the polynomial part
    double energy = 0;  // sign * gamma^T A gamma
  };

  Solution solve(const VectorXd& h) const {
    Solution s;
    const Index free = kernel_.rows() - polynomial_.rank();
    const VectorXd g = (polynomial_.householderQ().adjoint() * h).tail(free);  // Z^T h
    VectorXd padded = VectorXd::Zero(kernel_.rows());
    padded.tail(free) = reduced_.solve(sign_ * g);
    s.gamma = polynomial_.householderQ() * padded;  // Z delta
    s.polynomial = polynomial_.solve(h - kernel_ * s.gamma);
    // gamma^T A gamma = g^T (Z^T A Z)^-1 g, so sign * gamma^T A gamma = |L^-1 g|^2 >= 0.
    s.energy = reduced_.matrixL().solve(g).squaredNorm();
    return s;
  }

  // sign * M, M = Z (Z^T A Z)^-1 Z^T the upper-left block of the bordered inverse.
  MatrixXd energy_matrix() const {
    const MatrixXd q = polynomial_.householderQ();
    const MatrixXd z = q.rightCols(q.cols() - polynomial_.rank());
    return z * reduced_.solve(z.transpose());
  }

 private:
  MatrixXd kernel_;
  double sign_;
  Eigen::CompleteOrthogonalDecomposition<MatrixXd> polynomial_;
  Eigen::LLT<MatrixXd> reduced_;
};

void check_values(const VectorXd& values, std::size_t points, const char* who) {
  if (static_cast<std::size_t>(values.size()) != points)
    throw InvalidInput(std::string(who) + ": " + std::to_string(values.size()) + " values for " +
                       std::to_string(points) + " points");
  if (!values.allFinite()) throw InvalidInput(std::string(who) + ": a value is not finite");
}

void check_count(std::size_t points, std::size_t minimum, const char* who) {
  if (points < minimum)
    throw InvalidInput(std::string(who) + ": " + std::to_string(points) + " points, at least " +
                       std::to_string(minimum) + " needed");
}

// A height map's sites at unit size, after checking its data.
UnitCentres<2> height_map_sites(const std::vector<Eigen::Vector2d>& sites, const VectorXd& heights,
                                HeightMapPolynomial polynomial, const char* who) {
  check_count(sites.size(), static_cast<std::size_t>(term_count(polynomial)), who);
  check_values(heights, sites.size(), who);
  return unit_centres(sites, who);
}

const char* height_map_degeneracy(HeightMapPolynomial polynomial) {
  switch (polynomial) {
    case HeightMapPolynomial::linear: return "collinear";
    case HeightMapPolynomial::quadratic: return "on one conic";
    case HeightMapPolynomial::cubic: return "on one cubic curve";
  }
  return "degenerate";
}

// The polynomial (`terms` monomials) minimising sum_j w_j (p(q_j) - h_j)^2 over unit-size sites,
// by its normal equations: a terms x terms system in fixed-size storage, built in one pass over
// the sites (the smoothing fits one per vertex, and a QR of the n x terms matrix costs 4x as
// much). On unit-size sites the monomials are O(1), so squaring the condition number costs
// nothing that matters; sites (nearly) on one curve of the polynomial's degree leave a pivot under
// 1e-12 of the largest: no coefficients (size 0).
VectorXd least_squares_polynomial(const Eigen::Matrix2Xd& q, const VectorXd& h, const VectorXd& weights, Index terms) {
  using Normal = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, 0, 10, 10>;
  Eigen::Matrix<double, 10, 10> all = Eigen::Matrix<double, 10, 10>::Zero();  // of every monomial: fixed size, vectorised
  Eigen::Matrix<double, 10, 1> right = Eigen::Matrix<double, 10, 1>::Zero();
  for (Index j = 0; j < q.cols(); ++j) {
    const Eigen::Matrix<double, 10, 1> m = monomials(q.col(j));
    const Eigen::Matrix<double, 10, 1> weighted = (weights.size() > 0 ? weights[j] : 1.0) * m;
    all.noalias() += weighted * m.transpose();
    right += h[j] * weighted;
  }
  const Normal normal = all.topLeftCorner(terms, terms);
  const Eigen::LDLT<Normal, Eigen::Lower> ldlt(normal);
  const auto pivots = ldlt.vectorD().cwiseAbs();
  if (ldlt.info() != Eigen::Success || !(pivots.minCoeff() > 1e-12 * pivots.maxCoeff())) return VectorXd();
  return ldlt.solve(right.head(terms));
}

// Site weights: none (all 1) or one finite positive weight per site.
void check_weights(const VectorXd& weights, std::size_t sites, const char* who) {
  if (weights.size() == 0) return;
  if (static_cast<std::size_t>(weights.size()) != sites)
    throw InvalidInput(std::string(who) + ": " + std::to_string(weights.size()) + " weights for " +
                       std::to_string(sites) + " sites");
  if (!weights.allFinite() || !(weights.minCoeff() > 0))
    throw InvalidInput(std::string(who) + ": the weights must be finite and positive");
}

// The volume spline's system on unit-size centres; coplanar centres (rank 3) are accepted.
BorderedSystem volume_system(const UnitCentres<3>& unit, const char* who) {
  return BorderedSystem(kernel_matrix(unit.points, volume_kernel, who), volume_polynomial_matrix(unit.points), -1.0, 3,
                        "collinear", who);
}

}  // namespace

VolumeSpline::VolumeSpline(const std::vector<Vec3>& centres, const Eigen::VectorXd& values) {
  constexpr const char* who = "VolumeSpline";
  check_count(centres.size(), 4, who);
  check_values(values, centres.size(), who);
  UnitCentres<3> unit = unit_centres(centres, who);
  const BorderedSystem::Solution s = volume_system(unit, who).solve(values);
  centre_ = unit.centre;
  scale_ = unit.scale;
  scaled_centres_ = std::move(unit.points);
  gamma_ = s.gamma;
  affine_ = s.polynomial;
  // J scales as 1/length in R^3 (D^2 f ~ 1/length^2, volume ~ length^3).
  bending_energy_ = kEightPi * s.energy / scale_;
}

double VolumeSpline::evaluate(const Vec3& p) const {
  const Vec3 q = (p - centre_) / scale_;
  const double kernel_part = gamma_.dot((scaled_centres_.colwise() - q).colwise().norm().transpose());
  return kernel_part + affine_[0] + affine_.tail<3>().dot(q);
}

Eigen::MatrixXd volume_spline_energy_matrix(const std::vector<Vec3>& centres) {
  constexpr const char* who = "volume_spline_energy_matrix";
  check_count(centres.size(), 4, who);
  const UnitCentres<3> unit = unit_centres(centres, who);
  return (kEightPi / unit.scale) * volume_system(unit, who).energy_matrix();
}

HeightMapSpline::HeightMapSpline(const std::vector<Eigen::Vector2d>& sites, const Eigen::VectorXd& heights,
                                 HeightMapPolynomial polynomial, double smoothing, const Eigen::VectorXd& weights) {
  constexpr const char* who = "HeightMapSpline";
  if (!(smoothing >= 0)) throw InvalidInput(std::string(who) + ": smoothing must be >= 0");
  check_weights(weights, sites.size(), who);
  UnitCentres<2> unit = height_map_sites(sites, heights, polynomial, who);
  centre_ = unit.centre;
  scale_ = unit.scale;
  if (std::isinf(smoothing)) {  // the limit: the (weighted) least-squares polynomial, no kernel part
    polynomial_ = least_squares_polynomial(unit.points, heights, weights, term_count(polynomial));
    if (polynomial_.size() == 0) throw InvalidInput(std::string(who) + ": the points are " + height_map_degeneracy(polynomial));
    scaled_sites_.resize(2, 0);
    return;
  }
  MatrixXd kernel = kernel_matrix(unit.points, thin_plate_kernel, who);
  // sum_j w_j (z(S_j) - z_j)^2 + lambda/(8 pi) J(z): the site's own smoothing is lambda / w_j.
  if (weights.size() > 0)
    kernel.diagonal().array() += smoothing / weights.array();
  else
    kernel.diagonal().array() += smoothing;
  const Index terms = term_count(polynomial);
  const BorderedSystem system(std::move(kernel), height_map_polynomial_matrix(unit.points, terms), 1.0, terms,
                              height_map_degeneracy(polynomial), who);
  const BorderedSystem::Solution s = system.solve(heights);
  scaled_sites_ = std::move(unit.points);
  gamma_ = s.gamma;
  polynomial_ = s.polynomial;
  // Heights are not rescaled, so J scales as 1/length^2 in R^2.
  bending_energy_ = kEightPi * s.energy / (scale_ * scale_);
}

double HeightMapSpline::evaluate(double x, double y) const {
  const Eigen::Vector2d q = (Eigen::Vector2d(x, y) - centre_) / scale_;
  double kernel_part = 0;
  for (Index j = 0; j < scaled_sites_.cols(); ++j)
    kernel_part += gamma_[j] * thin_plate_kernel((scaled_sites_.col(j) - q).squaredNorm());
  return kernel_part + polynomial_at(q, polynomial_);
}

DuchonSpline::DuchonSpline(const std::vector<Eigen::Vector2d>& sites, const Eigen::VectorXd& heights,
                           HeightMapPolynomial polynomial) {
  constexpr const char* who = "DuchonSpline";
  const UnitCentres<2> unit = height_map_sites(sites, heights, polynomial, who);
  const detail::BorderedSolution s =
      detail::solve_bordered(kernel_matrix(unit.points, duchon_kernel, who),
                             height_map_polynomial_matrix(unit.points, term_count(polynomial)), heights, kRankThreshold,
                             height_map_degeneracy(polynomial), who);
  centre_ = unit.centre;
  scale_ = unit.scale;
  site_x_ = unit.points.row(0).transpose().array();
  site_y_ = unit.points.row(1).transpose().array();
  gamma_ = s.gamma.array();
  polynomial_ = s.polynomial;
}

// The kernel part is vectorised over the sites (Eigen packets); the squared distances are an
// expression, evaluated packet by packet, so nothing is allocated.
double DuchonSpline::evaluate(double x, double y) const {
  const Eigen::Vector2d q = (Eigen::Vector2d(x, y) - centre_) / scale_;
  const auto squared = (site_x_ - q.x()).square() + (site_y_ - q.y()).square();
  return (gamma_ * squared * squared.sqrt().sqrt()).sum() + polynomial_at(q, polynomial_);
}

}  // namespace meshprep
