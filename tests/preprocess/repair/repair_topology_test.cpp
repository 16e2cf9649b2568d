// The repair's non-manifold split and hole filling (repair.h, steps 3 and 5) on hand-made cases:
// bow-tie vertices, two cubes on one edge, a square hole in a plane, a sphere without its cap.
#include "meshprep/preprocess/repair/repair.h"
#include "meshprep/quality/self_intersections.h"
#include "meshprep/quality/topology.h"
#include "meshprep/quality/triangle_metrics.h"

#include "test_meshes.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace meshprep {
namespace {

// Without the faces whose centroid `drop` holds.
template <class Drop>
TriangleSoup without(TriangleSoup soup, Drop drop) {
  const auto kept = std::remove_if(soup.triangles.begin(), soup.triangles.end(), [&](const Triangle& t) {
    return drop((soup.points[t[0]] + soup.points[t[1]] + soup.points[t[2]]) / 3);
  });
  soup.triangles.erase(kept, soup.triangles.end());
  return soup;
}

TriangleSoup scaled(TriangleSoup soup, double s) {
  for (Vec3& p : soup.points) p *= s;
  return soup;
}

// A 24 x 24 grid without its 6 x 6 middle cells: the hole's rim is 24 long, the outline 96.
TriangleSoup grid_with_square_hole() {
  return without(test::grid(24), [](const Vec3& c) { return c.x() > 9 && c.x() < 15 && c.y() > 9 && c.y() < 15; });
}

// The unit icosphere without the faces above z = 0.7: a zigzag rim of radius ~0.7, 6.1 long, 1.8 x
// the diagonal (3.3: the box lost its top).
TriangleSoup sphere_without_cap() {
  return without(test::icosphere(3), [](const Vec3& c) { return c.z() > 0.7; });
}

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
  EXPECT_EQ(r.open_holes, 1u);  // the two borders through the point, 2.4 x the diagonal: a sheet's
}

// The two copies of the point are then held apart (separate_pinches.h), so the faces no longer
// touch: each moves 1e-3 x the unit edge, and its three faces (area sqrt 3 / 4 each) sweep at most
// 1e-3 x 3 (sqrt 3 / 4) / 3 of volume.
TEST(RepairSplit, TwoTetrahedraOnOneVertexBecomeTwoClosedSheets) {
  const TriangleSoup tet = test::regular_tetrahedron();
  TriangleSoup soup = test::merged(tet, test::translated(tet, tet.points[0] - tet.points[1]));  // touch at one point
  const RepairResult r = repair(soup);
  EXPECT_EQ(r.welded_vertices, 1u);
  EXPECT_EQ(r.split_vertices, 1u);
  EXPECT_EQ(r.components, 2u);
  EXPECT_EQ(r.separated_pinches, 2u);
  const Topology t = analyze_topology(soup);
  EXPECT_TRUE(t.closed && t.manifold && t.oriented);
  EXPECT_EQ(find_self_intersections(soup).count, 0u);
  EXPECT_NEAR(signed_volume(soup), 2 * signed_volume(tet), 2 * 1e-3 * std::sqrt(3.0) / 4);
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
  // The four copies at the edge's ends are held apart: each moves 1e-3 (the shortest edge is 1)
  // and its faces (at most 1.5 of area at a cube's corner) sweep at most 1e-3 x 1.5 / 3 of volume.
  EXPECT_EQ(r.separated_pinches, 4u);
  EXPECT_EQ(find_self_intersections(soup).count, 0u);
  EXPECT_NEAR(signed_volume(soup), 2.0, 4 * 1e-3 * 1.5 / 3);
}

// A fin on a cube's edge (three faces on it): the cube's two faces pair across its solid wedge,
// the fin keeps the edge as a border, and its loop is left open even with no length limit, since
// a patch would only repeat the fin.
TEST(RepairSplit, AFinOnACubesEdgeLeavesTheCubeClosed) {
  TriangleSoup soup = test::cube();
  soup.points.push_back({0.5, -1, 0.5});
  soup.triangles.push_back({0, 1, static_cast<std::uint32_t>(soup.points.size() - 1)});
  RepairParams params;
  params.max_hole = std::numeric_limits<double>::infinity();
  const RepairResult r = repair(soup, params);
  EXPECT_EQ(r.split_edges, 1u);
  EXPECT_EQ(r.split_vertices, 2u);
  ASSERT_EQ(r.holes.size(), 1u);
  EXPECT_FALSE(r.holes[0].filled);
  EXPECT_NE(r.holes[0].left_open.find("lone face"), std::string::npos) << r.holes[0].left_open;
  EXPECT_EQ(soup.triangles.size(), 13u);
  const Topology t = analyze_topology(soup);
  EXPECT_TRUE(t.manifold && t.oriented);
  EXPECT_EQ(t.components, 2u);
  EXPECT_EQ(t.boundary_loops, 1u);
  // The cube's two copies at the fin's edge are held apart from the fin's (as above).
  EXPECT_NEAR(signed_volume(TriangleSoup{soup.points, {soup.triangles.begin(), soup.triangles.end() - 1}}), 1.0,
              2 * 1e-3 * 1.5 / 3);
}

