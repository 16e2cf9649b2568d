#include "meshprep/core/errors.h"
#include "meshprep/preprocess/rbf/local_frame.h"
#include "meshprep/preprocess/rbf/local_height_map.h"
#include "meshprep/preprocess/rbf/sliding_landmarks.h"
#include "meshprep/preprocess/rbf/thin_plate_spline.h"

#include <Eigen/Eigenvalues>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>
#include <vector>

using namespace meshprep;

namespace {

constexpr double kTight = 1e-12;  // exact in exact arithmetic: round-off only

const Eigen::Matrix3d& tilt() {
  static const Eigen::Matrix3d rotation = Eigen::AngleAxisd(0.7, Vec3(1, 2, 3).normalized()).toRotationMatrix();
  return rotation;
}

// An irregular set of (x, y) sites in [-1, 1]^2 (deterministic).
std::vector<Eigen::Vector2d> scattered_sites(int count) {
  std::vector<Eigen::Vector2d> sites;
  for (int i = 0; i < count; ++i) sites.emplace_back(std::sin(1.7 * i + 0.3), std::cos(2.3 * i * i + 0.1));
  return sites;
}

// Irregular points of the plane through (1, -2, 3) with normal tilt() * e_z.
std::vector<Vec3> tilted_plane_points(int count) {
  std::vector<Vec3> points;
  for (const Eigen::Vector2d& s : scattered_sites(count))
    points.push_back(Vec3(1, -2, 3) + tilt() * Vec3(s.x(), s.y(), 0));
  return points;
}

// Irregular points filling a box, not coplanar.
std::vector<Vec3> scattered_centres(int count) {
  std::vector<Vec3> points;
  for (int i = 0; i < count; ++i)
    points.emplace_back(std::sin(1.3 * i), std::cos(1.9 * i + 0.5), std::sin(0.7 * i * i + 1.0));
  return points;
}

Eigen::VectorXd values_of(const std::vector<Vec3>& points, double (*f)(const Vec3&)) {
  Eigen::VectorXd values(static_cast<Eigen::Index>(points.size()));
  for (std::size_t i = 0; i < points.size(); ++i) values[static_cast<Eigen::Index>(i)] = f(points[i]);
  return values;
}

double affine(const Vec3& p) { return 0.5 - 2.0 * p.x() + 3.0 * p.y() + 0.25 * p.z(); }
double bump(const Vec3& p) { return std::exp(-p.squaredNorm()); }

// The union of the 1-rings of edge (0, 1) on a regular triangular grid of spacing 1: the end
// points (0, 0) and (1, 0), then their 8 neighbours. Symmetric under x -> 1 - x.
std::vector<Vec3> edge_patch() {
  const double r3 = std::sqrt(3.0) / 2;
  return {{0, 0, 0},   {1, 0, 0},   {-1, 0, 0},  {2, 0, 0},   {-0.5, r3, 0},
          {0.5, r3, 0}, {1.5, r3, 0}, {-0.5, -r3, 0}, {0.5, -r3, 0}, {1.5, -r3, 0}};
}

// Sum over x, y, z of the energies of the volume splines interpolating the displacement
// target - source: the bending energy of the deformation, computed from the fitted weights.
double deformation_energy(const std::vector<Vec3>& source, const std::vector<Vec3>& target) {
  double energy = 0;
  for (int c = 0; c < 3; ++c) {
    Eigen::VectorXd h(static_cast<Eigen::Index>(source.size()));
    for (std::size_t i = 0; i < source.size(); ++i) h[static_cast<Eigen::Index>(i)] = target[i][c] - source[i][c];
    energy += VolumeSpline(source, h).bending_energy();
  }
  return energy;
}

// The 20 nearest points of a slightly irregular grid of spacing h around the north pole, lifted
// onto the unit sphere and rotated; the query is off the sphere above the pole.
std::pair<std::vector<Vec3>, Vec3> sphere_neighbourhood(double h) {
  std::vector<Eigen::Vector2d> grid;
  for (int i = -4; i <= 4; ++i)
    for (int j = -4; j <= 4; ++j)
      if (i != 0 || j != 0)
        grid.emplace_back(h * (i + 0.13 * std::sin(7.0 * i + 3.0 * j)), h * (j + 0.11 * std::cos(5.0 * i - 2.0 * j)));
  std::sort(grid.begin(), grid.end(), [](const auto& a, const auto& b) { return a.squaredNorm() < b.squaredNorm(); });
  std::vector<Vec3> neighbours;
  for (int k = 0; k < 20; ++k) {
    const Eigen::Vector2d& q = grid[static_cast<std::size_t>(k)];
    neighbours.push_back(tilt() * Vec3(q.x(), q.y(), std::sqrt(1.0 - q.squaredNorm())));
  }
  return {neighbours, tilt() * Vec3(0.1 * h, -0.2 * h, 1.0 + 0.3 * h)};
}

}  // namespace

