// The repair stage's first steps (repair.h) on hand-made cases: split vertices, near copies, a
// flipped face, an inward cube, duplicate faces; welding never moves a vertex, and the tolerance
// is relative to the mesh's scale.
#include "meshprep/preprocess/repair/repair.h"
#include "meshprep/quality/topology.h"
#include "meshprep/quality/triangle_metrics.h"

#include "test_meshes.h"

#include <gtest/gtest.h>

#include "meshprep/core/errors.h"

#include <algorithm>
#include <string>

namespace meshprep {
namespace {

// Every face corner its own vertex (as VTK writes a surface after vtkPolyDataNormals), each copy
// moved by `jitter` along x.
TriangleSoup split_vertices(const TriangleSoup& soup, double jitter = 0) {
  TriangleSoup split;
  for (const Triangle& t : soup.triangles) {
    const auto first = static_cast<std::uint32_t>(split.points.size());
    for (const std::uint32_t v : t) split.points.push_back(soup.points[v] + Vec3(jitter * (split.points.size() % 3), 0, 0));
    split.triangles.push_back({first, first + 1, first + 2});
  }
  return split;
}

void expect_closed_oriented_outward(const TriangleSoup& soup) {
  const Topology t = analyze_topology(soup);
  EXPECT_TRUE(t.closed);
  EXPECT_TRUE(t.manifold);
  EXPECT_TRUE(t.oriented);
  EXPECT_GT(signed_volume(soup), 0);
}

TEST(Repair, SplitVerticesAreWeldedIntoTheClosedCube) {
  const TriangleSoup cube = test::cube();
  TriangleSoup soup = split_vertices(cube);
  const RepairResult r = repair(soup);
  EXPECT_EQ(r.welded_vertices, 3 * cube.triangles.size() - cube.points.size());
  EXPECT_EQ(soup.points.size(), cube.points.size());
  EXPECT_EQ(soup.triangles.size(), cube.triangles.size());
  EXPECT_EQ(r.flipped_faces + r.inverted_components + r.degenerate_faces + r.duplicate_faces, 0u);
  expect_closed_oriented_outward(soup);
}

// Copies within the tolerance (a fraction of the median edge) weld, at any scale; farther ones
// do not. Welding keeps the lowest index's position: every point out is a point in.
TEST(Repair, NearCopiesWeldWithinTheRelativeToleranceAtAnyScale) {
  for (const double scale : {1.0, 1e-3, 1e4}) {
    TriangleSoup cube = test::cube();
    for (Vec3& p : cube.points) p *= scale;
    TriangleSoup near = split_vertices(cube, 1e-5 * scale);  // the median edge is `scale`
    const TriangleSoup input = near;
    const RepairResult r = repair(near);
    EXPECT_EQ(r.welded_vertices, 28u) << scale;
    EXPECT_NEAR(r.weld_distance, 1e-3 * scale, 1e-7 * scale);  // the jitter moves the median edge by ~2e-5
    for (const Vec3& p : near.points)
      EXPECT_NE(std::find(input.points.begin(), input.points.end(), p), input.points.end());
    expect_closed_oriented_outward(near);

    TriangleSoup far = split_vertices(cube, 1e-2 * scale);
    EXPECT_LT(repair(far).welded_vertices, 28u) << scale;
  }
}

TEST(Repair, AFlippedFaceAgreesWithItsNeighboursAgain) {
  TriangleSoup soup = test::icosphere(2);
  std::swap(soup.triangles[7][1], soup.triangles[7][2]);
  const RepairResult r = repair(soup);
  EXPECT_EQ(r.flipped_faces, 1u);
  EXPECT_EQ(r.inverted_components, 0u);
  expect_closed_oriented_outward(soup);
}

TEST(Repair, AnInwardClosedComponentIsTurnedOutward) {
  TriangleSoup soup = test::merged(test::cube(), test::translated(test::cube(), {3, 0, 0}));
  for (std::size_t f = 12; f < 24; ++f) std::swap(soup.triangles[f][1], soup.triangles[f][2]);  // the second inward
  const RepairResult r = repair(soup);
  EXPECT_EQ(r.components, 2u);
  EXPECT_EQ(r.inverted_components, 1u);
  expect_closed_oriented_outward(soup);
}

TEST(Repair, DuplicateAndCollapsedFacesAreRemoved) {
  TriangleSoup soup = test::cube();
  soup.triangles.push_back(soup.triangles[4]);
  soup.triangles.push_back({soup.triangles[5][0], soup.triangles[5][2], soup.triangles[5][1]});  // reversed copy
  soup.points.push_back(soup.points[0]);  // an exact copy of vertex 0, used by a sliver onto it
  soup.triangles.push_back({0, static_cast<std::uint32_t>(soup.points.size() - 1), 1});
  const RepairResult r = repair(soup);
  EXPECT_EQ(r.duplicate_faces, 2u);
  EXPECT_EQ(r.degenerate_faces, 1u);
  EXPECT_EQ(soup.triangles.size(), 12u);
  expect_closed_oriented_outward(soup);
}

TEST(Repair, ACleanSurfaceIsLeftAsItIs) {
  TriangleSoup soup = test::torus(16, 8);
  const std::size_t faces = soup.triangles.size();
  const RepairResult r = repair(soup);
  EXPECT_EQ(r.welded_vertices + r.degenerate_faces + r.duplicate_faces + r.flipped_faces + r.inverted_components, 0u);
  EXPECT_EQ(soup.triangles.size(), faces);
}

// A valid closed part comes out as it went in, whatever its thickness against the weld distance
// (a fraction of the median edge): a 100 x 100 x 0.05 plate of 12 faces (issue 45: its top and
// bottom were welded, 10 faces removed, the rest extruded as a terrain), at any scale.
TEST(Repair, AThinClosedPlateIsLeftAsItIs) {
  for (const double scale : {1.0, 1e-3, 1e3}) {
    TriangleSoup plate = test::cube();
    for (Vec3& p : plate.points) p = Vec3(100 * p.x(), 100 * p.y(), 0.05 * p.z()) * scale;
    const TriangleSoup input = plate;
    const RepairResult r = repair(plate);
    EXPECT_TRUE(r.input_closed) << scale;
    EXPECT_EQ(r.welded_vertices + r.degenerate_faces + r.duplicate_faces, 0u) << scale;
    EXPECT_EQ(plate.triangles, input.triangles) << scale;
    EXPECT_EQ(plate.points, input.points) << scale;
    EXPECT_NEAR(signed_volume(plate), signed_volume(input), 1e-9 * signed_volume(input)) << scale;
  }
}

// A cube whose top corner is pulled to 1e-9 above the bottom corner under it: closed, manifold,
// without crossings, so valid; it was "repaired" into 204 faces with a 0.018 degree angle.
TEST(Repair, ACubeWithACornerPulledNearItsBottomIsLeftAsItIs) {
  TriangleSoup cube = test::cube();
  cube.points[7] = Vec3(1, 1, 1e-9);  // above corner 3, (1, 1, 0)
  const TriangleSoup input = cube;
  const RepairResult r = repair(cube);
  EXPECT_EQ(r.welded_vertices, 0u);
  EXPECT_EQ(cube.triangles, input.triangles);
  EXPECT_EQ(cube.points, input.points);
}

// A part exported double-sided (every face once per orientation) keeps one copy of each face and
// comes out closed and outward; it was repaired into an empty file with exit 0.
TEST(Repair, ADoubleSidedCubeKeepsOneCopyOfEachFace) {
  TriangleSoup soup = test::cube();
  for (std::size_t f = 0; f < 12; ++f) soup.triangles.push_back({soup.triangles[f][0], soup.triangles[f][2], soup.triangles[f][1]});
  const RepairResult r = repair(soup);
  EXPECT_EQ(r.duplicate_faces, 12u);
  EXPECT_EQ(soup.triangles.size(), 12u);
  expect_closed_oriented_outward(soup);
  EXPECT_NEAR(signed_volume(soup), 1.0, 1e-12);
}

// A soup whose faces all collapse to a point is refused, naming what was removed; no empty
// surface is ever returned. (Faces on three distinct collinear points stay, for the readiness
// check to refuse as faces of zero area.)
TEST(Repair, ASoupOfCollapsedFacesIsRefused) {
  TriangleSoup soup;
  for (std::uint32_t f = 0; f < 50; ++f) {
    const auto first = static_cast<std::uint32_t>(soup.points.size());
    soup.points.insert(soup.points.end(), 3, Vec3(f, 0, 0));
    soup.triangles.push_back({first, first + 1, first + 2});
  }
  try {
    repair(soup);
    FAIL() << "an empty repair was returned";
  } catch (const InvalidInput& e) {
    EXPECT_NE(std::string(e.what()).find("no face is left of 50"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace meshprep
