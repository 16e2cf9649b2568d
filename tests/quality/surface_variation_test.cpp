// surface_variation: sigma = lambda1 / (lambda1 + lambda2 + lambda3) over each vertex's 2-ring.
#include "meshprep/quality/surface_variation.h"

#include "test_meshes.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <map>

namespace meshprep {
namespace {

// Round-off bound for sigma where the exact value is 0 or 1/3 (a ratio of eigenvalues of a 3x3
// covariance of O(1) coordinates).
constexpr double kRoundOff = 1e-12;

std::uint32_t index_of(const TriangleSoup& soup, const Vec3& p) {
  return static_cast<std::uint32_t>(std::find(soup.points.begin(), soup.points.end(), p) - soup.points.begin());
}

TEST(SurfaceVariation, IsZeroOnAFlatGrid) {
  const TriangleSoup flat = test::grid(8, 0.0);
  // The same grid tilted and moved away from the origin: still a plane.
  TriangleSoup tilted = flat;
  const Eigen::Matrix3d rotation = Eigen::AngleAxisd(0.7, Vec3(1, 2, 3).normalized()).toRotationMatrix();
  for (Vec3& p : tilted.points) p = rotation * p + Vec3(100, -50, 25);
  for (const TriangleSoup& soup : {flat, tilted}) {
    const std::vector<double> sigma = surface_variation(soup);
    ASSERT_EQ(sigma.size(), soup.points.size());
    for (std::size_t v = 0; v < sigma.size(); ++v) {
      EXPECT_GE(sigma[v], 0.0) << "vertex " << v;
      EXPECT_LT(sigma[v], kRoundOff) << "vertex " << v;
    }
  }
}

TEST(SurfaceVariation, IsSmallAndNearlyUniformOnASphere) {
  const std::vector<double> sigma = surface_variation(test::icosphere(3));
  const auto [low, high] = std::minmax_element(sigma.begin(), sigma.end());
  // A 2-ring on the unit sphere is a cap of radius ~2h (edge length h ~ 0.13): its depth ~2h^2 is
  // small against its width, so sigma (~h^2 / 4, measured 0.0036 to 0.0044) is small, and the same
  // everywhere up to the icosphere's uneven edge lengths and valences (5 or 6).
  EXPECT_GT(*low, 0.0);
  EXPECT_LT(*high, 0.01);
  EXPECT_LT(*high, 1.5 * *low);
}

TEST(SurfaceVariation, CornerAboveCreaseAboveFlatSide) {
  const TriangleSoup cube = test::subdivided_cube(4);
  const std::vector<double> sigma = surface_variation(cube);
  const double corner = sigma[index_of(cube, Vec3(0, 0, 0))];
  const double crease = sigma[index_of(cube, Vec3(2, 0, 0))];
  const double side = sigma[index_of(cube, Vec3(2, 2, 0))];  // its 2-ring lies in the side's plane
  // Measured: corner 0.19, crease 0.10 (the same for every n >= 4: the 2-rings are congruent).
  EXPECT_LT(side, kRoundOff);
  EXPECT_GT(crease, 0.05);
  EXPECT_GT(corner, 1.5 * crease);
  EXPECT_LE(corner, 1.0 / 3.0 + kRoundOff);
}

TEST(SurfaceVariation, IsOneThirdForIsotropicScatter) {
  // The four corners of a regular tetrahedron (each one's 2-ring) have an isotropic covariance.
  for (const double s : surface_variation(test::regular_tetrahedron(2.0))) EXPECT_NEAR(s, 1.0 / 3.0, kRoundOff);
}

TEST(SurfaceVariation, IsInvariantUnderScalingAndTranslation) {
  const TriangleSoup sphere = test::icosphere(2);
  TriangleSoup moved = sphere;
  for (Vec3& p : moved.points) p = 1000.0 * p + Vec3(1e6, -2e6, 3e6);
  const std::vector<double> sigma = surface_variation(sphere);
  const std::vector<double> sigma_moved = surface_variation(moved);
  ASSERT_EQ(sigma.size(), sigma_moved.size());
  // The centroid is subtracted before the covariance is summed, so the far origin costs only the
  // round-off of the coordinates themselves (1e6 * 1e-16 relative to an edge of ~300).
  for (std::size_t v = 0; v < sigma.size(); ++v) EXPECT_NEAR(sigma_moved[v], sigma[v], 1e-9 * sigma[v]) << v;
}

TEST(SurfaceVariation, IsZeroWithFewerThanThreePointsAround) {
  TriangleSoup soup;
  soup.points = {{0, 0, 0}, {1, 0, 0}, {5, 5, 5}, {0, 0, 1}};  // point 2 is isolated
  soup.triangles = {{0, 1, 1}, {3, 3, 3}};                        // repeated-index triangles: one edge, none
  EXPECT_EQ(surface_variation(soup), (std::vector<double>{0, 0, 0, 0}));
  EXPECT_TRUE(surface_variation(TriangleSoup{}).empty());
}

}  // namespace
}  // namespace meshprep
