// The repair's envelope route (repair.h, step 7): a soup's solid rebuilt on a grid from its
// winding number, checked for validity, for the distance the maths allows, for scale, and for when
// the automatic route takes it.
#include "meshprep/core/errors.h"
#include "meshprep/preprocess/compose/repair_solid.h"
#include "meshprep/preprocess/enhance/enhance.h"
#include "meshprep/preprocess/repair/repair.h"
#include "meshprep/quality/self_intersections.h"
#include "meshprep/quality/surface_distance.h"
#include "meshprep/quality/topology.h"
#include "meshprep/quality/triangle_metrics.h"

#include "test_meshes.h"

#include <gtest/gtest.h>

#include <cmath>

namespace meshprep {
namespace {

// A unit cube and a bar through it, sticking out of one side: their union is 1.125.
TriangleSoup cube_and_bar() {
  return test::merged(test::box({0, 0, 0}, {1, 1, 1}), test::box({0.5, 0.25, 0.25}, {1.5, 0.75, 0.75}));
}
constexpr double kUnionVolume = 1 + 0.5 * 0.5 * 0.5;
constexpr double kUnionArea = 6 + 4 * 0.5 * 0.5;  // the cube's, the bar's outer sides and end, less its hole in the cube

RepairParams envelope_route() {
  RepairParams params;
  params.route = RepairRoute::envelope;
  params.envelope_cells = 64;
  params.fidelity_bound = EnhanceParams::kLargestAutoDeviation;
  return params;
}

TEST(RepairEnvelope, OverlappingBoxesBecomeOneValidSolidWithinTheCellBound) {
  const TriangleSoup input = cube_and_bar();
  TriangleSoup soup = input;
  const RepairResult r = repair(soup, envelope_route());
  EXPECT_EQ(r.route, "envelope");
  ASSERT_TRUE(r.envelope.has_value());
  const Topology t = analyze_topology(soup);
  EXPECT_TRUE(t.closed);
  EXPECT_TRUE(t.manifold);
  EXPECT_TRUE(t.oriented);
  EXPECT_EQ(t.components, 1u);
  EXPECT_EQ(find_self_intersections(soup).count, 0u);
  // Each face of the grid's surface lies in a grid tetrahedron whose corners lie on both sides of
  // the union's surface: no point of it is farther from that surface than the tetrahedron's
  // longest edge, sqrt 3 cells.
  const double cell = 1.5 / 64;
  EXPECT_NEAR(r.envelope->cell, cell, 1e-12);
  const double diagonal = bbox_diagonal(input);
  EXPECT_LE(r.envelope->distance_max, std::sqrt(3.0) * cell / diagonal);
  EXPECT_GT(r.envelope->distance_max, 0);  // the box's edges are chamfered
  EXPECT_LE(r.envelope->distance_rms, r.envelope->distance_max);
  // So the solid differs from the union by at most its area times that.
  EXPECT_NEAR(signed_volume(soup), kUnionVolume, kUnionArea * std::sqrt(3.0) * cell);
  // The report's places are the samples over the bound, the farthest first.
  EXPECT_EQ(r.envelope->samples_over_bound > 0, !r.envelope->places.empty());
  for (std::size_t i = 1; i < r.envelope->places.size(); ++i)
    EXPECT_LE(r.envelope->places[i].distance, r.envelope->places[i - 1].distance);
  for (const RepairPlace& place : r.envelope->places) EXPECT_GT(place.distance, r.envelope->bound);
}

TEST(RepairEnvelope, TheSolidDoesNotDependOnTheUnits) {
  TriangleSoup metres = cube_and_bar(), millimetres = cube_and_bar();
  for (Vec3& p : millimetres.points) p *= 1000;
  const RepairResult m = repair(metres, envelope_route());
  const RepairResult mm = repair(millimetres, envelope_route());
  ASSERT_EQ(metres.triangles.size(), millimetres.triangles.size());
  EXPECT_EQ(m.envelope->relabelled_specks, mm.envelope->relabelled_specks);
  EXPECT_NEAR(mm.envelope->distance_max, m.envelope->distance_max, 1e-9);
  EXPECT_NEAR(mm.envelope->distance_rms, m.envelope->distance_rms, 1e-9);
  EXPECT_EQ(mm.envelope->places.size(), m.envelope->places.size());
}

TEST(RepairEnvelope, TheGridSurfaceIsSimplifiedWithinTheBoundAndStaysValid) {
  const TriangleSoup input = cube_and_bar();
  TriangleSoup soup = input;
  RepairParams params = envelope_route();
  const RepairResult r = repair_solid(soup, params);
  ASSERT_TRUE(r.envelope.has_value());
  EXPECT_EQ(r.envelope->reduced_faces, soup.triangles.size());
  EXPECT_LT(r.envelope->reduced_faces, r.envelope->faces / 4);
  const Topology t = analyze_topology(soup);
  EXPECT_TRUE(t.closed && t.manifold && t.oriented);
  EXPECT_EQ(find_self_intersections(soup).count, 0u);
  // The grid's surface within sqrt 3 cells; the collapses' estimate allows a quarter of the bound
  // more, and an estimate may be exceeded: the whole bound is the margin.
  DistanceParams sampling;
  sampling.samples = 20000;
  const double diagonal = bbox_diagonal(input);
  EXPECT_LE(surface_distance(soup, input, sampling).a_to_b.max,
            (std::sqrt(3.0) * 1.5 / 64 / diagonal + r.envelope->bound) * diagonal);
}

TEST(RepairEnvelope, ASphereComesBackWithinTheCellBoundAndEnclosesItsVolume) {
  // Curved: the chamfer is the chord's sagitta, far under a cell.
  const TriangleSoup input = test::icosphere(4);
  TriangleSoup soup = input;
  const RepairResult r = repair(soup, envelope_route());
  const double cell = 2.0 / 64;
  EXPECT_LE(r.envelope->distance_max, std::sqrt(3.0) * cell / bbox_diagonal(input));
  EXPECT_NEAR(signed_volume(soup), signed_volume(input), 4 * 3.14159265358979 * std::sqrt(3.0) * cell);
  const Topology t = analyze_topology(soup);
  EXPECT_TRUE(t.closed && t.manifold && t.oriented);
  EXPECT_EQ(t.genus, 0);
}

TEST(RepairEnvelope, TheAutomaticRouteKeepsTheExactCutWhenNothingIsLeftCrossing) {
  TriangleSoup soup = cube_and_bar();
  const RepairResult r = repair(soup);
  EXPECT_EQ(r.route, "exact");
  EXPECT_FALSE(r.envelope.has_value());
  EXPECT_NEAR(signed_volume(soup), kUnionVolume, 1e-12);
}

TEST(RepairEnvelope, TheExactRouteNeverRebuilds) {
  TriangleSoup soup = cube_and_bar();
  RepairParams params;
  params.route = RepairRoute::exact;
  EXPECT_EQ(repair(soup, params).route, "exact");
}

TEST(RepairEnvelope, TheAutomaticRouteRebuildsWhenTheExactCutIsPastTheTimeLimit) {
  // A limit already passed when the cut asks the clock first (before its first pass): the
  // envelope takes over from the surface as it was before the cut, and says why. The exact route
  // asked for has no limit of its own: it cuts.
  TriangleSoup soup = cube_and_bar();
  RepairParams params = envelope_route();
  params.route = RepairRoute::automatic;
  params.time_limit_seconds = 1e-9;
  const RepairResult r = repair(soup, params);
  EXPECT_EQ(r.route, "envelope");
  ASSERT_TRUE(r.envelope.has_value());
  EXPECT_NE(r.envelope->reason.find("exact cut was not done"), std::string::npos) << r.envelope->reason;
  EXPECT_EQ(r.cut_faces, 0u);
  const Topology topology = analyze_topology(soup);
  EXPECT_TRUE(topology.closed && topology.manifold);
  EXPECT_EQ(find_self_intersections(soup).count, 0u);
  EXPECT_NEAR(signed_volume(soup), kUnionVolume, kUnionArea * std::sqrt(3.0) * r.envelope->cell);

  TriangleSoup exact = cube_and_bar();
  params.route = RepairRoute::exact;
  EXPECT_EQ(repair(exact, params).route, "exact");
  EXPECT_NEAR(signed_volume(exact), kUnionVolume, 1e-12);

  params.time_limit_seconds = -2;
  EXPECT_THROW(repair(exact, params), InvalidInput);
}

TEST(RepairEnvelope, EachFaceTakesThePatchOfTheNearestInputFace) {
  TriangleSoup input = test::box({0, 0, 0}, {1, 1, 1});
  input.patches.assign(input.triangles.size(), 1);
  input.patch_names = {{1, "sides"}, {2, "top"}};
  for (std::size_t f = 0; f < input.triangles.size(); ++f) {
    bool top = true;
    for (const auto v : input.triangles[f]) top = top && input.points[v].z() == 1;
    if (top) input.patches[f] = 2;
  }
  TriangleSoup soup = input;
  repair(soup, envelope_route());
  ASSERT_EQ(soup.patches.size(), soup.triangles.size());
  EXPECT_EQ(soup.patch_names, input.patch_names);
  std::size_t top_faces = 0;
  for (std::size_t f = 0; f < soup.triangles.size(); ++f) {
    const Triangle& t = soup.triangles[f];
    const Vec3 centre = (soup.points[t[0]] + soup.points[t[1]] + soup.points[t[2]]) / 3;
    // Faces well inside the top (away from the chamfered edges) are the top's.
    if (centre.z() > 1 - 1e-9 && centre.x() > 0.1 && centre.x() < 0.9 && centre.y() > 0.1 && centre.y() < 0.9) {
      EXPECT_EQ(soup.patches[f], 2);
      ++top_faces;
    }
  }
  EXPECT_GT(top_faces, 0u);
}

TEST(RepairEnvelope, ASoupEnclosingNothingIsRefusedAsBadInput) {
  // A flat square: its winding number is under one half at every grid point (found by the fuzzer).
  TriangleSoup square;
  square.points = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
  square.triangles = {{0, 1, 2}, {0, 2, 3}};
  RepairParams params = envelope_route();
  params.envelope_cells = 16;
  EXPECT_THROW(repair(square, params), InvalidInput);
}

TEST(RepairEnvelope, AGridTooCoarseIsRefused) {
  TriangleSoup soup = cube_and_bar();
  RepairParams params = envelope_route();
  params.envelope_cells = 4;
  EXPECT_THROW(repair(soup, params), InvalidInput);
}

}  // namespace
}  // namespace meshprep
