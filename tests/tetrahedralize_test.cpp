#include "meshprep/fem/extrude.h"
#include "meshprep/fem/readiness.h"
#include "meshprep/fem/size_conformity.h"
#include "meshprep/fem/tet_quality.h"
#include "meshprep/fem/tetrahedralize.h"

#include "test_meshes.h"

#include <gtest/gtest.h>

#include <cmath>
#include <utility>
#include <vector>

using namespace meshprep;

namespace {

double surface_volume(const TriangleSoup& s) {
  double six_v = 0;
  for (const Triangle& t : s.triangles) six_v += s.points[t[0]].dot(s.points[t[1]].cross(s.points[t[2]]));
  return six_v / 6.0;
}

void expect_positive_and_outward(const TetMesh& m) {
  for (std::size_t t = 0; t < m.tets.size(); ++t) ASSERT_GT(tet_volume(m, t), 0.0) << "tet " << t;
  // Outward boundary: the divergence theorem over the boundary gives the tets' volume.
  double six_v = 0;
  for (const Triangle& f : m.boundary_faces) six_v += m.points[f[0]].dot(m.points[f[1]].cross(m.points[f[2]]));
  double volume = 0;
  for (std::size_t t = 0; t < m.tets.size(); ++t) volume += tet_volume(m, t);
  EXPECT_NEAR(six_v / 6.0, volume, 1e-9 * volume);
}

}  // namespace

TEST(Tetrahedralize, CubeVolumeIsExactAndBoundsHold) {
  TetParams p;
  p.radius_edge = 1.414;
  p.min_dihedral_deg = 10;
  p.max_volume = 0.001;
  const TetMesh m = tetrahedralize_plc(plc_from_surface(test::cube(1.0)), p);
  const TetQualityReport q = analyze_tet_quality(m);
  EXPECT_NEAR(q.volume, 1.0, 1e-9);  // the tets fill the cube exactly: volume to round-off
  EXPECT_GT(q.tetrahedra, 1000u);    // max volume 1e-3 forces at least 1000 tets
  EXPECT_LE(q.radius_edge_ratio.max, 1.414 + 1e-6);
  EXPECT_GE(q.min_dihedral_deg.min, 10.0 - 1e-6);
  EXPECT_EQ(q.inverted_tets, 0u);
  expect_positive_and_outward(m);
  for (int tag : m.boundary_tags) EXPECT_EQ(tag, 1);
}

TEST(Tetrahedralize, SphereKeepsItsSurfaceVolume) {
  const TriangleSoup sphere = test::icosphere(3);
  TetParams p;
  p.keep_surface = true;  // -Y: the boundary is exactly the input triangles, so the volumes agree
  const TetMesh m = tetrahedralize_plc(plc_from_surface(sphere), p);
  const TetQualityReport q = analyze_tet_quality(m);
  EXPECT_NEAR(q.volume, surface_volume(sphere), 1e-9 * surface_volume(sphere));
  EXPECT_EQ(m.boundary_faces.size(), sphere.triangles.size());
  expect_positive_and_outward(m);
}

// A cube inside a cube, facing inwards (repair's keep_cavities): the wall of a void, which TetGen
// leaves empty through the hole point plc_from_surface puts just inside it.
TEST(Tetrahedralize, AnInwardInnerCubeIsAVoid) {
  TriangleSoup inner = test::translated(test::cube(1.0), {1, 1, 1});
  for (Triangle& t : inner.triangles) std::swap(t[1], t[2]);
  const TriangleSoup hollow = test::merged(test::cube(4.0), inner);
  const SurfacePlc plc = plc_from_surface(hollow);
  ASSERT_EQ(plc.holes.size(), 1u);
  EXPECT_TRUE((plc.holes[0].array() > 1).all() && (plc.holes[0].array() < 2).all()) << plc.holes[0].transpose();
  const TetMesh m = tetrahedralize_plc(plc, TetParams{});
  EXPECT_NEAR(analyze_tet_quality(m).volume, 64 - 1, 1e-9 * 63);
  expect_positive_and_outward(m);
  EXPECT_TRUE(plc_from_surface(test::cube(4.0)).holes.empty());
}