// --- LocalFrame -------------------------------------------------------------------------------

TEST(LocalFrame, TiltedPlaneHasZeroVariationAndItsNormal) {
  const LocalFrame frame = pca_frame(tilted_plane_points(30));
  EXPECT_LE(frame.surface_variation(), 1e-15);
  EXPECT_NEAR(std::abs(frame.normal().dot(tilt().col(2))), 1.0, kTight);
  EXPECT_LE(frame.eigenvalues[0], frame.eigenvalues[1]);
  EXPECT_LE(frame.eigenvalues[1], frame.eigenvalues[2]);
  EXPECT_LE((frame.axes.transpose() * frame.axes - Eigen::Matrix3d::Identity()).norm(), kTight);
  EXPECT_NEAR(frame.axes.determinant(), 1.0, kTight);
  const Vec3 p(0.3, -0.7, 2.0);
  EXPECT_LE((frame.to_world(frame.to_local(p)) - p).norm(), kTight);
}

TEST(LocalFrame, IsotropicCloudHasVariationOneThird) {
  // The octahedron's vertices: covariance (1/3) I exactly.
  const std::vector<Vec3> octahedron{{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
  EXPECT_NEAR(pca_frame(octahedron).surface_variation(), 1.0 / 3.0, kTight);
  // A Fibonacci sphere: nearly isotropic.
  std::vector<Vec3> sphere;
  const int n = 2000;
  for (int i = 0; i < n; ++i) {
    const double z = 1.0 - (2.0 * i + 1.0) / n, r = std::sqrt(1.0 - z * z), phi = i * M_PI * (3.0 - std::sqrt(5.0));
    sphere.emplace_back(r * std::cos(phi), r * std::sin(phi), z);
  }
  EXPECT_NEAR(pca_frame(sphere).surface_variation(), 1.0 / 3.0, 1e-3);
}

TEST(LocalFrame, NormalFollowsTheOrientation) {
  const std::vector<Vec3> points = tilted_plane_points(12);
  for (const double sign : {1.0, -1.0}) {
    const LocalFrame frame = pca_frame(points, sign * tilt().col(2));
    EXPECT_NEAR(frame.normal().dot(tilt().col(2)), sign, kTight);
    EXPECT_NEAR(frame.axes.determinant(), 1.0, kTight);
  }
  EXPECT_THROW(pca_frame(std::vector<Vec3>{}), InvalidInput);
}

// --- HeightMapSpline ------------------------------------------------------------------------

TEST(HeightMapSpline, ReproducesAPlaneWithZeroEnergy) {
  const std::vector<Eigen::Vector2d> sites = scattered_sites(15);
  Eigen::VectorXd plane(15), bump_heights(15);
  for (Eigen::Index i = 0; i < 15; ++i) {
    const Eigen::Vector2d& s = sites[static_cast<std::size_t>(i)];
    plane[i] = 1.5 + 0.3 * s.x() - 0.8 * s.y();
    bump_heights[i] = std::exp(-s.squaredNorm());
  }
  const HeightMapSpline flat(sites, plane), bumped(sites, bump_heights);
  for (const auto& [x, y] : std::vector<std::pair<double, double>>{{0.1, 0.2}, {-0.9, 0.4}, {2.0, -3.0}})
    EXPECT_NEAR(flat.evaluate(x, y), 1.5 + 0.3 * x - 0.8 * y, kTight);
  EXPECT_GT(bumped.bending_energy(), 0.1);
  EXPECT_LE(flat.bending_energy(), 1e-10 * bumped.bending_energy());
  for (Eigen::Index i = 0; i < 15; ++i) {
    const Eigen::Vector2d& s = sites[static_cast<std::size_t>(i)];
    EXPECT_NEAR(bumped.evaluate(s.x(), s.y()), bump_heights[i], 1e-10);
  }
}

TEST(HeightMapSpline, QuadraticPolynomialReproducesAQuadric) {
  const std::vector<Eigen::Vector2d> sites = scattered_sites(12);
  auto quadric = [](double x, double y) { return 0.2 - x + 0.5 * y + 0.7 * x * x - 0.3 * x * y + 1.1 * y * y; };
  Eigen::VectorXd heights(12);
  for (Eigen::Index i = 0; i < 12; ++i)
    heights[i] = quadric(sites[static_cast<std::size_t>(i)].x(), sites[static_cast<std::size_t>(i)].y());
  const HeightMapSpline spline(sites, heights, HeightMapPolynomial::quadratic);
  EXPECT_NEAR(spline.evaluate(0.3, -0.4), quadric(0.3, -0.4), 1e-11);
  EXPECT_LE(spline.bending_energy(), 1e-18);
  // The linear spline bends to follow it.
  EXPECT_GT(HeightMapSpline(sites, heights).bending_energy(), 1.0);
}

TEST(HeightMapSpline, SmoothingSplineKeepsQuadricsAndStopsInterpolatingNoise) {
  const std::vector<Eigen::Vector2d> sites = scattered_sites(30);
  auto quadric = [](double x, double y) { return 0.2 - x + 0.5 * y + 0.7 * x * x - 0.3 * x * y + 1.1 * y * y; };
  Eigen::VectorXd heights(30), noisy(30);
  for (Eigen::Index i = 0; i < 30; ++i) {
    heights[i] = quadric(sites[static_cast<std::size_t>(i)].x(), sites[static_cast<std::size_t>(i)].y());
    noisy[i] = heights[i] + 0.01 * (i % 2 == 0 ? 1 : -1);
  }
  for (const double lambda : {0.1, 1.0, std::numeric_limits<double>::infinity()}) {
    // Any lambda: the quadric is in the polynomial part, which the penalty does not touch.
    const HeightMapSpline exact(sites, heights, HeightMapPolynomial::quadratic, lambda);
    EXPECT_NEAR(exact.evaluate(0.3, -0.4), quadric(0.3, -0.4), 1e-10) << lambda;
    // Noise is no longer interpolated: the sites' residuals are of the noise's size.
    const HeightMapSpline smooth(sites, noisy, HeightMapPolynomial::quadratic, lambda);
    const Eigen::Vector2d& s = sites[3];
    EXPECT_GT(std::abs(smooth.evaluate(s.x(), s.y()) - noisy[3]), 1e-3) << lambda;
  }
  // lambda = 0 interpolates.
  const HeightMapSpline interpolant(sites, noisy, HeightMapPolynomial::quadratic, 0.0);
  EXPECT_NEAR(interpolant.evaluate(sites[3].x(), sites[3].y()), noisy[3], 1e-10);
  EXPECT_THROW(HeightMapSpline(sites, noisy, HeightMapPolynomial::quadratic, -1.0), InvalidInput);
}

TEST(HeightMapSpline, CubicPolynomialReproducesACubicWhateverTheWeights) {
  const std::vector<Eigen::Vector2d> sites = scattered_sites(30);
  auto cubic = [](double x, double y) {
    return 0.2 - x + 0.5 * y + 0.7 * x * x - 0.3 * x * y + 1.1 * y * y + 0.4 * x * x * x - 0.9 * x * x * y + 0.2 * x * y * y - 0.6 * y * y * y;
  };
  Eigen::VectorXd heights(30), weights(30);
  for (Eigen::Index i = 0; i < 30; ++i) {
    heights[i] = cubic(sites[static_cast<std::size_t>(i)].x(), sites[static_cast<std::size_t>(i)].y());
    weights[i] = 0.1 + static_cast<double>(i % 7);  // any positive weights
  }
  for (const double lambda : {0.0, 1.0, std::numeric_limits<double>::infinity()})
    for (const bool weighted : {false, true}) {
      const HeightMapSpline spline(sites, heights, HeightMapPolynomial::cubic, lambda, weighted ? weights : Eigen::VectorXd());
      EXPECT_NEAR(spline.evaluate(0.3, -0.4), cubic(0.3, -0.4), 1e-10) << lambda << " " << weighted;
    }
  // The quadratic polynomial cannot follow it: its least-squares fit misses.
  const HeightMapSpline quadratic(sites, heights, HeightMapPolynomial::quadratic, std::numeric_limits<double>::infinity());
  EXPECT_GT(std::abs(quadratic.evaluate(0.3, -0.4) - cubic(0.3, -0.4)), 1e-3);
}

TEST(HeightMapSpline, AWeightCountsAsThatManyCopiesOfItsSite) {
  // sum_j w_j r_j^2 with w_j = 2 is the sum with site j listed twice: the least-squares limits agree.
  const std::vector<Eigen::Vector2d> sites = scattered_sites(16);
  Eigen::VectorXd heights(16), weights = Eigen::VectorXd::Ones(16);
  for (Eigen::Index i = 0; i < 16; ++i) heights[i] = std::sin(3 * sites[static_cast<std::size_t>(i)].x()) + (i % 3) * 0.1;
  std::vector<Eigen::Vector2d> doubled = sites;
  Eigen::VectorXd doubled_heights(20);
  doubled_heights.head(16) = heights;
  for (int i = 0; i < 4; ++i) {
    weights[i] = 2;
    doubled.push_back(sites[static_cast<std::size_t>(i)]);
    doubled_heights[16 + i] = heights[i];
  }
  const double inf = std::numeric_limits<double>::infinity();
  const HeightMapSpline weighted(sites, heights, HeightMapPolynomial::cubic, inf, weights);
  const HeightMapSpline copies(doubled, doubled_heights, HeightMapPolynomial::cubic, inf);
  const HeightMapSpline plain(sites, heights, HeightMapPolynomial::cubic, inf);
  EXPECT_NEAR(weighted.evaluate(0.1, 0.2), copies.evaluate(0.1, 0.2), 1e-12);
  EXPECT_GT(std::abs(weighted.evaluate(0.1, 0.2) - plain.evaluate(0.1, 0.2)), 1e-4);  // the weights matter
  EXPECT_THROW(HeightMapSpline(sites, heights, HeightMapPolynomial::cubic, inf, Eigen::VectorXd::Ones(15)), InvalidInput);
  weights[0] = 0;
  EXPECT_THROW(HeightMapSpline(sites, heights, HeightMapPolynomial::cubic, 1.0, weights), InvalidInput);
  weights[0] = std::nan("");
  EXPECT_THROW(HeightMapSpline(sites, heights, HeightMapPolynomial::cubic, inf, weights), InvalidInput);
}

TEST(HeightMapSpline, EnergyIsTheThinPlateIntegral) {
  // J = integral over R^2 of z_xx^2 + 2 z_xy^2 + z_yy^2, by finite differences on a grid that is
  // fine near the sites and coarse far away (the integrand decays as 1/r^4).
  const std::vector<Eigen::Vector2d> sites{{0, 0}, {1, 0}, {0, 1}, {1, 1}, {0.5, 0.5}, {0.2, 0.7}};
  Eigen::VectorXd heights(6);
  heights << 0, 0, 0, 0, 1, 0.3;
  const HeightMapSpline spline(sites, heights);
  const double e = 1e-3;
  double integral = 0;
  auto step = [](double t) { return std::abs(t - 0.5) < 2.0 ? 0.01 : 0.1; };
  for (double x = -30; x < 30; x += step(x)) {
    for (double y = -30; y < 30; y += step(y)) {
      const double cx = x + step(x) / 2, cy = y + step(y) / 2, f = spline.evaluate(cx, cy);
      const double fxx = (spline.evaluate(cx + e, cy) - 2 * f + spline.evaluate(cx - e, cy)) / (e * e);
      const double fyy = (spline.evaluate(cx, cy + e) - 2 * f + spline.evaluate(cx, cy - e)) / (e * e);
      const double fxy = (spline.evaluate(cx + e, cy + e) - spline.evaluate(cx + e, cy - e) -
                          spline.evaluate(cx - e, cy + e) + spline.evaluate(cx - e, cy - e)) / (4 * e * e);
      integral += (fxx * fxx + 2 * fxy * fxy + fyy * fyy) * step(x) * step(y);
    }
  }
  EXPECT_NEAR(integral / spline.bending_energy(), 1.0, 0.01);
}

TEST(HeightMapSpline, RefusesDegenerateSites) {
  const Eigen::VectorXd three = Eigen::VectorXd::Zero(3);
  EXPECT_THROW(HeightMapSpline({{0, 0}, {1, 1}, {2, 2}}, three), InvalidInput);               // collinear
  EXPECT_THROW(HeightMapSpline({{0, 0}, {1, 0}, {1, 0}}, three), InvalidInput);               // duplicate
  EXPECT_THROW(HeightMapSpline({{0, 0}, {1, 0}}, Eigen::VectorXd::Zero(2)), InvalidInput);     // too few
  EXPECT_THROW(HeightMapSpline({{0, 0}, {1, 0}, {0, 1}}, Eigen::VectorXd::Zero(4)), InvalidInput);
  std::vector<Eigen::Vector2d> circle;
  for (int i = 0; i < 8; ++i) circle.emplace_back(std::cos(i * M_PI / 4), std::sin(i * M_PI / 4));
  EXPECT_THROW(HeightMapSpline(circle, Eigen::VectorXd::Zero(8), HeightMapPolynomial::quadratic), InvalidInput);
  // Sites on one conic are on one cubic curve too (the conic times any line); 16 of them.
  for (int i = 8; i < 16; ++i) circle.emplace_back(std::cos(i * M_PI / 8 + 0.1), std::sin(i * M_PI / 8 + 0.1));
  for (const double lambda : {0.0, std::numeric_limits<double>::infinity()})
    EXPECT_THROW(HeightMapSpline(circle, Eigen::VectorXd::Zero(16), HeightMapPolynomial::cubic, lambda), InvalidInput);
}

// --- DuchonSpline ---------------------------------------------------------------------------

TEST(DuchonSpline, InterpolatesAndReproducesPlanesAndQuadrics) {
  const std::vector<Eigen::Vector2d> sites = scattered_sites(20);
  auto quadric = [](double x, double y) { return 0.2 - x + 0.5 * y + 0.7 * x * x - 0.3 * x * y + 1.1 * y * y; };
  Eigen::VectorXd plane(20), bump(20), curved(20);
  for (Eigen::Index i = 0; i < 20; ++i) {
    const Eigen::Vector2d& s = sites[static_cast<std::size_t>(i)];
    plane[i] = 1.5 + 0.3 * s.x() - 0.8 * s.y();
    bump[i] = std::exp(-s.squaredNorm());
    curved[i] = quadric(s.x(), s.y());
  }
  const DuchonSpline flat(sites, plane), bumped(sites, bump), quadratic(sites, curved, HeightMapPolynomial::quadratic);
  for (const auto& [x, y] : std::vector<std::pair<double, double>>{{0.1, 0.2}, {-0.9, 0.4}, {2.0, -3.0}}) {
    EXPECT_NEAR(flat.evaluate(x, y), 1.5 + 0.3 * x - 0.8 * y, kTight);
    EXPECT_NEAR(quadratic.evaluate(x, y), quadric(x, y), 1e-10);
  }
  for (Eigen::Index i = 0; i < 20; ++i) {
    const Eigen::Vector2d& s = sites[static_cast<std::size_t>(i)];
    EXPECT_NEAR(bumped.evaluate(s.x(), s.y()), bump[i], 1e-10);
  }
  // Between the sites it is a smooth surface close to the bump, not the thin plate's surface.
  EXPECT_NEAR(bumped.evaluate(0.1, -0.2), std::exp(-0.05), 0.05);
  EXPECT_GT(std::abs(bumped.evaluate(0.1, -0.2) - HeightMapSpline(sites, bump).evaluate(0.1, -0.2)), 1e-6);
}

TEST(DuchonSpline, RefusesDegenerateSites) {
  const Eigen::VectorXd three = Eigen::VectorXd::Zero(3);
  EXPECT_THROW(DuchonSpline({{0, 0}, {1, 1}, {2, 2}}, three), InvalidInput);  // collinear
  EXPECT_THROW(DuchonSpline({{0, 0}, {1, 0}, {1, 0}}, three), InvalidInput);  // duplicate
  EXPECT_THROW(DuchonSpline({{0, 0}, {1, 0}}, Eigen::VectorXd::Zero(2)), InvalidInput);  // too few
}

// --- VolumeSpline ---------------------------------------------------------------------------

TEST(VolumeSpline, ReproducesAffineDataWithZeroEnergy) {
  const std::vector<Vec3> centres = scattered_centres(25);
  const VolumeSpline flat(centres, values_of(centres, affine)), bumped(centres, values_of(centres, bump));
  for (const Vec3& p : {Vec3(0.1, 0.2, 0.3), Vec3(-2, 5, 1), Vec3(0.9, -0.9, 0.0)})
    EXPECT_NEAR(flat.evaluate(p), affine(p), kTight);
  EXPECT_GT(bumped.bending_energy(), 0.1);
  EXPECT_LE(flat.bending_energy(), 1e-10 * bumped.bending_energy());
}

TEST(VolumeSpline, InterpolatesItsData) {
  const std::vector<Vec3> centres = scattered_centres(25);
  const Eigen::VectorXd values = values_of(centres, bump);
  const VolumeSpline spline(centres, values);
  for (std::size_t i = 0; i < centres.size(); ++i)
    EXPECT_NEAR(spline.evaluate(centres[i]), values[static_cast<Eigen::Index>(i)], 1e-10);
}

TEST(VolumeSpline, EnergyMatrixGivesTheSplinesEnergyAndAnnihilatesAffineData) {
  const std::vector<Vec3> centres = scattered_centres(25);
  const Eigen::MatrixXd energy = volume_spline_energy_matrix(centres);
  const Eigen::VectorXd h = values_of(centres, bump);
  const double expected = VolumeSpline(centres, h).bending_energy();
  EXPECT_NEAR(h.dot(energy * h), expected, 1e-10 * expected);
  EXPECT_LE((energy - energy.transpose()).norm(), kTight * energy.norm());
  EXPECT_GE(Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(energy).eigenvalues().minCoeff(), -1e-12 * energy.norm());
  EXPECT_LE((energy * values_of(centres, affine)).norm(), 1e-10 * energy.norm());
}

TEST(VolumeSpline, UnitsOnlyScaleTheEnergy) {
  // The interpolant does not depend on the units; the energy scales as 1/length.
  const std::vector<Vec3> centres = scattered_centres(20);
  std::vector<Vec3> scaled;
  for (const Vec3& p : centres) scaled.push_back(1000.0 * p + Vec3(5e3, -2e3, 1e4));
  const Eigen::VectorXd values = values_of(centres, bump);
  const VolumeSpline unit(centres, values), large(scaled, values);
  const Vec3 p(0.3, -0.1, 0.2);
  EXPECT_NEAR(large.evaluate(1000.0 * p + Vec3(5e3, -2e3, 1e4)), unit.evaluate(p), 1e-10);
  EXPECT_NEAR(1000.0 * large.bending_energy(), unit.bending_energy(), 1e-9 * unit.bending_energy());
}

TEST(VolumeSpline, CoplanarCentresAreAccepted) {
  // A flat mesh patch: the interpolant and its energy are defined on the plane.
  const std::vector<Vec3> centres = tilted_plane_points(15);
  const Eigen::VectorXd values = values_of(centres, bump);
  const VolumeSpline spline(centres, values);
  for (std::size_t i = 0; i < centres.size(); ++i)
    EXPECT_NEAR(spline.evaluate(centres[i]), values[static_cast<Eigen::Index>(i)], 1e-10);
  EXPECT_GT(spline.bending_energy(), 0.0);
  EXPECT_LE(VolumeSpline(centres, values_of(centres, affine)).bending_energy(), 1e-10 * spline.bending_energy());
}

TEST(VolumeSpline, RefusesDegenerateCentres) {
  const Eigen::VectorXd four = Eigen::VectorXd::Zero(4);
  EXPECT_THROW(VolumeSpline({{0, 0, 0}, {1, 1, 1}, {2, 2, 2}, {3, 3, 3}}, four), InvalidInput);  // collinear
  EXPECT_THROW(VolumeSpline({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 1, 0}}, four), InvalidInput);  // duplicate
  EXPECT_THROW(VolumeSpline({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}, Eigen::VectorXd::Zero(3)), InvalidInput);
  EXPECT_THROW(VolumeSpline({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}}, Eigen::VectorXd::Zero(5)), InvalidInput);
  const double nan = std::numeric_limits<double>::quiet_NaN();
  EXPECT_THROW(VolumeSpline({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, nan}}, four), InvalidInput);
}

