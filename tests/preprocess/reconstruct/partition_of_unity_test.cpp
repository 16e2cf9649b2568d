#include "meshprep/core/errors.h"
#include "meshprep/core/io.h"
#include "meshprep/preprocess/reconstruct/partition_of_unity.h"
#include "meshprep/preprocess/reconstruct/reconstruct.h"
#include "meshprep/quality/report.h"
#include "preprocess/scattered_points.h"

#include <Eigen/Geometry>
#include <gtest/gtest.h>
#include <tbb/global_control.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <vector>

using namespace meshprep;
using meshprep::test::sample;
using meshprep::test::scattered;

namespace {

const Eigen::Matrix3d& tilt() {
  static const Eigen::Matrix3d r = Eigen::AngleAxisd(0.9, Vec3(1, -2, 0.5).normalized()).toRotationMatrix();
  return r;
}

// The distance from the reconstructed surface point above (x, y) of the frame to the true
// surface, measured along the true surface's up direction `up` (the heights are single-valued).
template <class Height>
double worst_error(const PartitionOfUnity& pu, Height height, const Eigen::Matrix3d& rotation) {
  double worst = 0;
  const Eigen::AlignedBox2d box = pu.footprint();
  for (int i = 0; i <= 40; ++i)
    for (int j = 0; j <= 40; ++j) {
      const Eigen::Vector2d q = box.min() + box.sizes().cwiseProduct(Eigen::Vector2d(i / 40.0, j / 40.0));
      const Vec3 p = rotation.transpose() * pu.surface_point(q.x(), q.y());
      if (std::abs(p.x()) > 0.9 || std::abs(p.y()) > 0.9) continue;  // inside the sampled square
      worst = std::max(worst, std::abs(p.z() - height(p.x(), p.y())));
    }
  return worst;
}

}  // namespace

TEST(PartitionOfUnity, WendlandWeight) {
  EXPECT_EQ(wendland_weight(0), 1.0);
  EXPECT_EQ(wendland_weight(1), 0.0);
  EXPECT_EQ(wendland_weight(2), 0.0);
  EXPECT_NEAR(wendland_weight(0.5), std::pow(0.5, 4) * 3, 1e-15);
}

TEST(PartitionOfUnity, ReproducesATiltedPlaneToRoundOff) {
  auto plane = [](double x, double y) { return 0.3 * x - 0.2 * y + 0.1; };
  const PartitionOfUnity pu(sample(400, plane, tilt()));
  EXPECT_GT(pu.patches(), 20u);
  EXPECT_LT(worst_error(pu, plane, tilt()), 1e-12);
}

TEST(PartitionOfUnity, QuadraticPatchesReproduceAQuadric) {
  // Even in x and y over a sample symmetric in x and in y: the PCA plane is exactly z = const, so
  // the quadric is a quadric of the frame's (x, y) too.
  auto quadric = [](double x, double y) { return 0.2 * x * x + 0.1 * y * y; };
  std::vector<Vec3> points;
  for (const Vec3& p : sample(101, quadric)) {
    if (p.x() == 0 || p.y() == 0) continue;  // (the first site is the origin: its mirrors coincide)
    for (const double sx : {1.0, -1.0})
      for (const double sy : {1.0, -1.0}) points.emplace_back(sx * p.x(), sy * p.y(), p.z());
  }
  PartitionOfUnityParams params;
  params.polynomial = HeightMapPolynomial::quadratic;
  const PartitionOfUnity pu(points, params);
  EXPECT_LT(worst_error(pu, quadric, Eigen::Matrix3d::Identity()), 1e-10);
}

TEST(PartitionOfUnity, EveryPointOfTheFootprintIsCovered) {
  const PartitionOfUnity pu(sample(500, [](double x, double y) { return std::sin(2 * x) * std::cos(3 * y); }));
  const Eigen::AlignedBox2d box = pu.footprint();
  for (int i = 0; i <= 100; ++i)
    for (int j = 0; j <= 100; ++j) {
      const Eigen::Vector2d q = box.min() + box.sizes().cwiseProduct(Eigen::Vector2d(i / 100.0, j / 100.0));
      EXPECT_GT(pu.evaluate(q.x(), q.y()).weight_sum, 0) << q.transpose();
    }
}

TEST(PartitionOfUnity, ARotatedSampleReconstructsAsWellAsTheAxisAlignedOne) {
  auto wave = [](double x, double y) { return 0.15 * std::sin(2 * x) * std::cos(3 * y); };
  const double aligned = worst_error(PartitionOfUnity(sample(600, wave)), wave, Eigen::Matrix3d::Identity());
  const double rotated = worst_error(PartitionOfUnity(sample(600, wave, tilt())), wave, tilt());
  EXPECT_LT(aligned, 0.01);  // a smooth wave of amplitude 0.15 from 600 samples
  EXPECT_LT(rotated, 1.5 * aligned + 1e-6);
}

