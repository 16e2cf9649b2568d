// The repair's non-manifold split and hole filling (repair.h, steps 3 and 5) on hand-made cases:
// bow-tie vertices, two cubes on one edge, a square hole in a plane, a sphere without its cap, and
// which loops the default fills: sheets (flat, wavy, bowls) against solids missing a part.
#include "meshprep/preprocess/repair/repair.h"
#include "meshprep/quality/self_intersections.h"
#include "repair/sheet_outlines.h"
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

// The unit icosphere's faces within `degrees` of its north pole: a bowl up to 90, then a sphere
// missing a cap of 180 - degrees around its south pole.
TriangleSoup spherical_cap(double degrees) {
  const double lowest = std::cos(degrees * M_PI / 180);
  return without(test::icosphere(4), [&](const Vec3& c) { return c.normalized().z() < lowest; });
}

// A 24 x 24 grid as the terrain z = 0.3 x + 3 sin(x / 3) cos(y / 4): tilted 17 degrees, slopes
// up to 53 degrees.
TriangleSoup wavy_terrain() {
  TriangleSoup soup = test::grid(24);
  for (Vec3& p : soup.points) p.z() = 0.3 * p.x() + 3 * std::sin(p.x() / 3) * std::cos(p.y() / 4);
  return soup;
}

// The same without its 6 x 6 middle cells.
TriangleSoup wavy_terrain_with_square_hole() {
  return without(wavy_terrain(), [](const Vec3& c) { return c.x() > 9 && c.x() < 15 && c.y() > 9 && c.y() < 15; });
}

// The side of a cylinder of radius 1 and height 1: two loops of 32 corners, 2 pi each (4.4 x the
// diagonal).
TriangleSoup open_tube() {
  return without(test::cylinder_with_fan_caps(32), [](const Vec3& c) { return c.z() == 0 || c.z() == 1; });
}

