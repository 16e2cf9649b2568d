#include "meshprep/quality/statistics.h"
#include "meshprep/quality/triangle_metrics.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

using namespace meshprep;

namespace {
constexpr double kTight = 1e-12;  // closed-form values computed in double: round-off only
}

TEST(TriangleMetrics, EquilateralIsOptimal) {
  const TriangleShape s = triangle_shape({0, 0, 0}, {2, 0, 0}, {1, std::sqrt(3.0), 0});
  EXPECT_NEAR(s.radius_ratio, 1.0, kTight);
  EXPECT_NEAR(s.aspect_ratio, 1.0, kTight);
  EXPECT_NEAR(s.min_angle_deg, 60.0, 1e-10);
  EXPECT_NEAR(s.max_angle_deg, 60.0, 1e-10);
  EXPECT_NEAR(s.area, std::sqrt(3.0), kTight);
  EXPECT_FALSE(s.degenerate);
}

TEST(TriangleMetrics, RightIsoscelesRadiusRatio) {
  // legs 1: R = sqrt(2)/2, r = (2 - sqrt 2)/2  =>  R/(2r) = (1 + sqrt 2)/2 = 1.2071...
  const TriangleShape s = triangle_shape({0, 0, 0}, {1, 0, 0}, {0, 1, 0});
  EXPECT_NEAR(s.radius_ratio, (1.0 + std::sqrt(2.0)) / 2.0, kTight);
  // aspect = sqrt2 (2 + sqrt2) / (4 sqrt3 * 1/2)
  EXPECT_NEAR(s.aspect_ratio, std::sqrt(2.0) * (2.0 + std::sqrt(2.0)) / (2.0 * std::sqrt(3.0)), kTight);
  EXPECT_NEAR(s.min_angle_deg, 45.0, 1e-10);
  EXPECT_NEAR(s.max_angle_deg, 90.0, 1e-10);
  EXPECT_NEAR(s.area, 0.5, kTight);
}

TEST(TriangleMetrics, ScaleAndRotationInvariant) {
  const Vec3 p(0, 0, 0), q(3, 0, 0), r(1, 2, 0);
  const Eigen::Matrix3d rotation = Eigen::AngleAxisd(0.7, Vec3(1, 2, 3).normalized()).toRotationMatrix();
  auto moved = [&](const Vec3& x) -> Vec3 { return 10.0 * (rotation * x) + Vec3(5, -4, 2); };
  const TriangleShape a = triangle_shape(p, q, r);
  const TriangleShape b = triangle_shape(moved(p), moved(q), moved(r));
  EXPECT_NEAR(a.radius_ratio, b.radius_ratio, 1e-12);  // dimensionless: invariant up to round-off
  EXPECT_NEAR(a.aspect_ratio, b.aspect_ratio, 1e-12);
  EXPECT_NEAR(a.min_angle_deg, b.min_angle_deg, 1e-10);
  EXPECT_NEAR(b.area, 100 * a.area, 1e-11);
}

TEST(TriangleMetrics, DegenerateIsInfinite) {
  const TriangleShape s = triangle_shape({0, 0, 0}, {1, 0, 0}, {2, 0, 0});
  EXPECT_TRUE(s.degenerate);
  EXPECT_TRUE(std::isinf(s.radius_ratio));
  EXPECT_TRUE(std::isinf(s.aspect_ratio));
  EXPECT_NEAR(s.min_angle_deg, 0.0, 1e-12);
  EXPECT_NEAR(s.max_angle_deg, 180.0, 1e-12);
}

TEST(TriangleMetrics, RadiusRatioAloneMatchesTheKnownTriangles) {
  EXPECT_NEAR(radius_ratio(Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0.5, std::sqrt(3.0) / 2, 0)), 1.0, 1e-12);
  // Right isosceles with unit legs: R = sqrt(2) / 2, r = (2 - sqrt(2)) / 2, R / 2r = (1 + sqrt(2)) / 2.
  EXPECT_NEAR(radius_ratio(Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0)), (1 + std::sqrt(2.0)) / 2, 1e-12);
  EXPECT_EQ(radius_ratio(Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(2, 0, 0)), std::numeric_limits<double>::infinity());
}

TEST(TriangleMetrics, NeedleAngleIsAccurate) {
  // atan2 keeps a 1e-7 rad angle accurate where acos of a dot product would lose it.
  const double eps = 1e-7;
  const TriangleShape s = triangle_shape({0, 0, 0}, {1, 0, 0}, {1, eps, 0});
  EXPECT_NEAR(s.min_angle_deg, std::atan(eps) * 180.0 / M_PI, 1e-15);
}

TEST(Statistics, NearestRankPercentiles) {
  std::vector<double> v;
  for (int i = 1; i <= 100; ++i) v.push_back(i);
  const Distribution d = summarize(v);
  EXPECT_EQ(d.min, 1);
  EXPECT_EQ(d.max, 100);
  EXPECT_DOUBLE_EQ(d.mean, 50.5);
  EXPECT_EQ(d.p5, 5);  // rank ceil(0.05 * 100) = 5
  EXPECT_EQ(d.p50, 50);
  EXPECT_EQ(d.p95, 95);
  EXPECT_EQ(d.count, 100u);
}

TEST(Statistics, IgnoresNonFiniteAndHandlesEmpty) {
  const Distribution d = summarize({1.0, INFINITY, 3.0, NAN});
  EXPECT_EQ(d.count, 2u);
  EXPECT_DOUBLE_EQ(d.mean, 2.0);
  const Distribution e = summarize({});
  EXPECT_TRUE(std::isnan(e.mean));
  EXPECT_EQ(e.count, 0u);
}
