#include "meshprep/quality/surface_distance.h"
#include "meshprep/quality/triangle_bvh.h"

#include "test_meshes.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <random>

using namespace meshprep;

TEST(TriangleBvh, ClosestPointMatchesBruteForce) {
  const TriangleSoup s = test::icosphere(3);
  const TriangleBvh bvh(s);
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(-2, 2);
  for (int k = 0; k < 200; ++k) {
    const Vec3 p(u(rng), u(rng), u(rng));
    double best = INFINITY;
    for (const Triangle& t : s.triangles)
      best = std::min(best, (closest_point_on_triangle(p, s.points[t[0]], s.points[t[1]], s.points[t[2]]) - p).squaredNorm());
    EXPECT_DOUBLE_EQ(bvh.closest_point(p).squared_distance, best);
  }
}

// The early-exit query gives the closest point's answer on either side of the distance, and at it.
TEST(TriangleBvh, ReachesWithinAgreesWithTheClosestPoint) {
  const TriangleSoup s = test::icosphere(3);
  const TriangleBvh bvh(s);
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> u(-1.5, 1.5);
  for (int k = 0; k < 200; ++k) {
    const Vec3 p(u(rng), u(rng), u(rng));
    const double d2 = bvh.closest_point(p).squared_distance;
    EXPECT_TRUE(bvh.reaches_within(p, d2));
    EXPECT_TRUE(bvh.reaches_within(p, 1.01 * d2 + 1e-12));
    if (d2 > 0) {
      EXPECT_FALSE(bvh.reaches_within(p, 0.99 * d2));
    }
  }
  EXPECT_FALSE(bvh.reaches_within(Vec3(3, 0, 0), 3.9));  // the sphere's radius is 1: 2 from (3, 0, 0)
  EXPECT_TRUE(bvh.reaches_within(Vec3(3, 0, 0), 4.1));
}

// The hierarchy keeps its boxes in single precision, rounded outwards: a filter, never an answer.
// Far from the origin (floats 1 apart at 1e7, where the sphere is 2e-3 wide: every box is as
// wide as the whole surface) and beyond the float range (1e39), the closest points, the first
// hits and the overlapping faces are still exactly those of a search over every triangle.
TEST(TriangleBvh, CoarseBoxesStillGiveExactAnswers) {
  for (const auto& [scale, offset] : {std::pair(1e-3, 1e7), std::pair(1e33, 1e39), std::pair(1.0, 0.0)}) {
    TriangleSoup s = test::icosphere(2, scale);
    for (Vec3& p : s.points) p += Vec3::Constant(offset);
    const TriangleBvh bvh(s);
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> u(-2 * scale, 2 * scale);
    for (int k = 0; k < 100; ++k) {
      const Vec3 p = Vec3::Constant(offset) + Vec3(u(rng), u(rng), u(rng));
      double best = INFINITY, nearest_hit = INFINITY;
      const Vec3 direction = (Vec3::Constant(offset) - p).normalized();
      std::vector<std::size_t> overlapping;
      Box3 query(p);
      query.extend(p + Vec3::Constant(0.5 * scale));
      for (std::size_t f = 0; f < s.triangles.size(); ++f) {
        const Triangle& t = s.triangles[f];
        const double d2 = (closest_point_on_triangle(p, s.points[t[0]], s.points[t[1]], s.points[t[2]]) - p).squaredNorm();
        best = std::min(best, d2);
        const double along = ray_triangle(p, direction, s.points[t[0]], s.points[t[1]], s.points[t[2]]);
        nearest_hit = std::min(nearest_hit, along);
        Box3 box;
        box.setEmpty();
        for (auto v : t) box.extend(s.points[v]);
        if (box.intersects(query)) overlapping.push_back(f);
      }
      const TriangleBvh::Hit found = bvh.closest_point(p);
      EXPECT_EQ(found.squared_distance, best);
      const Triangle& at = s.triangles[found.face];
      EXPECT_EQ((closest_point_on_triangle(p, s.points[at[0]], s.points[at[1]], s.points[at[2]]) - p).squaredNorm(), best);
      const TriangleBvh::RayHit ray = bvh.first_hit(p, direction, s.triangles.size());
      EXPECT_EQ(ray.distance, nearest_hit);
      std::vector<std::size_t> listed;
      bvh.for_each_overlapping(query, [&](std::size_t f) { listed.push_back(f); });
      std::sort(listed.begin(), listed.end());
      // A superset (the boxes are widened): every face the exact boxes overlap is listed.
      EXPECT_TRUE(std::includes(listed.begin(), listed.end(), overlapping.begin(), overlapping.end()));
    }
  }
}