TEST(Tetrahedralize, SwitchesFollowTheParameters) {
  TetParams p;
  p.radius_edge = 1.2;
  p.min_dihedral_deg = 15;
  p.max_volume_relative = 0.01;
  p.keep_surface = true;
  EXPECT_EQ(tetgen_switches(p, 2.0), "pzQq1.2/15a0.02Y");
  EXPECT_EQ(tetgen_switches(TetParams{}, 1.0), "pzQq1.414");
}

// Every parameter out of its range is refused before TetGen runs: a NaN bound would drop the
// switch silently, a radius-edge bound under 1 refines for ever (issue 30).
TEST(Tetrahedralize, ParametersOutOfRangeAreRefused) {
  const double nan = std::nan(""), inf = INFINITY;
  const std::vector<std::pair<double TetParams::*, std::vector<double>>> refused = {
      {&TetParams::radius_edge, {nan, inf, -1, 0.5, 0.999, 101}},
      {&TetParams::min_dihedral_deg, {nan, inf, -1, 31}},
      {&TetParams::max_volume, {nan, inf, -1}},
      {&TetParams::max_volume_relative, {nan, inf, -0.1, 1.5}}};
  for (const auto& [field, values] : refused)
    for (const double value : values) {
      TetParams p;
      p.*field = value;
      EXPECT_THROW(check_tet_params(p), InvalidInput) << value;
      EXPECT_THROW(tetgen_switches(p, 1.0), InvalidInput) << value;
    }
  TetParams unrefined;
  unrefined.radius_edge = 0;
  EXPECT_NO_THROW(check_tet_params(unrefined));
  unrefined.radius_edge = 1;
  EXPECT_NO_THROW(check_tet_params(unrefined));
}

TEST(Tetrahedralize, OpenSurfaceGivesNoTetsError) {
  TriangleSoup open = test::cube();
  open.triangles.pop_back();
  try {
    tetrahedralize_plc(plc_from_surface(open), TetParams{});
    FAIL() << "expected a TetgenError";
  } catch (const TetgenError& e) {
    EXPECT_TRUE(e.code() == 0 || e.code() == 10) << e.what();
  }
}

TEST(Tetrahedralize, ATetgenCrashIsAnErrorNotTheEndOfTheCaller) {
  // Debian's TetGen 1.5 segfaults on two interpenetrating cubes (the readiness check normally
  // stops them first); the forked child takes the crash and the caller gets a TetgenError.
  const TriangleSoup a = test::cube();
  const TriangleSoup both = test::merged(a, test::translated(a, {0.5, 0.25, 0.3}));
  try {
    tetrahedralize_plc(plc_from_surface(both), TetParams{});
    FAIL() << "expected a TetgenError";
  } catch (const TetgenError& e) {
    const std::string message = e.what();
    EXPECT_TRUE(e.code() == 3 || e.code() == -1) << message;
    EXPECT_TRUE(message.find("self-intersecting") != std::string::npos || message.find("crashed") != std::string::npos)
        << message;
  }
}

TEST(Readiness, CleanClosedSurfaceIsReady) {
  EXPECT_TRUE(check_fem_readiness(test::icosphere(2)).ready());
  EXPECT_TRUE(check_fem_readiness(test::torus(16, 8)).ready());
}

TEST(Readiness, OpenBoxNamesItsBorderFaces) {
  TriangleSoup box = test::cube();
  box.triangles.erase(box.triangles.begin() + 2, box.triangles.begin() + 4);  // remove the top
  const Readiness r = check_fem_readiness(box);
  ASSERT_FALSE(r.ready());
  EXPECT_EQ(r.problems[0].check, "closed");
  EXPECT_EQ(r.problems[0].count, 4u);  // the square hole's four edges
  EXPECT_FALSE(r.problems[0].faces.empty());
  EXPECT_NE(r.problems[0].hint.find("extrude"), std::string::npos);
}