TEST(PartitionOfUnity, GridEvaluationEqualsPointEvaluation) {
  const PartitionOfUnity pu(sample(700, [](double x, double y) { return 0.2 * std::sin(3 * x) * std::cos(2 * y); }));
  PlaneGrid grid;
  grid.origin = pu.footprint().min() - Eigen::Vector2d(0.05, 0.03);  // a little beyond the footprint
  grid.columns = 37;
  grid.rows = 29;
  grid.step = (pu.footprint().sizes() + Eigen::Vector2d(0.1, 0.06)).cwiseQuotient(Eigen::Vector2d(36, 28));
  const std::vector<PartitionOfUnity::Value> values = pu.evaluate_grid(grid);
  ASSERT_EQ(values.size(), 37u * 29u);
  for (std::size_t j = 0; j < grid.rows; ++j)
    for (std::size_t i = 0; i < grid.columns; ++i) {
      const Eigen::Vector2d q = grid.at(i, j);
      const PartitionOfUnity::Value point = pu.evaluate(q.x(), q.y()), gridded = values[j * grid.columns + i];
      EXPECT_NEAR(gridded.height, point.height, 1e-12) << q.transpose();
      EXPECT_NEAR(gridded.weight_sum, point.weight_sum, 1e-12);
      EXPECT_NEAR(gridded.variation, point.variation, 1e-15);
    }
}

TEST(PartitionOfUnity, SurfaceVariationIsZeroOnAPlaneAndDrivesTheGrowth) {
  const PartitionOfUnity plane(sample(400, [](double x, double y) { return 0.3 * x - 0.2 * y; }, tilt()));
  for (const double sigma : plane.patch_variation()) EXPECT_LT(sigma, 1e-12);
  // A bump: sigma is high around it. The paper's fixed 0.3 never fires on a height field this
  // gentle; the 75th percentile grows about a quarter of the patches, with more samples each.
  auto bump = [](double x, double y) { return 0.3 * std::exp(-20 * (x * x + y * y)); };
  PartitionOfUnityParams fixed;
  fixed.variation_percentile = -1;
  const PartitionOfUnity paper(sample(1500, bump), fixed);
  EXPECT_EQ(paper.grown_patches(), 0u);
  EXPECT_DOUBLE_EQ(paper.variation_threshold(), 0.3);
  PartitionOfUnityParams adaptive;
  adaptive.variation_percentile = 75;
  const PartitionOfUnity grown(sample(1500, bump), adaptive);
  const double share = static_cast<double>(grown.grown_patches()) / static_cast<double>(grown.patches());
  EXPECT_GT(share, 0.2);
  EXPECT_LE(share, 0.25);
  EXPECT_GT(grown.evaluate(0.15, 0).variation, grown.evaluate(0.8, 0.8).variation);
  EXPECT_LT(worst_error(grown, bump, Eigen::Matrix3d::Identity()), 0.01);
}

TEST(PartitionOfUnity, RefusesBadInput) {
  EXPECT_THROW(PartitionOfUnity(sample(10, [](double, double) { return 0.0; })), InvalidInput);  // < 40 points
  std::vector<Vec3> points = sample(100, [](double x, double) { return x; });
  points[5] = points[6];  // two samples at the same place
  EXPECT_THROW(PartitionOfUnity{points}, InvalidInput);
  points = sample(100, [](double, double) { return 0.0; });
  points[5] = points[6] + Vec3(0, 0, 1);  // one above the other: not a height field
  EXPECT_THROW(PartitionOfUnity{points}, InvalidInput);
  points = sample(100, [](double x, double) { return x; });
  points[3].x() = std::nan("");
  EXPECT_THROW(PartitionOfUnity{points}, InvalidInput);
  PartitionOfUnityParams bad;
  bad.enlargement = 1.0;
  EXPECT_THROW(PartitionOfUnity(sample(100, [](double, double) { return 0.0; }), bad), InvalidInput);
  bad = PartitionOfUnityParams();
  bad.variation_percentile = 101;
  EXPECT_THROW(PartitionOfUnity(sample(100, [](double, double) { return 0.0; }), bad), InvalidInput);
}

TEST(Reconstruct, NanSpacingOrGapIsRefused) {
  const std::vector<Vec3> points = sample(100, [](double, double) { return 0.0; });
  ReconstructParams params;
  params.max_gap = std::nan("");
  EXPECT_THROW(reconstruct_surface(points, params), InvalidInput);
  params = ReconstructParams();
  params.spacing = std::nan("");
  EXPECT_THROW(reconstruct_surface(points, params), InvalidInput);
}