TEST(ClosestPointOnTriangle, Regions) {
  const Vec3 a(0, 0, 0), b(1, 0, 0), c(0, 1, 0);
  EXPECT_TRUE(closest_point_on_triangle({0.2, 0.2, 5}, a, b, c).isApprox(Vec3(0.2, 0.2, 0)));
  EXPECT_TRUE(closest_point_on_triangle({-1, -1, 0}, a, b, c).isApprox(a));
  EXPECT_TRUE(closest_point_on_triangle({0.5, -3, 1}, a, b, c).isApprox(Vec3(0.5, 0, 0)));
  EXPECT_TRUE(closest_point_on_triangle({1, 1, 0}, a, b, c).isApprox(Vec3(0.5, 0.5, 0)));
}

TEST(SurfaceDistance, MeshAgainstItselfIsZero) {
  const TriangleSoup s = test::icosphere(2);
  DistanceParams p;
  p.samples = 20000;
  p.refine_faces = 16;
  const SurfaceDistance d = surface_distance(s, s, p);
  // Each sample lies on the surface it is measured against: only the round-off of the
  // closest-point projection remains (unit sphere: ~1e-16).
  EXPECT_LT(d.hausdorff(), 1e-14);
  EXPECT_LT(d.rms(), 1e-14);
}

TEST(SurfaceDistance, ShiftedPlaneGivesTheShift) {
  // Two parallel 10 x 10 grids 0.25 apart over the same footprint: every point of one lies
  // exactly 0.25 above or below the other surface.
  const double shift = 0.25;
  const TriangleSoup a = test::grid(10), b = test::grid(10, shift);
  DistanceParams p;
  p.samples = 20000;
  p.refine_faces = 16;
  const SurfaceDistance d = surface_distance(a, b, p);
  EXPECT_NEAR(d.hausdorff(), shift, 1e-12);
  EXPECT_NEAR(d.rms(), shift, 1e-12);
  EXPECT_NEAR(d.mean(), shift, 1e-12);
}

TEST(SurfaceDistance, SphereInscribedPolyhedronConverges) {
  // An icosphere's vertices lie on the unit sphere and its faces inside it; the gap shrinks
  // about 4x per subdivision level (the sagitta of an edge of length h is ~h^2/8).
  DistanceParams p;
  p.samples = 20000;
  p.refine_faces = 16;
  const double coarse = surface_distance(test::icosphere(2), test::icosphere(4), p).hausdorff();
  const double fine = surface_distance(test::icosphere(3), test::icosphere(4), p).hausdorff();
  EXPECT_GT(coarse, 2.5 * fine);
}

TEST(SurfaceDistance, DeterministicForASeed) {
  const TriangleSoup a = test::icosphere(2), b = test::icosphere(3, 1.01);
  DistanceParams p;
  p.samples = 5000;
  p.refine_faces = 16;
  const SurfaceDistance d1 = surface_distance(a, b, p), d2 = surface_distance(a, b, p);
  EXPECT_EQ(d1.rms(), d2.rms());
  EXPECT_EQ(d1.hausdorff(), d2.hausdorff());
}