// --- Local height map -------------------------------------------------------------------------

TEST(LocalHeightMap, PointOffAPlaneReturnsOntoIt) {
  const std::vector<Vec3> neighbours = tilted_plane_points(12);
  const Vec3 on_plane = Vec3(1, -2, 3) + tilt() * Vec3(0.2, -0.1, 0);
  const Vec3 x = on_plane + 0.05 * tilt().col(2);
  const LocalSurfacePoint fit = fit_local_surface(neighbours, x);
  EXPECT_LE((fit.point - on_plane).norm(), kTight);  // moved along the normal, onto the plane
  EXPECT_LE(fit.surface_variation, 1e-15);
  EXPECT_LE(fit.bending_energy, 1e-20);
  EXPECT_LE((project_to_local_surface(neighbours, x, HeightMapPolynomial::quadratic) - on_plane).norm(), kTight);
}

TEST(LocalHeightMap, SphereIsProjectedAccurately) {
  auto radius_error = [](double h, HeightMapPolynomial polynomial) {
    const auto [neighbours, x] = sphere_neighbourhood(h);
    return std::abs(project_to_local_surface(neighbours, x, polynomial).norm() - 1.0);
  };
  // Quadratic polynomial: well below 1e-4 at h = 0.05, and at least third order.
  const double quadratic = radius_error(0.05, HeightMapPolynomial::quadratic);
  EXPECT_LT(quadratic, 1e-5);
  EXPECT_GT(quadratic / radius_error(0.025, HeightMapPolynomial::quadratic), 8.0);
  // The paper's linear polynomial: second order with a small constant (~0.1 h^2).
  const double linear = radius_error(0.05, HeightMapPolynomial::linear);
  EXPECT_LT(linear, 0.15 * 0.05 * 0.05);
  EXPECT_GT(linear / radius_error(0.025, HeightMapPolynomial::linear), 3.5);
}