TEST(PartitionOfUnity, ADegenerateLocalFitIsNamedByItsPlace) {
  // Two parallel lines of samples a unit apart: the set spans an area, but every cell's nearest
  // samples lie on one line, where no height map is determined. The message gives the place, not
  // the spline class's name.
  std::vector<Vec3> lines;
  for (int i = 0; i < 500; ++i)
    for (const double y : {0.0, 1.0}) lines.emplace_back(i / 499.0, y, 0.0);
  try {
    const PartitionOfUnity pu(lines);
    ADD_FAILURE() << "two lines of samples accepted";
  } catch (const Error& e) {
    const std::string message = e.what();
    EXPECT_EQ(message.rfind("the local surface of the ", 0), 0u) << message;
    EXPECT_NE(message.find(" points around ("), std::string::npos) << message;
  }
}

TEST(PartitionOfUnity, RefusesPointsAlongACurveAndAcceptsANarrowStrip) {
  // 1,000 points on a line with 1e-9 noise across it (issue 30: a grid of 178 k needles), and the
  // same on a tilted line; then a strip three samples wide, which is a surface.
  std::vector<Vec3> line;
  for (int i = 0; i < 1000; ++i) {
    const double t = i / 999.0;
    line.push_back(Vec3(t, 2 * t, 3 * t) + 1e-9 * Vec3(std::sin(7.0 * i), std::cos(11.0 * i), std::sin(13.0 * i)));
  }
  try {
    const PartitionOfUnity pu(line);
    ADD_FAILURE() << "points on a line accepted";
  } catch (const InvalidInput& e) {
    EXPECT_NE(std::string(e.what()).find("collinear"), std::string::npos) << e.what();
  }
  std::vector<Vec3> strip;
  for (int i = 0; i < 300; ++i)
    for (int j = 0; j < 3; ++j) strip.push_back(tilt() * Vec3(0.01 * i + 0.003 * j, 0.01 * j, 0));
  EXPECT_NO_THROW(PartitionOfUnity{strip});
}

TEST(SharedPartitionOfUnity, JacksboroHeldOutPoints) {
  // The anchors' measurement (../shared/anchors.md): predict the grid points not in the sample.
  const std::filesystem::path dir = std::filesystem::path(MESHPREP_SHARED_DATA_DIR) / "points";
  if (!std::filesystem::exists(dir / "jacksboro_10k.xyz"))
    GTEST_SKIP() << "../shared/data/points not found beside the clone: the jacksboro figure is skipped";
  auto read = [](const std::filesystem::path& file) {
    std::vector<Vec3> points;
    std::ifstream in(file);
    double x, y, z;
    while (in >> x >> y >> z) points.emplace_back(x, y, z);
    return points;
  };
  const std::vector<Vec3> sample = read(dir / "jacksboro_10k.xyz"), grid = read(dir / "jacksboro_grid.xyz");
  std::map<std::pair<long long, long long>, bool> in_sample;
  for (const Vec3& p : sample) in_sample[{std::llround(p.x() * 1000), std::llround(p.y() * 1000)}] = true;
  // RMS of the held-out points for a fit with `params`.
  auto held_out_rms = [&](const PartitionOfUnityParams& params) {
    const PartitionOfUnity pu(sample, params);
    double squared = 0;
    std::size_t count = 0;
    for (const Vec3& p : grid) {
      if (in_sample.count({std::llround(p.x() * 1000), std::llround(p.y() * 1000)})) continue;
      // The terrain's PCA plane is nearly horizontal: intersect the vertical through p with the
      // reconstruction by evaluating at p's frame (x, y) and correcting along the frame normal.
      const Vec3 local = pu.frame().to_local(p);
      const Vec3 surface = pu.surface_point(local.x(), local.y());
      const double error = (surface - p).dot(pu.frame().normal()) / std::abs(pu.frame().normal().z());
      squared += error * error;
      ++count;
    }
    EXPECT_EQ(count, 128632u);
    return std::sqrt(squared / static_cast<double>(count));
  };
  const double rms = held_out_rms(PartitionOfUnityParams());
  // Goal 18.7 m (the global thin-plate spline). Measured 18.535 m with the defaults (Duchon
  // r^(5/2) patches, p90 growth), 18.564 m without the growth; thin-plate patches gave 18.74 m
  // (bench/RESULTS.md, docs/reconstruction.md).
  EXPECT_LE(rms, 18.7) << rms;
  // The paper's curvature analysis must keep paying for itself: growing the high-sigma patches
  // lowers the error (by 0.03 m measured; a fixed 0.3 threshold grows none on terrain).
  PartitionOfUnityParams no_growth;
  no_growth.variation_percentile = -1;
  no_growth.variation_threshold = 0.3;
  EXPECT_LT(rms, held_out_rms(no_growth) - 0.01) << rms;
  RecordProperty("rms_m", std::to_string(rms));
  std::cout << "jacksboro held-out RMS " << rms << " m\n";
}

