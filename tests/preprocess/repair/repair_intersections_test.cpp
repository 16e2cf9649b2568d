// The repair's self-intersection step (repair.h, step 6) on hand-made cases: two crossing
// triangles cut exactly; overlapping, flush, face-sharing and nested boxes made one solid; and
// the corpus's self-intersecting scans. Parts touching at a point: repair_topology_test.cpp.
#include "meshprep/core/io.h"
#include "meshprep/preprocess/repair/repair.h"
#include "meshprep/quality/self_intersections.h"
#include "meshprep/quality/surface_distance.h"
#include "meshprep/quality/topology.h"
#include "meshprep/quality/triangle_metrics.h"

#include "repair/cut_face.h"
#include "repair/face_intersection.h"
#include "test_meshes.h"

#include <gtest/gtest.h>

#include <filesystem>

namespace meshprep {
namespace {

TriangleSoup transformed(TriangleSoup soup, const Eigen::Matrix3d& rotation, double scale, const Vec3& shift) {
  for (Vec3& p : soup.points) p = rotation * p * scale + shift;
  return soup;
}

// One closed, manifold, consistently oriented solid without self-intersections.
void expect_one_valid_solid(const TriangleSoup& soup, std::size_t components = 1) {
  const Topology t = analyze_topology(soup);
  EXPECT_TRUE(t.closed);
  EXPECT_TRUE(t.manifold);
  EXPECT_TRUE(t.oriented);
  EXPECT_EQ(t.components, components);
  EXPECT_EQ(find_self_intersections(soup).count, 0u);
}

// Every point of `repaired` lies on `input`, up to `relative` x its diagonal.
void expect_on_input(const TriangleSoup& repaired, const TriangleSoup& input, double relative) {
  DistanceParams params;
  params.samples = 20000;
  EXPECT_LE(surface_distance(repaired, input, params).a_to_b.max, relative * bbox_diagonal(input));
}

// The repair of a and b together: one valid solid of `volume`, lying on the input.
RepairResult expect_union(const TriangleSoup& a, const TriangleSoup& b, double volume) {
  const TriangleSoup input = test::merged(a, b);
  TriangleSoup soup = input;
  const RepairResult r = repair(soup);
  expect_one_valid_solid(soup);
  EXPECT_NEAR(signed_volume(soup), volume, 1e-12 * volume);
  expect_on_input(soup, input, 1e-12);
  return r;
}

TEST(RepairIntersections, TwoCrossingTrianglesAreCutAlongTheirCommonSegment) {
  using namespace detail;
  const ExactTriangle a{exact_point({0, 0, 0}), exact_point({2, 0, 0}), exact_point({0, 2, 0})};
  const ExactTriangle b{exact_point({0.5, -1, -1}), exact_point({0.5, 1, -1}), exact_point({0.5, 0, 1})};
  // a's chord on x = 0.5 is y in [0, 1.5]; b's on z = 0 is y in [-0.5, 0.5]: they share y in [0, 0.5].
  const FaceIntersection meet = intersect_faces(a, b);
  ASSERT_EQ(meet.in_a.size(), 1u);
  ASSERT_EQ(meet.in_b.size(), 1u);
  const ExactPoint p = exact_point({0.5, 0, 0}), q = exact_point({0.5, 0.5, 0});
  const CutSegment& cut = meet.in_a[0];
  EXPECT_TRUE((cut.from == p && cut.to == q) || (cut.from == q && cut.to == p));

  for (const auto& [face, cuts] : {std::make_pair(a, meet.in_a), std::make_pair(b, meet.in_b)}) {
    const CutFace pieces = cut_face(face, cuts, {});
    Rational area = 0;
    bool segment_is_an_edge = false;
    const ExactPoint n = normal(face);
    for (const auto& t : pieces.triangles) {
      const ExactTriangle piece{pieces.points[t[0]], pieces.points[t[1]], pieces.points[t[2]]};
      const Rational twice_area = dot(normal(piece), n);  // facing as the face: positive
      EXPECT_GT(sgn(twice_area), 0);
      area += twice_area;
      for (int i = 0; i < 3; ++i) {
        const ExactPoint &u = piece[i], &v = piece[(i + 1) % 3];
        segment_is_an_edge = segment_is_an_edge || (u == p && v == q) || (u == q && v == p);
      }
    }
    EXPECT_EQ(area, dot(n, n));  // the pieces tile the face exactly
    EXPECT_TRUE(segment_is_an_edge);
  }
}

TEST(RepairIntersections, OverlappingBoxesBecomeTheirUnion) {
  const RepairResult r = expect_union(test::box({0, 0, 0}, {2, 2, 2}), test::box({1, 1, 1}, {3, 3, 3}), 8 + 8 - 1);
  EXPECT_GT(r.intersecting_pairs, 0u);
  EXPECT_GT(r.removed_faces, 0u);
}

// Rotated, the cuts' points are no longer doubles: they are rounded, and the union must still be
// valid and the volume 15 up to that rounding.
TEST(RepairIntersections, TheUnionHoldsRotatedScaledAndMoved) {
  const Eigen::Matrix3d rotation = Eigen::AngleAxisd(0.7, Vec3(1, 2, 3).normalized()).toRotationMatrix();
  const TriangleSoup boxes = test::merged(test::box({0, 0, 0}, {2, 2, 2}), test::box({1, 1, 1}, {3, 3, 3}));
  std::size_t faces = 0;
  for (const double scale : {1.0, 1e-3, 1e3}) {
    const TriangleSoup input = transformed(boxes, rotation, scale, Vec3(1, -2, 5) * scale * 1e3);
    TriangleSoup soup = input;
    repair(soup);
    expect_one_valid_solid(soup);
    EXPECT_NEAR(signed_volume(soup), 15 * scale * scale * scale, 1e-9 * 15 * scale * scale * scale);
    expect_on_input(soup, input, 1e-12);
    if (faces == 0) faces = soup.triangles.size();
    EXPECT_EQ(soup.triangles.size(), faces) << "scale " << scale;
  }
}

// Coplanar faces overlapping and facing the same way: one copy of the overlap stays.
TEST(RepairIntersections, BoxesOverlappingFlushShareTheirCoplanarSides) {
  EXPECT_GT(expect_union(test::box({0, 0, 0}, {2, 2, 2}), test::box({1, 0, 0}, {3, 2, 2}), 12).intersecting_pairs, 0u);
}

// The shared face is written by both boxes, facing into each other: a wall, both copies go.
TEST(RepairIntersections, TwoBoxesSharingAFaceBecomeOne) {
  EXPECT_EQ(expect_union(test::box({0, 0, 0}, {1, 1, 1}), test::box({1, 0, 0}, {2, 1, 1}), 2).duplicate_faces, 4u);
}

// A box sharing part of a face with a larger one: the face is cut where the small one sits on it.
TEST(RepairIntersections, ABoxOnPartOfAnothersFaceIsJoinedToIt) {
  expect_union(test::box({0, 0, 0}, {2, 2, 2}), test::box({2, 0.5, 0.5}, {3, 1.5, 1.5}), 9);
}

TEST(RepairIntersections, ABoxInsideABoxIsDroppedOrKeptAsACavity) {
  const TriangleSoup input = test::merged(test::box({0, 0, 0}, {4, 4, 4}), test::box({1, 1, 1}, {2, 2, 2}));
  TriangleSoup dropped = input;
  const RepairResult r = repair(dropped);
  EXPECT_EQ(r.nested_components, 1u);
  EXPECT_EQ(r.cavities, 0u);
  expect_one_valid_solid(dropped);
  EXPECT_NEAR(signed_volume(dropped), 64, 1e-12);

  TriangleSoup kept = input;
  RepairParams params;
  params.keep_cavities = true;
  const RepairResult k = repair(kept, params);
  EXPECT_EQ(k.nested_components, 0u);
  EXPECT_EQ(k.cavities, 1u);
  expect_one_valid_solid(kept, 2);
  EXPECT_NEAR(signed_volume(kept), 63, 1e-12);  // the inner box faces inwards: a void
}

// Open parts have no inside: two sheets, one above the other, are neither cut nor judged (a
// winding number around a sheet is fractional, and rounding it dropped one of stacked horizons).
TEST(RepairIntersections, OpenSheetsAreNeitherCutNorJudged) {
  TriangleSoup soup = test::merged(test::grid(6), test::grid(6, 1.0));
  const std::size_t faces = soup.triangles.size();
  RepairParams params;
  params.max_hole = 0.0;  // both outlines stay open
  const RepairResult r = repair(soup, params);
  EXPECT_EQ(r.removed_faces, 0u);
  EXPECT_EQ(r.nested_components, 0u);
  EXPECT_EQ(soup.triangles.size(), faces);
}

// The corpus's self-intersecting scans, and its open elephant that crosses itself.
TEST(RepairIntersections, TheCorpusScansBecomeValidSolidsOnTheirInput) {
  const std::filesystem::path shared(MESHPREP_SHARED_DATA_DIR);
  if (!std::filesystem::exists(shared / "corpus"))
    GTEST_SKIP() << "../shared/data/corpus not found beside the clone: the corpus repair skipped";
  for (const char* name : {"corpus/camel", "corpus/cow", "corpus/bull", "corpus/elk", "corpus/bones",
                           "corpus/elephant-with-holes", "meshes/ChineseDragon-10kv"}) {
    SCOPED_TRACE(name);
    const TriangleSoup input = read_soup((shared / (std::string(name) + ".off")).string());
    TriangleSoup soup = input;
    RepairParams params;
    params.max_hole = 3;
    const RepairResult r = repair(soup, params);
    EXPECT_GT(r.intersecting_pairs, 0u);
    expect_one_valid_solid(soup, analyze_topology(soup).components);
    // The pieces lie on the input; the patches of holes do not (the elephant's are reported).
    if (r.filled_holes == 0) expect_on_input(soup, input, 2e-3);
  }
}

}  // namespace
}  // namespace meshprep