// Every point the patch adds is an average of points at z = 0 (centroids, then the fairing's
// solve with a zero right-hand side in z), so z is exactly 0; the patch covers the removed cells.
TEST(RepairHoles, ASquareHoleInAPlaneIsFilledInThePlane) {
  TriangleSoup soup = grid_with_square_hole();
  RepairParams params;
  params.max_hole = 1.0;  // the rim is 24 / 33.9 = 0.71 x the diagonal, the outline 2.8 x
  const RepairResult r = repair(soup, params);
  ASSERT_EQ(r.holes.size(), 2u);
  EXPECT_EQ(r.filled_holes, 1u);
  EXPECT_EQ(r.open_holes, 1u);
  const auto filled = std::find_if(r.holes.begin(), r.holes.end(), [](const RepairHole& h) { return h.filled; });
  EXPECT_EQ(filled->rim_vertices, 24u);
  EXPECT_GT(filled->patch_vertices, 0u);  // refined to the grid's density, then faired
  EXPECT_TRUE(filled->faired);
  EXPECT_NEAR(filled->patch_area, 36.0, 1e-12 * 36);
  EXPECT_EQ(filled->plane_distance, 0.0);
  for (const Vec3& p : soup.points) EXPECT_EQ(p.z(), 0.0);
  const Topology t = analyze_topology(soup);
  EXPECT_TRUE(t.manifold && t.oriented);
  EXPECT_EQ(t.boundary_loops, 1u);
}

// Two 2 x 2 holes touching at the corner (11, 11) make it a bow-tie: the split gives each fan a
// copy, each hole's walk enters the point through one copy and leaves through the other, and once
// the two patches fill the sectors between the fans the copies are one vertex again.
TEST(RepairHoles, TwoHolesTouchingAtACornerMakeTheCornerManifold) {
  TriangleSoup soup = without(test::grid(24), [](const Vec3& c) {
    const auto in = [](double x, double lo) { return x > lo && x < lo + 2; };
    return (in(c.x(), 9) && in(c.y(), 9)) || (in(c.x(), 11) && in(c.y(), 11));
  });
  ASSERT_FALSE(analyze_topology(soup).manifold);
  RepairParams params;
  params.max_hole = 1.0;
  const RepairResult r = repair(soup, params);
  ASSERT_EQ(r.holes.size(), 3u);
  ASSERT_EQ(r.filled_holes, 2u);
  for (const RepairHole& h : r.holes)
    if (h.filled) {
      EXPECT_EQ(h.rim_vertices, 8u);
      EXPECT_NEAR(h.patch_area, 4.0, 1e-12 * 4);
    }
  EXPECT_EQ(r.split_vertices, 0u);
  for (const Vec3& p : soup.points) EXPECT_EQ(p.z(), 0.0);
  const Topology t = analyze_topology(soup);
  EXPECT_TRUE(t.manifold && t.oriented);
  EXPECT_EQ(t.boundary_loops, 1u);
}

TEST(RepairHoles, ASphereWithoutItsCapIsClosedNearTheSphere) {
  TriangleSoup soup = sphere_without_cap();
  const std::size_t kept_points = soup.points.size();
  RepairParams params;
  params.max_hole = 2.0;
  const RepairResult r = repair(soup, params);
  ASSERT_EQ(r.holes.size(), 1u);
  ASSERT_TRUE(r.holes[0].filled) << r.holes[0].left_open << ", rim " << r.holes[0].rim_length;
  const Topology t = analyze_topology(soup);
  EXPECT_TRUE(t.closed && t.manifold && t.oriented);
  EXPECT_GT(signed_volume(soup), 0);
  // The cap rises 0.3 above the rim's plane; the faired patch follows it within a tenth of that.
  EXPECT_GT(r.holes[0].plane_distance, 0.2);
  for (std::size_t v = kept_points; v < soup.points.size(); ++v) EXPECT_NEAR(soup.points[v].norm(), 1.0, 0.03) << v;
}

TEST(RepairHoles, ALoopLongerThanMaxHoleIsLeftOpenAndReported) {
  TriangleSoup soup = sphere_without_cap();
  const std::size_t faces = soup.triangles.size();
  const RepairResult r = repair(soup);  // 0.5 x the diagonal
  ASSERT_EQ(r.holes.size(), 1u);
  EXPECT_FALSE(r.holes[0].filled);
  EXPECT_NE(r.holes[0].left_open.find("max_hole"), std::string::npos);
  EXPECT_EQ(r.open_holes, 1u);
  EXPECT_EQ(soup.triangles.size(), faces);
}

TEST(RepairHoles, TheScaleDoesNotChangeTheCounts) {
  RepairParams params;
  params.max_hole = 2.0;
  for (const auto& make : {grid_with_square_hole, sphere_without_cap}) {
    TriangleSoup unit = make();
    const RepairResult reference = repair(unit, params);
    for (const double s : {1e-3, 1e3}) {
      TriangleSoup soup = scaled(make(), s);
      const RepairResult r = repair(soup, params);
      ASSERT_EQ(r.holes.size(), reference.holes.size()) << s;
      EXPECT_EQ(soup.triangles.size(), unit.triangles.size()) << s;
      for (std::size_t h = 0; h < r.holes.size(); ++h) {
        EXPECT_EQ(r.holes[h].filled, reference.holes[h].filled) << s;
        EXPECT_EQ(r.holes[h].patch_faces, reference.holes[h].patch_faces) << s;
        EXPECT_NEAR(r.holes[h].patch_area, reference.holes[h].patch_area * s * s, 1e-9 * s * s) << s;
      }
    }
  }
}

}  // namespace
}  // namespace meshprep