// --- Sliding landmarks and the collapse point ---------------------------------------------------

TEST(SlidingLandmarks, IdentityNeedsNoSliding) {
  const std::vector<Vec3> source = scattered_centres(12);
  const SlidingLandmarks relaxed =
      relax_sliding_landmarks(source, source, {0, 3}, {Vec3(1, 0, 0), Vec3(0, 1, 1).normalized()});
  EXPECT_LE(relaxed.t.norm(), 1e-12);
  EXPECT_LE(relaxed.bending_energy, 1e-12);
}

TEST(SlidingLandmarks, OneLandmarkSlidesOffItsDisplacementAlongTheLine) {
  // Y0 = X + e_j delta^T: J(t) = E_jj |delta + t u|^2, minimised at t = -delta.u (unit u).
  const std::vector<Vec3> source = scattered_centres(12);
  std::vector<Vec3> target = source;
  const Vec3 delta(0.1, -0.2, 0.05), u = Vec3(1, 1, 0).normalized();
  target[4] += delta;
  const SlidingLandmarks relaxed = relax_sliding_landmarks(source, target, {4}, {u});
  EXPECT_NEAR(relaxed.t[0], -delta.dot(u), kTight);
  EXPECT_LE((relaxed.relaxed[4] - (source[4] + delta - delta.dot(u) * u)).norm(), kTight);
  EXPECT_NEAR(relaxed.bending_energy, deformation_energy(source, relaxed.relaxed), 1e-9 * relaxed.bending_energy);
}

