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
