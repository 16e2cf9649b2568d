#pragma once
/// \file thin_plate_spline.h
/// The radial-basis-function interpolants of Section 4 of the paper: the volume spline of eqs. (1)
/// and (2) in R^3 and the thin-plate spline of a height map z(x, y) behind the inverse mapping of
/// eq. (3). Both minimise the bending energy J(f) = integral over R^d of sum_ij (d_i d_j f)^2 among
/// all interpolants of the data (Duchon 1977), so the kernel phi is the fundamental solution of the
/// biharmonic operator in R^d, augmented by a linear polynomial (the height map may take a
/// quadratic one):
/// - d = 3: phi(r) = r (lap^2 r = -8 pi delta): the "volume spline";
/// - d = 2: phi(r) = r^2 log r (lap^2 (r^2 log r) = 8 pi delta): the thin-plate spline.
///
/// Solving eq. (2): the doubly bordered system [A B; B^T 0] [gamma; v] = [h; 0], with
/// A_ij = phi(|P_i - P_j|) and B_i = (1, P_i^T), is symmetric but indefinite, so Eigen's LDLT/LLT
/// (semi-definite matrices only) cannot factor it. It is solved by the null-space method: a rank-revealing QR of B gives
/// an orthonormal basis Z of null(B^T); gamma = Z delta satisfies B^T gamma = 0 exactly and
/// (Z^T A Z) delta = Z^T h, where Z^T A Z is definite (phi is conditionally definite: -r of order
/// 1, r^2 log r of order 2), so it has a Cholesky factorisation (of -Z^T A Z in 3D); then
/// v = B^+ (h - A gamma). Before A is built the centres are translated to their centroid and
/// divided by their largest distance from it (unit size): the interpolant is unchanged (both
/// kernel spaces are invariant under translation and scaling, given the moment conditions
/// B^T gamma = 0) but the condition number no longer depends on the units. Energies are converted
/// back, so every figure below is in the caller's units.
///
/// Bending energy: with gamma the kernel weights, J = 8 pi gamma^T A gamma in 2D and
/// J = -8 pi gamma^T A gamma in 3D (the sign of the fundamental solution), i.e. J = h^T E h with
/// the bending-energy matrix E = +-8 pi M, M the upper-left N x N block of the inverse of the
/// bordered matrix (Bookstein's L_N^-1; M = Z (Z^T A Z)^-1 Z^T). This is the paper's h'A^-1 h made
/// precise: the polynomial part carries no energy, so J is 0 for data that the polynomial fits
/// (affine data, with the linear polynomial) and > 0 otherwise.

#include "meshprep/core/mesh.h"

#include <Eigen/Core>

#include <vector>

namespace meshprep {

/// The volume spline of eq. (1): f(P) = sum_j gamma_j |P - P_j| + v0 + v1 x + v2 y + v3 z,
/// interpolating values h_i at centres P_i (eq. 2).
/// Coplanar centres (rms distance to a plane below ~1e-10 of their size) are accepted, a flat
/// patch of a mesh being the common case: the interpolant and its energy are still unique on the
/// plane; the affine part is the minimum-norm one, which has no gradient along the plane's normal.
class VolumeSpline {
 public:
  /// \throws InvalidInput if there are fewer than 4 centres, values.size() differs, a coordinate or
  ///         value is not finite, two centres coincide or all centres are collinear.
  VolumeSpline(const std::vector<Vec3>& centres, const Eigen::VectorXd& values);

  /// f(P), eq. (1).
  double evaluate(const Vec3& p) const;
  /// J(f) = -8 pi gamma^T A gamma >= 0 (in the caller's units: J scales as 1/length in 3D).
  double bending_energy() const { return bending_energy_; }