TEST(SlidingLandmarks, IndependentEndPointsSlideBackFromACollapse) {
  // Why an edge collapse needs one shared parameter: from the collapsed target, the two end points
  // free to slide along the edge go back to where they were (the identity has zero energy).
  const std::vector<Vec3> source = edge_patch();
  std::vector<Vec3> target = source;
  target[0] = target[1] = Vec3(0.5, 0, 0);
  const SlidingLandmarks relaxed =
      relax_sliding_landmarks(source, target, {0, 1}, {Vec3(1, 0, 0), Vec3(1, 0, 0)});
  EXPECT_NEAR(relaxed.t[0], -0.5, 1e-10);
  EXPECT_NEAR(relaxed.t[1], 0.5, 1e-10);
  EXPECT_LE(relaxed.bending_energy, 1e-10);
}

TEST(CollapsePoint, SymmetricEdgeCollapsesToItsMidpoint) {
  std::vector<Vec3> patch = edge_patch();
  for (Vec3& p : patch) p = tilt() * p + Vec3(3, 1, -2);
  const CollapsePoint collapse = optimal_collapse_point(patch, 0, 1);
  EXPECT_NEAR(collapse.s, 0.5, kTight);
  EXPECT_LE((collapse.point - 0.5 * (patch[0] + patch[1])).norm(), kTight);
}