namespace {
// A disc of radius 1 without the samples within 0.35 of (0.3, 0), on z = 0.1 x^2.
std::vector<Vec3> holed_disc() {
  std::vector<Vec3> points;
  for (const Eigen::Vector2d& s : scattered(3000)) {
    if (s.norm() > 1 || (s - Eigen::Vector2d(0.3, 0)).norm() < 0.35) continue;
    points.emplace_back(s.x(), s.y(), 0.1 * s.x() * s.x());
  }
  return points;
}
}  // namespace

TEST(Reconstruct, AHoleInTheSampleStaysOpenAndTheMeshManifold) {
  // A disc of radius 1 without the samples within 0.35 of (0.3, 0): the grid over the footprint
  // must leave the hole (and the corners outside the disc) out, not paper over them.
  const std::vector<Vec3> points = holed_disc();
  ReconstructParams params;
  params.columns = params.rows = 80;
  const ReconstructResult result = reconstruct_surface(points, params);
  const QualityReport q = analyze_quality(result.mesh);
  EXPECT_GT(result.gap_triangles, 0u);
  EXPECT_TRUE(q.manifold);
  EXPECT_EQ(q.self_intersections, 0u);
  EXPECT_EQ(q.boundary_loops, 2u);  // the rim and the hole
  for (const Triangle& t : result.mesh.triangles) {
    const Vec3 centre = (result.mesh.points[t[0]] + result.mesh.points[t[1]] + result.mesh.points[t[2]]) / 3.0;
    EXPECT_GT((centre.head<2>() - Eigen::Vector2d(0.3, 0)).norm(), 0.35 - result.max_gap);
  }
  EXPECT_GT(result.normal.z(), 0.99);  // turned up: the faces face +z
}

TEST(Reconstruct, VerticesSetsTheGridSizeOnSquareCells) {
  const std::vector<Vec3> points = sample(500, [](double x, double y) { return 0.1 * x * y; });
  ReconstructParams params;
  params.vertices = 2500;
  const ReconstructResult result = reconstruct_surface(points, params);
  EXPECT_NEAR(static_cast<double>(result.columns * result.rows), 2500.0, 2500.0 * 0.05);
  EXPECT_EQ(result.vertex_variation.size(), result.mesh.points.size());
}

TEST(Reconstruct, TheSameResultOnOneThreadAsOnAll) {
  const std::vector<Vec3> points = sample(2000, [](double x, double y) { return 0.2 * std::sin(4 * x * y); });
  ReconstructParams params;
  params.columns = params.rows = 60;
  const ReconstructResult all = reconstruct_surface(points, params);
  const tbb::global_control one(tbb::global_control::max_allowed_parallelism, 1);
  const ReconstructResult single = reconstruct_surface(points, params);
  ASSERT_EQ(all.mesh.points.size(), single.mesh.points.size());
  for (std::size_t v = 0; v < all.mesh.points.size(); ++v) EXPECT_EQ(all.mesh.points[v], single.mesh.points[v]);
  EXPECT_EQ(all.mesh.triangles, single.mesh.triangles);
  EXPECT_EQ(all.vertex_variation, single.vertex_variation);
}

TEST(Reconstruct, FillHolesKeepsAHoleInTheDataFlaggedAndLeavesOneBoundaryLoop) {
  // The holed disc of the test above, with fill_holes: the hole (interior, away from the grid's
  // border) is kept and its faces listed; the corners outside the disc reach the border and stay
  // out, so the rim is the only boundary loop (what extrude_to_block needs).
  const std::vector<Vec3> points = holed_disc();
  ReconstructParams params;
  params.columns = params.rows = 80;
  params.fill_holes = true;
  const ReconstructResult result = reconstruct_surface(points, params);
  const QualityReport q = analyze_quality(result.mesh);
  EXPECT_TRUE(q.manifold);
  EXPECT_EQ(q.boundary_loops, 1u);
  ASSERT_FALSE(result.filled_faces.empty());
  EXPECT_EQ(result.filled_triangles, result.filled_faces.size());
  // Every filled face lies in the hole, farther than max_gap from the samples around it.
  for (const std::size_t f : result.filled_faces) {
    const Triangle& t = result.mesh.triangles[f];
    const Vec3 centre = (result.mesh.points[t[0]] + result.mesh.points[t[1]] + result.mesh.points[t[2]]) / 3.0;
    EXPECT_LT((centre.head<2>() - Eigen::Vector2d(0.3, 0)).norm(), 0.35) << f;
  }
  // The corners of the footprint's square outside the disc stay out.
  for (const Vec3& p : result.mesh.points) EXPECT_LT(p.head<2>().norm(), 1 + 2 * result.max_gap);
}
