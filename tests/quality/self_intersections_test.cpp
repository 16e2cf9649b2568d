#include "meshprep/quality/self_intersections.h"

#include "test_meshes.h"

#include <gtest/gtest.h>

using namespace meshprep;

TEST(SelfIntersections, ClosedSurfacesHaveNone) {
  EXPECT_EQ(find_self_intersections(test::cube()).count, 0u);
  EXPECT_EQ(find_self_intersections(test::icosphere(3)).count, 0u);
  EXPECT_EQ(find_self_intersections(test::torus(32, 16)).count, 0u);
}

TEST(SelfIntersections, TwoInterpenetratingTetrahedraAreFound) {
  const TriangleSoup a = test::regular_tetrahedron(1.0);
  const TriangleSoup s = test::merged(a, test::translated(a, {0.2, 0.1, 0.15}));
  const SelfIntersections si = find_self_intersections(s);
  EXPECT_GT(si.count, 0u);
  for (const auto& [i, j] : si.pairs) {  // only pairs across the two tetrahedra
    EXPECT_LT(i, 4u);
    EXPECT_GE(j, 4u);
  }
  // Moved far apart: none.
  EXPECT_EQ(find_self_intersections(test::merged(a, test::translated(a, {3, 0, 0}))).count, 0u);
}

TEST(SelfIntersections, FoldedNeighboursIntersect) {
  // Two faces on edge (0,1) whose opposite corners lie on the same side, in one plane: a fold.
  TriangleSoup s;
  s.points = {{0, 0, 0}, {2, 0, 0}, {1, 1, 0}, {1, 2, 0}};
  s.triangles = {{0, 1, 2}, {1, 0, 3}};
  EXPECT_EQ(find_self_intersections(s).count, 1u);
  s.points[3] = {1, -2, 0};  // unfolded: a flat quad
  EXPECT_EQ(find_self_intersections(s).count, 0u);
}

TEST(SelfIntersections, VertexNeighbourPiercing) {
  // Faces sharing vertex 0; the second one's far edge passes through the first.
  TriangleSoup s;
  s.points = {{0, 0, 0}, {2, 0, 0}, {0, 2, 0}, {0.5, 0.5, -1}, {0.5, 0.5, 1}};
  s.triangles = {{0, 1, 2}, {0, 3, 4}};
  EXPECT_EQ(find_self_intersections(s).count, 1u);
  s.points[3] = {-0.5, -0.5, -1};  // far edge now outside the first face
  s.points[4] = {-0.5, -0.5, 1};
  EXPECT_EQ(find_self_intersections(s).count, 0u);
}

TEST(SelfIntersections, CapStopsCounting) {
  const TriangleSoup a = test::icosphere(2);
  const TriangleSoup s = test::merged(a, test::translated(a, {0.5, 0, 0}));
  const SelfIntersections all = find_self_intersections(s);
  ASSERT_GT(all.count, 5u);
  const SelfIntersections capped = find_self_intersections(s, 5);
  EXPECT_EQ(capped.count, 5u);
  EXPECT_TRUE(capped.capped);
}

// Issue 30: the broad phase passed every pair of a vertex's fan to the exact test, because their
// boxes all overlap at the vertex (a fan of 20,000 corners took over 120 s; a cylinder whose caps
// are fans of 6,000 corners, 24 k faces, 24 s). The exact tests must grow with the faces.
TEST(SelfIntersections, FansCostExactTestsInProportionToTheirFaces) {
  const TriangleSoup fan = test::fan_triangulated_polygon(20000);
  const SelfIntersections in_fan = find_self_intersections(fan);
  EXPECT_EQ(in_fan.count, 0u);
  EXPECT_LT(in_fan.exact_tests, 2 * fan.triangles.size());  // was n^2 / 2

  const TriangleSoup cylinder = test::cylinder_with_fan_caps(6000);
  const SelfIntersections in_cylinder = find_self_intersections(cylinder);
  EXPECT_EQ(in_cylinder.count, 0u);
  EXPECT_LT(in_cylinder.exact_tests, 5 * cylinder.triangles.size());
}

// What the fans' broad phase skips must not hide a crossing: one far corner pulled across the
// fan makes its two faces overlap others that have only the fan's corner in common with them; two
// neighbouring corners pulled there, one above and one below the plane, make an edge that pierces
// such a face.
TEST(SelfIntersections, CornersPulledAcrossAFanAreFound) {
  TriangleSoup fan = test::fan_triangulated_polygon(200);
  fan.points[50] = {-0.5, -0.2, 0};
  const SelfIntersections flat = find_self_intersections(fan);
  EXPECT_GT(flat.count, 0u);
  EXPECT_LT(flat.exact_tests, 2 * fan.triangles.size());
  fan.points[50].z() = 0.25;
  fan.points[49] = {-0.5, -0.2, -0.25};
  EXPECT_GT(find_self_intersections(fan).count, 0u);
}