// The one-sidedness of the component of the soup's first face (sheet_outlines.h).
double one_sidedness(const TriangleSoup& soup) {
  return detail::sheet_outlines(soup, {detail::LoopBorder{0, Vec3::Zero(), true}})[0].one_sidedness;
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
// which leaves the fin a lone face (no edge shared), and it goes: it encloses nothing and a patch
// would only repeat it. The cube comes out as it was.
TEST(RepairSplit, AFinOnACubesEdgeIsDroppedAndTheCubeStaysClosed) {
  TriangleSoup soup = test::cube();
  soup.points.push_back({0.5, -1, 0.5});
  soup.triangles.push_back({0, 1, static_cast<std::uint32_t>(soup.points.size() - 1)});
  RepairParams params;
  params.max_hole = std::numeric_limits<double>::infinity();
  const RepairResult r = repair(soup, params);
  EXPECT_EQ(r.split_edges, 1u);
  EXPECT_EQ(r.dropped_lone_faces, 1u);
  EXPECT_TRUE(r.holes.empty());
  EXPECT_EQ(soup.triangles.size(), 12u);
  EXPECT_EQ(soup.points.size(), 8u);  // the edge's copies the split gave the fin went with it
  const Topology t = analyze_topology(soup);
  EXPECT_TRUE(t.closed && t.manifold && t.oriented);
  EXPECT_EQ(t.components, 1u);
  EXPECT_NEAR(signed_volume(soup), 1.0, 1e-12);
}

// A lone face that is all there is stays: a one-face sheet.
TEST(RepairSplit, ALoneFaceThatIsAllThereIsStays) {
  TriangleSoup soup;
  soup.points = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  soup.triangles = {{0, 1, 2}};
  const RepairResult r = repair(soup);
  EXPECT_EQ(r.dropped_lone_faces, 0u);
  EXPECT_EQ(soup.triangles.size(), 1u);
}

// T-junctions: one face on a cube's edge refined at k points of the edge (a fan from its opposite
// vertex), its neighbour across the edge not. The neighbour is split at each point, the seam is
// closed and the cube's volume exact (no point moves).
TEST(RepairTJunctions, AFaceRefinedOnOneSideOfAnEdgeIsMatchedOnTheOther) {
  for (const int k : {1, 2, 3}) {
    TriangleSoup soup = test::cube(2);
    const auto on_edge = std::find_if(soup.triangles.begin(), soup.triangles.end(), [](const Triangle& t) {
      return std::count(t.begin(), t.end(), 0u) + std::count(t.begin(), t.end(), 1u) == 2;
    });
    ASSERT_NE(on_edge, soup.triangles.end());
    // The face in the order from -> to -> opposite, its edge from 0 to 1 or from 1 to 0.
    Triangle t = *on_edge;
    while (!((t[0] == 0 && t[1] == 1) || (t[0] == 1 && t[1] == 0))) t = {t[1], t[2], t[0]};
    soup.triangles.erase(on_edge);
    std::uint32_t previous = t[0];
    for (int i = 1; i <= k; ++i) {
      soup.points.push_back(soup.points[t[0]] + (soup.points[t[1]] - soup.points[t[0]]) * (double(i) / (k + 1)));
      const auto m = static_cast<std::uint32_t>(soup.points.size() - 1);
      soup.triangles.push_back({previous, m, t[2]});
      previous = m;
    }
    soup.triangles.push_back({previous, t[1], t[2]});
    ASSERT_FALSE(analyze_topology(soup).closed);
    const RepairResult r = repair(soup);
    EXPECT_EQ(r.t_junction_splits, static_cast<std::size_t>(k)) << k;
    EXPECT_EQ(r.filled_holes + r.open_holes, 0u) << k;
    EXPECT_EQ(soup.triangles.size(), 12u + 2 * k) << k;
    const Topology topology = analyze_topology(soup);
    EXPECT_TRUE(topology.closed && topology.manifold && topology.oriented) << k;
    EXPECT_EQ(find_self_intersections(soup).count, 0u) << k;
    EXPECT_NEAR(signed_volume(soup), 8.0, 1e-12) << k;
  }
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

// By default: the rim is 1.8 x the diagonal, but the sphere wraps 134 degrees around its pole
// (one-sidedness 0.34), a solid missing a part.
TEST(RepairHoles, ASphereWithoutItsCapIsClosedNearTheSphere) {
  TriangleSoup soup = sphere_without_cap();
  const std::size_t kept_points = soup.points.size();
  const RepairResult r = repair(soup);
  ASSERT_EQ(r.holes.size(), 1u);
  ASSERT_TRUE(r.holes[0].filled) << r.holes[0].left_open << ", rim " << r.holes[0].rim_length;
  const Topology t = analyze_topology(soup);
  EXPECT_TRUE(t.closed && t.manifold && t.oriented);
  EXPECT_GT(signed_volume(soup), 0);
  // The cap rises 0.3 above the rim's plane; the faired patch follows it within a tenth of that.
  EXPECT_GT(r.holes[0].plane_distance, 0.2);
  for (std::size_t v = kept_points; v < soup.points.size(); ++v) EXPECT_NEAR(soup.points[v].norm(), 1.0, 0.03) << v;
}

// A face on the rim turned over: orientation turns it back, and the hole's walk then needs its rim
// edge the right way round (the repair sorts the face edges again after any flip).
TEST(RepairHoles, AFaceTurnedOverOnTheRimIsTurnedBackBeforeTheHoleIsFilled) {
  TriangleSoup soup = sphere_without_cap();
  const std::size_t on_rim = analyze_topology(soup).border_edge_faces.back();
  ASSERT_NE(on_rim, 0u);  // the first face leads the orientation
  std::swap(soup.triangles[on_rim][1], soup.triangles[on_rim][2]);
  const RepairResult r = repair(soup);
  EXPECT_EQ(r.flipped_faces, 1u);
  ASSERT_EQ(r.holes.size(), 1u);
  EXPECT_TRUE(r.holes[0].filled) << r.holes[0].left_open;
  const Topology t = analyze_topology(soup);
  EXPECT_TRUE(t.closed && t.manifold && t.oriented);
  EXPECT_GT(signed_volume(soup), 0);
}

TEST(RepairHoles, ALoopLongerThanMaxHoleIsLeftOpenAndReported) {
  TriangleSoup soup = sphere_without_cap();
  const std::size_t faces = soup.triangles.size();
  RepairParams params;
  params.max_hole = 0.5;
  const RepairResult r = repair(soup, params);
  ASSERT_EQ(r.holes.size(), 1u);
  EXPECT_FALSE(r.holes[0].filled);
  EXPECT_NE(r.holes[0].left_open.find("max_hole"), std::string::npos);
  EXPECT_EQ(r.open_holes, 1u);
  EXPECT_EQ(soup.triangles.size(), faces);
}

// By length and by default (the one-sidedness is a ratio of areas).
TEST(RepairHoles, TheScaleDoesNotChangeTheCounts) {
  RepairParams by_length;
  by_length.max_hole = 2.0;
  for (const RepairParams& params : {RepairParams{}, by_length}) {
    for (const auto& make : {grid_with_square_hole, sphere_without_cap, wavy_terrain_with_square_hole}) {
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
}

// 1 for every height field, then sin^2 t / (1 + cos^2 t) for a cap of half angle t past 90
// degrees (sheet_outlines.cpp), to the icosphere's zigzag rim; about 0 for a sphere with a small
// hole, or a tube open at both ends.
TEST(RepairHoles, OneSidednessIsOneForHeightFieldsAndFallsAsACapWrapsTheSphere) {
  EXPECT_NEAR(one_sidedness(test::grid(12)), 1.0, 1e-12);
  EXPECT_NEAR(one_sidedness(wavy_terrain()), 1.0, 1e-12);
  EXPECT_NEAR(one_sidedness(spherical_cap(90)), 1.0, 1e-12);
  for (const double degrees : {110.0, 125.0, 150.0}) {
    const double c = std::cos(degrees * M_PI / 180);
    EXPECT_NEAR(one_sidedness(spherical_cap(degrees)), (1 - c * c) / (1 + c * c), 0.05) << degrees;
  }
  EXPECT_LT(one_sidedness(spherical_cap(175)), 0.01);
  EXPECT_LT(one_sidedness(open_tube()), 1e-9);
}

// A sheet's outline stays open however it is shaped; a hole in the sheet is filled.
TEST(RepairHoles, ByDefaultASheetsOutlineStaysOpenAndItsHolesAreFilled) {
  for (const auto& make : {grid_with_square_hole, wavy_terrain_with_square_hole}) {
    TriangleSoup soup = make();
    const RepairResult r = repair(soup);
    ASSERT_EQ(r.holes.size(), 2u);
    EXPECT_EQ(r.filled_holes, 1u);
    for (const RepairHole& h : r.holes) {
      EXPECT_EQ(h.filled, h.rim_vertices == 24u) << h.rim_vertices;
      if (!h.filled) {
        EXPECT_NE(h.left_open.find("outline of an open sheet"), std::string::npos) << h.left_open;
      }
    }
  }
}

// Bowls up to a hemisphere are height fields: an open box and a hemisphere stay open, and so does
// a cap 10 degrees deeper (one-sidedness 0.94).
TEST(RepairHoles, ByDefaultBowlsStayOpen) {
  const TriangleSoup open_box = without(test::subdivided_cube(4), [](const Vec3& c) { return c.z() == 4; });
  for (const TriangleSoup& bowl : {open_box, spherical_cap(90), spherical_cap(100)}) {
    TriangleSoup soup = bowl;
    const RepairResult r = repair(soup);
    ASSERT_EQ(r.holes.size(), 1u);
    EXPECT_FALSE(r.holes[0].filled);
    EXPECT_EQ(soup.triangles.size(), bowl.triangles.size());
  }
}

// A cap of 120 degrees (one-sidedness 0.6) wraps the sphere past the bowl: a solid missing a part,
// closed; so is the tube, whose two loops no direction sees one side of.
TEST(RepairHoles, ByDefaultASolidsMissingPartIsFilledHoweverLong) {
  for (const TriangleSoup& open : {spherical_cap(120), open_tube()}) {
    TriangleSoup soup = open;
    const RepairResult r = repair(soup);
    EXPECT_EQ(r.open_holes, 0u);
    const Topology t = analyze_topology(soup);
    EXPECT_TRUE(t.closed && t.manifold && t.oriented);
    EXPECT_GT(signed_volume(soup), 0);
  }
}

// Each component is judged alone: the sphere's hole is filled, the flat sheet beside it stays open.
TEST(RepairHoles, ByDefaultEachComponentIsJudgedAlone) {
  TriangleSoup soup = test::merged(sphere_without_cap(), test::translated(test::grid(4), {3, 0, 0}));
  const RepairResult r = repair(soup);
  ASSERT_EQ(r.holes.size(), 2u);
  EXPECT_EQ(r.filled_holes, 1u);
  const Topology t = analyze_topology(soup);
  EXPECT_EQ(t.boundary_loops, 1u);
  EXPECT_EQ(t.components, 2u);
}

}  // namespace
}  // namespace meshprep