TEST(CollapsePoint, MinimisesTheEnergyOnTheEdge) {
  // An asymmetric flat patch: drop a neighbour of the end point (1, 0) and move another.
  std::vector<Vec3> patch = edge_patch();
  patch.pop_back();
  patch[3] = Vec3(2.3, 0.2, 0);
  const CollapseEnergy energy(patch, 0, 1);
  const CollapsePoint collapse = optimal_collapse_point(patch, 0, 1);
  EXPECT_GT(std::abs(collapse.s - 0.5), 0.01);
  EXPECT_LE((collapse.point - patch[0]).cross(patch[1] - patch[0]).norm(), kTight);  // on the edge line
  EXPECT_NEAR(collapse.bending_energy, energy.at(collapse.s), kTight);
  EXPECT_LE(collapse.bending_energy, energy.at(0.0));
  EXPECT_LE(collapse.bending_energy, energy.at(1.0));
  EXPECT_LE(collapse.bending_energy, energy.at(0.5));
  for (double s = 0; s <= 1; s += 0.01) EXPECT_LE(collapse.bending_energy, energy.at(s) + 1e-12);
  // J(s) is the energy of the deformation that moves both end points to the collapse point.
  std::vector<Vec3> target = patch;
  target[0] = target[1] = collapse.point;
  EXPECT_NEAR(collapse.bending_energy, deformation_energy(patch, target), 1e-9 * collapse.bending_energy);
}