TEST(Readiness, IntersectingBoxesAreNamed) {
  const TriangleSoup a = test::cube();
  const Readiness r = check_fem_readiness(test::merged(a, test::translated(a, {0.5, 0.25, 0.3})));
  ASSERT_FALSE(r.ready());
  EXPECT_EQ(r.problems.back().check, "self_intersections");
  EXPECT_GT(r.problems.back().count, 0u);
  const TriangleSoup diagnosis = diagnosis_mesh(test::merged(a, test::translated(a, {0.5, 0.25, 0.3})), r);
  EXPECT_EQ(diagnosis.triangles.size(), r.problems.back().faces.size());
}

// The repair's own search stands in for the check's only on the very surface it searched: a
// caller's word is taken, but not across a weld, which changes what touches.
TEST(Readiness, AKnownFreeSurfaceSkipsTheSearchUnlessWelded) {
  const TriangleSoup a = test::cube();
  const TriangleSoup crossing = test::merged(a, test::translated(a, {0.5, 0.25, 0.3}));
  EXPECT_TRUE(check_fem_readiness(crossing, true).ready());  // taken on trust: what the flag means
  TriangleSoup split = crossing;
  split.points.push_back(split.points[split.triangles[0][0]]);  // a copy of a used vertex, used instead
  split.triangles[0][0] = static_cast<std::uint32_t>(split.points.size() - 1);
  const Readiness r = check_fem_readiness(split, true);
  ASSERT_FALSE(r.ready());
  EXPECT_EQ(r.problems.back().check, "self_intersections");
}

TEST(Readiness, NonManifoldEdgeAndDuplicateFaces) {
  TriangleSoup fin = test::cube();
  fin.points.emplace_back(0.5, 0.5, -1.0);
  fin.triangles.push_back({0, 1, static_cast<std::uint32_t>(fin.points.size() - 1)});  // a fin on edge 0-1
  const Readiness r = check_fem_readiness(fin);
  ASSERT_FALSE(r.ready());
  bool manifold_named = false;
  for (const auto& p : r.problems) manifold_named |= p.check == "manifold" && p.count >= 1;
  EXPECT_TRUE(manifold_named);

  TriangleSoup twice = test::cube();
  twice.triangles.push_back(twice.triangles[5]);
  const Readiness d = check_fem_readiness(twice);
  bool duplicate_named = false;
  for (const auto& p : d.problems)
    if (p.check == "duplicate_faces") {
      duplicate_named = true;
      EXPECT_EQ(p.faces, std::vector<std::size_t>{12});
    }
  EXPECT_TRUE(duplicate_named);
}

// Every face corner its own vertex, as VTK writes a surface after its normals filter.
TriangleSoup split_vertices(const TriangleSoup& soup) {
  TriangleSoup split;
  for (const Triangle& t : soup.triangles) {
    Triangle own;
    for (int k = 0; k < 3; ++k) {
      own[k] = static_cast<std::uint32_t>(split.points.size());
      split.points.push_back(soup.points[t[k]]);
    }
    split.triangles.push_back(own);
  }
  return split;
}

TEST(Readiness, SplitVerticesAreOneProblemAndTheRestIsCheckedWelded) {
  const TriangleSoup cube = test::cube();
  const Readiness r = check_fem_readiness(split_vertices(cube));
  ASSERT_EQ(r.problems.size(), 1u) << r.problems[1].what;  // not "open" nor "intersecting"
  EXPECT_EQ(r.problems[0].check, "welded");
  EXPECT_EQ(r.problems[0].count, 3 * cube.triangles.size() - cube.points.size());
  EXPECT_EQ(r.problems[0].faces.size(), cube.triangles.size());
  EXPECT_EQ(r.isolated_vertices, 0u);

  // Real intersections are still counted, as on the welded surface.
  const TriangleSoup boxes = test::merged(cube, test::translated(cube, {0.5, 0.25, 0.3}));
  const Readiness welded = check_fem_readiness(boxes), split = check_fem_readiness(split_vertices(boxes));
  ASSERT_EQ(split.problems.size(), welded.problems.size() + 1);
  EXPECT_EQ(split.problems.back().check, "self_intersections");
  EXPECT_EQ(split.problems.back().count, welded.problems.back().count);
}

