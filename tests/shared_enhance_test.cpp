// Issue #7's acceptance figures on the shared meshes (../shared/data/meshes), with --reference the
// original mesh, measured with our own quality report (cross-checked with ../shared/tools/judge in
// bench/RESULTS.md). Relative distances are / the reference's bbox diagonal. Bounds: the issue's
// goals where we meet them, otherwise the level measured when the stage landed plus a margin (so a
// regression fails); both are noted per line. The peers' figures are in ../shared/anchors.md.
// Skipped, with a message, when ../shared is not beside the clone.
#include "meshprep/core/io.h"
#include "meshprep/preprocess/enhance.h"
#include "meshprep/quality/report.h"
#include "meshprep/quality/self_intersections.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>

using namespace meshprep;

namespace {

const std::filesystem::path kMeshes = std::filesystem::path(MESHPREP_SHARED_DATA_DIR) / "meshes";

struct Enhanced {
  QualityReport input, output;
  EnhanceResult result;
  std::size_t input_faces = 0, input_intersections = 0;
};

Enhanced enhance_shared(const char* input, const char* original) {
  LoadedMesh loaded = load_mesh((kMeshes / input).string());
  const TriangleSoup reference = read_soup((kMeshes / original).string());
  Enhanced e;
  e.input_faces = loaded.soup.triangles.size();
  e.input_intersections = find_self_intersections(loaded.soup).count;
  e.result = enhance(loaded.mesh, &reference);
  QualityParams q;
  q.distance_samples = 200000;
  e.input = analyze_quality(loaded.soup);
  e.output = analyze_quality(soup_from_mesh(loaded.mesh), q, &reference);
  return e;
}

void expect_valid(const Enhanced& e) {
  EXPECT_TRUE(e.output.closed);
  EXPECT_TRUE(e.output.manifold);
  EXPECT_EQ(e.output.genus, e.input.genus);
  EXPECT_LE(e.output.self_intersections, e.input_intersections);
  EXPECT_LE(std::abs(static_cast<double>(e.output.faces) / static_cast<double>(e.input_faces) - 1), 0.02);
}

#define SKIP_WITHOUT_SHARED_DATA()                                       \
  if (!std::filesystem::exists(kMeshes / "bunny00.off"))                 \
  GTEST_SKIP() << "../shared/data/meshes not found beside the clone: real-data enhancement figures skipped"

}  // namespace

TEST(SharedEnhance, Bunny10Percent) {
  SKIP_WITHOUT_SHARED_DATA();
  const Enhanced e = enhance_shared("decimated/bunny00_0.1_openmesh.off", "bunny00.off");
  expect_valid(e);
  EXPECT_LE(e.output.faces_min_angle_below_20, 0.02);       // goal 2 % (measured 0 %; input 25.7 %)
  EXPECT_LE(e.output.radius_ratio.p95, 1.8);                // goal 1.8 (measured 1.28; input 6.48)
  EXPECT_LE(e.output.reference->hausdorff_relative, 2.5e-3);  // goal (measured 2.2e-3)
  EXPECT_LE(e.output.reference->rms_relative, 3.5e-4);      // goal (measured 2.5e-4)
  EXPECT_LE(std::abs(*e.output.reference->volume_change_percent), 0.1);  // goal 0.1 % (measured 0.02 %)
}

TEST(SharedEnhance, Fandisk30Percent) {
  SKIP_WITHOUT_SHARED_DATA();
  const Enhanced e = enhance_shared("decimated/fandisk_0.3_cgal_gh.off", "fandisk.off");
  expect_valid(e);
  // Goals 3 %, Hausdorff 1.0e-3, RMS 0.5e-4 are not met yet: measured 4.2 %, 2.1e-3, 1.3e-4
  // (input 17.0 %; the best peer keeping the surface, angle-and-area smoothing, left 14.4 %).
  EXPECT_LE(e.output.faces_min_angle_below_20, 0.045);
  EXPECT_LE(e.output.reference->hausdorff_relative, 3.5e-3);
  EXPECT_LE(e.output.reference->rms_relative, 2.0e-4);
}

TEST(SharedEnhance, FemurAsIs) {
  SKIP_WITHOUT_SHARED_DATA();
  const Enhanced e = enhance_shared("femur.off", "femur.off");
  expect_valid(e);
  EXPECT_LE(e.output.faces_min_angle_below_20, 0.01);       // goal 1 % (measured 0.04 %; input 10.7 %)
  EXPECT_LE(e.output.reference->hausdorff_relative, 3e-3);  // goal (measured 2.0e-3)
  EXPECT_GE(e.output.min_angle_deg.min, 15.0);              // goal 15 degrees (measured 17.4; input 0.45)
}