TEST(CollapsePoint, CurvedPatchAndDegenerateCases) {
  std::vector<Vec3> patch = edge_patch();
  for (Vec3& p : patch) p.z() = 0.3 * (p - Vec3(0.5, 0, 0)).squaredNorm();  // symmetric dome
  EXPECT_NEAR(optimal_collapse_point(patch, 0, 1).s, 0.5, 1e-10);
  // Four centres: every deformation is affine, J = 0, the midpoint is returned.
  const std::vector<Vec3> tetrahedron{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  const CollapsePoint collapse = optimal_collapse_point(tetrahedron, 0, 1);
  EXPECT_EQ(collapse.s, 0.5);
  EXPECT_LE(collapse.bending_energy, 1e-20);
  EXPECT_THROW(optimal_collapse_point(patch, 2, 2), InvalidInput);
  EXPECT_THROW(optimal_collapse_point(patch, 0, 10), InvalidInput);
}

TEST(CollapseEnergy, SmallRingKernelMatchesTheFullEnergyMatrix) {
  // Up to 40 centres CollapseEnergy uses a fixed-size kernel (one Cholesky in the border's null
  // space, compiled apart for 8-13 centres) instead of volume_spline_energy_matrix: the same J(s)
  // up to round-off, in 3D (rank 4) and on a plane (rank 3), for each compiled size and beyond.
  std::vector<std::vector<Vec3>> sets;
  for (const int n : {8, 9, 10, 11, 12, 13, 14, 40}) {
    sets.push_back(scattered_centres(n));
    sets.push_back(tilted_plane_points(n));
  }
  for (const std::vector<Vec3>& centres : sets) {
    const Eigen::MatrixXd e = volume_spline_energy_matrix(centres);
    const CollapseEnergy energy(centres, 2, 5);
    const double d2 = (centres[5] - centres[2]).squaredNorm();
    for (const double s : {0.0, 0.3, 1.0}) {
      const double wa = s, wb = s - 1;
      const double expected = d2 * (wa * wa * e(2, 2) + 2 * wa * wb * e(2, 5) + wb * wb * e(5, 5));
      EXPECT_NEAR(energy.at(s), expected, 1e-9 * std::max(1.0, expected));
    }
  }
}