TEST(Readiness, InwardOrientationIsFlippedNotRefused) {
  TriangleSoup s = test::cube();
  for (auto& t : s.triangles) std::swap(t[1], t[2]);
  const Readiness r = check_fem_readiness(s);
  EXPECT_TRUE(r.ready());
  EXPECT_TRUE(r.inward_oriented);
}

TEST(Extrude, GridBecomesABlockOfTheRightVolume) {
  // Unit-spaced 4 x 4 grid at z = 0 extruded 2 below: a 4 x 4 x 2 block.
  const SurfacePlc plc = extrude_to_block(test::grid(4), 2.0);
  const TetMesh m = tetrahedralize_plc(plc, TetParams{});
  EXPECT_NEAR(analyze_tet_quality(m).volume, 32.0, 1e-9);
  int tags[4] = {0, 0, 0, 0};
  double area[4] = {0, 0, 0, 0};
  for (std::size_t f = 0; f < m.boundary_faces.size(); ++f) {
    const auto& t = m.boundary_faces[f];
    ++tags[m.boundary_tags[f]];
    area[m.boundary_tags[f]] +=
        0.5 * (m.points[t[1]] - m.points[t[0]]).cross(m.points[t[2]] - m.points[t[0]]).norm();
  }
  EXPECT_NEAR(area[kTopTag], 16.0, 1e-9);
  EXPECT_NEAR(area[kSideTag], 4 * 4 * 2.0, 1e-9);
  EXPECT_NEAR(area[kBaseTag], 16.0, 1e-9);
  expect_positive_and_outward(m);
}

TEST(Extrude, RefusesWhatIsNotAHeightField) {
  EXPECT_THROW(extrude_to_block(test::cube(), 1.0), InvalidInput);  // closed
  TriangleSoup folded = test::grid(3);
  std::swap(folded.triangles[4][1], folded.triangles[4][2]);  // one face upside down
  EXPECT_THROW(extrude_to_block(folded, 1.0), InvalidInput);
  EXPECT_THROW(extrude_to_block(test::grid(3), 0.0), InvalidInput);
}

namespace meshprep {
namespace {

// TetGen's -m with sizes kTetgenSizePerLength x h: it splits while half the longest edge at a
// vertex exceeds that vertex's size, so no edge ends longer than 2 x share x h (boundary edges
// included: without -Y they are split too); and the edges centre on h (the band of issue 49).
TEST(Tetrahedralize, ASizeFieldSetsTheEdgeLengths) {
  const double h = 0.1;
  TetParams params;
  params.size_field = std::make_shared<SizeField>(std::vector<SizeDemand>{}, h, 1.3);
  const SurfacePlc plc = plc_from_surface(test::cube(1.0));
  const TetMesh tets = tetrahedralize_plc(plc, params);
  EXPECT_NE(tetgen_switches(params, 1.0).find('m'), std::string::npos);
  const SizeConformity c = measure_size_conformity(tets, *params.size_field);
  EXPECT_LE(c.ratio_p99 * h, 2 * kTetgenSizePerLength * h * (1 + 1e-9));
  EXPECT_GE(c.within_band, 0.9) << "median " << c.ratio_median << " p05 " << c.ratio_p05 << " p95 " << c.ratio_p95;
  // Without a field TetGen keeps the cube's few points: the field is what made the tets.
  EXPECT_LT(tetrahedralize_plc(plc, TetParams()).tets.size() * 50, tets.tets.size());
}

// A field twice as fine near one corner: the tets there are smaller, and their size jumps
// between neighbours no more than the grading allows, give or take TetGen's own spread.
TEST(Tetrahedralize, TetsFollowAGradedField) {
  TetParams params;
  params.size_field = std::make_shared<SizeField>(std::vector<SizeDemand>{{Vec3(0, 0, 0), 0.05}}, 0.2, 1.3);
  const TetMesh tets = tetrahedralize_plc(plc_from_surface(test::cube(1.0)), params);
  const SizeConformity c = measure_size_conformity(tets, *params.size_field);
  EXPECT_GE(c.within_band, 0.8) << "median " << c.ratio_median << " p05 " << c.ratio_p05 << " p95 " << c.ratio_p95;
  EXPECT_LE(c.grading_excess_p99, 1.5);
}

}  // namespace
}  // namespace meshprep
