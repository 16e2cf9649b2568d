// Issue #4's acceptance figures on the shared meshes (../shared/data/meshes), measured with our own
// quality report (cross-checked with ../shared/tools/judge in bench/RESULTS.md). Relative
// distances are / bbox diagonal. Bounds: the goals where we meet them, otherwise the level
// measured when the simplifier landed plus ~8 % (so a regression fails); both are noted per line.
// Skipped, with a message, when ../shared is not beside the clone.
#include "meshprep/core/io.h"
#include "meshprep/preprocess/simplify/simplify.h"
#include "meshprep/quality/report.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>

using namespace meshprep;

namespace {

const std::filesystem::path kMeshes = std::filesystem::path(MESHPREP_SHARED_DATA_DIR) / "meshes";

struct Simplified {
  QualityReport input, output;
  SimplifyResult result;
  TriangleSoup soup;
};

Simplified simplify_shared(const char* file, const SimplifyParams& p) {
  LoadedMesh loaded = load_mesh((kMeshes / file).string());
  Simplified s;
  s.result = simplify(loaded.mesh, p);
  s.soup = soup_from_mesh(loaded.mesh);
  QualityParams q;
  q.distance_samples = 200000;
  s.input = analyze_quality(loaded.soup);
  s.output = analyze_quality(s.soup, q, &loaded.soup);
  return s;
}

Simplified simplify_shared(const char* file, double ratio) {
  SimplifyParams p;
  p.keep_ratio = ratio;
  return simplify_shared(file, p);
}

void expect_valid(const Simplified& s) {
  EXPECT_TRUE(s.result.reached_target);
  EXPECT_TRUE(s.output.closed);
  EXPECT_TRUE(s.output.manifold);
  EXPECT_EQ(s.output.genus, s.input.genus);
  EXPECT_EQ(s.output.self_intersections, 0u);
}

// Total length of the edges whose faces meet at more than 60 degrees: fandisk's sharp edges.
double sharp_edge_length(const TriangleSoup& soup) {
  const TriMesh mesh = mesh_from_soup(soup);
  double length = 0;
  for (const auto e : mesh.edges())
    if (!mesh.is_boundary(e) && std::abs(mesh.calc_dihedral_angle(e)) > M_PI / 3) length += mesh.calc_edge_length(e);
  return length;
}

#define SKIP_WITHOUT_SHARED_DATA()                                                                    \
  if (!std::filesystem::exists(kMeshes / "bunny00.off"))                                              \
  GTEST_SKIP() << "../shared/data/meshes not found beside the clone: real-data simplification figures skipped"

}  // namespace

TEST(SharedSimplify, Bunny10Percent) {
  SKIP_WITHOUT_SHARED_DATA();
  const Simplified s = simplify_shared("bunny00.off", 0.1);
  expect_valid(s);
  EXPECT_LE(s.output.reference->hausdorff_relative, 1.55e-3);  // goal: 1.25 x CGAL GH's 1.24e-3 (measured 1.25e-3)
  EXPECT_LE(s.output.reference->rms_relative, 1.55e-4);  // goal: 1.25 x CGAL LT's 1.24e-4 (measured 1.54e-4)
  EXPECT_LE(s.output.faces_min_angle_below_20, 0.05);  // goal; measured 0
  EXPECT_LE(s.output.radius_ratio.p95, 2.0);  // goal; measured 1.88
}

TEST(SharedSimplify, Bunny30Percent) {
  SKIP_WITHOUT_SHARED_DATA();
  const Simplified s = simplify_shared("bunny00.off", 0.3);
  expect_valid(s);
  EXPECT_LE(s.output.reference->hausdorff_relative, 5.125e-4);  // goal: 1.25 x CGAL GH's 4.1e-4 (measured 4.64e-4)
  EXPECT_LE(s.output.reference->rms_relative, 5.5e-5);  // goal: 1.25 x CGAL LT's 0.44e-4 (measured 5.41e-5)
  EXPECT_LE(s.output.faces_min_angle_below_20, 0.05);
  EXPECT_LE(s.output.radius_ratio.p95, 2.0);  // goal; measured 1.85
}

TEST(SharedSimplify, Fandisk30PercentKeepsItsSharpEdges) {
  SKIP_WITHOUT_SHARED_DATA();
  const Simplified s = simplify_shared("fandisk.off", 0.3);
  expect_valid(s);
  EXPECT_LE(s.output.reference->hausdorff_relative, 1.0e-3);  // goal; measured 1.25e-4
  EXPECT_LE(s.output.faces_min_angle_below_20, 0.05);
  EXPECT_LE(s.output.radius_ratio.p95, 2.0);  // goal; measured 1.99
  const TriangleSoup input = load_mesh((kMeshes / "fandisk.off").string()).soup;
  // Every sharp edge survives as a chain of sharp edges of the same total length (measured:
  // 8.8906 -> 8.8904 diagonals); a rounded or chamfered crease would lose length.
  EXPECT_NEAR(sharp_edge_length(s.soup), sharp_edge_length(input), 0.01 * sharp_edge_length(input));
}

namespace {

// bunny00 to a coarse face count with the default options: valid, and every angle above the bound.
Simplified bunny_to_faces(std::size_t faces) {
  SimplifyParams p;
  p.target_faces = faces;
  Simplified s = simplify_shared("bunny00.off", p);
  expect_valid(s);
  EXPECT_GE(s.output.min_angle_deg.min, p.min_angle_deg - 1e-9);
  return s;
}

}  // namespace

TEST(SharedSimplify, BunnyToTwoThousandFaces) {
  SKIP_WITHOUT_SHARED_DATA();
  // 2.7 % of the faces: edges refused by the guards come back when a face beside them changes
  // (measured RMS 7.3e-4; 8.3e-4 when only the kept vertex's edges were queued again).
  EXPECT_LE(bunny_to_faces(2000).output.reference->rms_relative, 7.8e-4);
}

TEST(SharedSimplify, BunnyToFiveHundredFaces) {
  SKIP_WITHOUT_SHARED_DATA();
  // The shape guard alone runs dry at ~1,190 faces; with the relaxation each time the face count
  // halves (and flips if the queue still runs dry) the target is reached, every angle above the
  // bound.
  EXPECT_TRUE(bunny_to_faces(500).result.reached_target);
}