 private:
  Vec3 centre_;
  double scale_ = 1;
  Eigen::Matrix3Xd scaled_centres_;
  Eigen::VectorXd gamma_;
  Eigen::Vector4d affine_;  // v0..v3 in the scaled coordinates
  double bending_energy_ = 0;
};

/// The bending-energy matrix E = -8 pi M of the volume spline on these centres (symmetric,
/// positive semi-definite, N x N): the spline interpolating h has energy h^T E h. E annihilates
/// the affine functions of the centres (E 1 = 0, E x = E y = E z = 0).
/// \throws InvalidInput as VolumeSpline.
Eigen::MatrixXd volume_spline_energy_matrix(const std::vector<Vec3>& centres);

/// The polynomial part of a HeightMapSpline.
enum class HeightMapPolynomial {
  /// v0 + v1 x + v2 y, as in eqs. (1) and (3): reproduces planes; O(h^2) error on a curved surface
  /// sampled at spacing h. Needs 3 sites, not collinear: robust on a 1-ring.
  linear,
  /// adds v3 x^2 + v4 x y + v5 y^2 (r^2 log r stays conditionally definite): reproduces quadrics,
  /// O(h^3) error. Needs 6 sites, not on one conic: use it with two rings or more (the sites of a
  /// single regular 1-ring lie close to a circle, where the quadratic part is ill-determined).
  quadratic,
  /// adds the four cubic monomials: reproduces cubic height maps. Needs 10 sites, not on one cubic
  /// curve (three rings or more). Its odd terms let a one-sided neighbourhood (beside a crease)
  /// follow the surface's change of curvature.
  cubic,
};

/// The thin-plate spline of a height map: z(x, y) = sum_j gamma_j phi(|(x, y) - S_j|) + p(x, y)
/// with phi(r) = r^2 log r and p a linear or quadratic polynomial, interpolating heights z_j at
/// sites S_j. It reproduces any plane z = a + b x + c y exactly, with zero energy (and any
/// quadratic height map with HeightMapPolynomial::quadratic).
class HeightMapSpline {
 public:
  /// `smoothing` lambda >= 0 makes it the thin-plate smoothing spline (Wahba): instead of
  /// interpolating it minimises sum_j w_j (z(S_j) - z_j)^2 + lambda/(8 pi) J(z) in the unit-scaled
  /// coordinates, i.e. solves (A + lambda W^-1) gamma + B v = h; lambda -> infinity tends to the
  /// weighted least-squares polynomial, which lambda = infinity gives directly (no kernel part,
  /// energy 0). `weights` w_j > 0, one per site, default all 1. Planes (quadrics, cubics, with
  /// the quadratic or cubic polynomial) are still reproduced exactly, whatever lambda and the
  /// weights. bending_energy() then includes lambda |gamma|^2 (weighted).
  /// \throws InvalidInput if there are fewer sites than polynomial terms, heights.size() or
  ///         weights.size() differs, a value or weight is not finite, a weight is not positive, two
  ///         sites coincide (finite lambda), or the sites are collinear (linear), on one conic
  ///         (quadratic) or on one cubic curve (cubic).
  HeightMapSpline(const std::vector<Eigen::Vector2d>& sites, const Eigen::VectorXd& heights,
                  HeightMapPolynomial polynomial = HeightMapPolynomial::linear, double smoothing = 0,
                  const Eigen::VectorXd& weights = Eigen::VectorXd());

  double evaluate(double x, double y) const;
  /// 8 pi gamma^T A gamma >= 0. With the linear polynomial this is the thin-plate energy
  /// J(z) = integral of z_xx^2 + 2 z_xy^2 + z_yy^2 over R^2; with the quadratic one it is that of
  /// the kernel part, the bending a quadric does not explain. Dimensionless (invariant when x, y
  /// and z are scaled together).
  double bending_energy() const { return bending_energy_; }

 private:
  Eigen::Vector2d centre_;
  double scale_ = 1;
  Eigen::Matrix2Xd scaled_sites_;
  Eigen::VectorXd gamma_;
  Eigen::VectorXd polynomial_;  // coefficients of 1, x, y[, x^2, xy, y^2[, x^3, x^2 y, x y^2, y^3]], scaled coordinates
  double bending_energy_ = 0;
};

/// Duchon's spline of a height map (Duchon 1977, order m = 2, s = 1/4): z(x, y) =
/// sum_j gamma_j phi(|(x, y) - S_j|) + p(x, y) with phi(r) = r^(5/2) and p a linear or quadratic
/// polynomial, interpolating heights z_j at sites S_j. Among all interpolants it minimises
/// integral |xi|^(1/2) |F(D^2 z)(xi)|^2 dxi, the thin plate's J (s = 0, phi = r^2 log r) with the
/// high frequencies weighted up a little: a slightly smoother surface, between the thin plate and
/// phi = r^3 (s = 1/2). Like r^2 log r, r^(5/2) is conditionally positive definite of order 2, so
/// the system is eq. (2)'s, solved as HeightMapSpline's, and planes (quadrics, with the quadratic
/// polynomial) are reproduced exactly. It needs no logarithm: phi = t sqrt(sqrt(t)) with t = r^2,
/// two SIMD square roots. The partition of unity's local approximant: on the Jacksboro DEM it
/// predicts held-out points better than the thin plate (docs/reconstruction.md).
class DuchonSpline {
 public:
  /// \throws InvalidInput as HeightMapSpline (without smoothing).
  DuchonSpline(const std::vector<Eigen::Vector2d>& sites, const Eigen::VectorXd& heights,
               HeightMapPolynomial polynomial = HeightMapPolynomial::linear);

  double evaluate(double x, double y) const;

 private:

  Eigen::Vector2d centre_;
  double scale_ = 1;
  Eigen::ArrayXd site_x_, site_y_, gamma_;  // the sites in the scaled coordinates, one array per axis
  Eigen::VectorXd polynomial_;              // coefficients of 1, x, y[, x^2, xy, y^2], scaled coordinates
};

}  // namespace meshprep
