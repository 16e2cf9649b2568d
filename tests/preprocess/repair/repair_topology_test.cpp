// The repair's non-manifold split (repair.h, step 3) on hand-made cases: bow-tie vertices, two
// cubes on one edge.
#include "meshprep/preprocess/repair/repair.h"
#include "meshprep/quality/topology.h"
#include "meshprep/quality/triangle_metrics.h"

#include "test_meshes.h"

#include <gtest/gtest.h>

namespace meshprep {
namespace {

TEST(RepairSplit, ABowTieOfTwoTrianglesBecomesTwoSheets) {
  TriangleSoup soup;
  soup.points = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {-1, 0, 0}, {0, -1, 0}};
  soup.triangles = {{0, 1, 2}, {0, 3, 4}};
  ASSERT_FALSE(analyze_topology(soup).manifold);
  const RepairResult r = repair(soup);
  EXPECT_EQ(r.split_vertices, 1u);
  EXPECT_EQ(r.split_edges, 0u);
  EXPECT_EQ(soup.points.size(), 6u);
  EXPECT_TRUE(analyze_topology(soup).manifold);
}

TEST(RepairSplit, TwoTetrahedraOnOneVertexBecomeTwoClosedSheets) {
  const TriangleSoup tet = test::regular_tetrahedron();
  TriangleSoup soup = test::merged(tet, test::translated(tet, tet.points[0] - tet.points[1]));  // touch at one point
  const RepairResult r = repair(soup);
  EXPECT_EQ(r.welded_vertices, 1u);
  EXPECT_EQ(r.split_vertices, 1u);
  EXPECT_EQ(r.components, 2u);
  const Topology t = analyze_topology(soup);
  EXPECT_TRUE(t.closed && t.manifold && t.oriented);
  EXPECT_NEAR(signed_volume(soup), 2 * signed_volume(tet), 1e-12);
}

// The four faces on the shared edge pair across the two boxes' wedges, not across the empty ones.
TEST(RepairSplit, TwoCubesOnOneEdgeStayTwoClosedCubes) {
  TriangleSoup soup = test::merged(test::cube(), test::translated(test::cube(), {1, 1, 0}));
  const RepairResult r = repair(soup);
  EXPECT_EQ(r.split_edges, 1u);
  EXPECT_EQ(r.split_vertices, 2u);
  EXPECT_EQ(r.components, 2u);
  EXPECT_EQ(r.flipped_faces + r.inverted_components, 0u);
  const Topology t = analyze_topology(soup);
  EXPECT_TRUE(t.closed && t.manifold && t.oriented);
  EXPECT_EQ(t.components, 2u);
  EXPECT_NEAR(signed_volume(soup), 2.0, 1e-12);
}

}  // namespace
}  // namespace meshprep
