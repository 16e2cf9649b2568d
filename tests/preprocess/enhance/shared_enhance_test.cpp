// Issue #7's acceptance figures on the shared meshes (../shared/data/meshes), with --reference the
// original mesh, measured with our own quality report (cross-checked with ../shared/tools/judge in
// bench/RESULTS.md). Relative distances are / the reference's bbox diagonal. Bounds: the issue's
// goals where we meet them, otherwise the level measured when the stage landed plus a margin (so a
// regression fails); both are noted per line. The peers' figures are in ../shared/anchors.md.
// Skipped, with a message, when ../shared is not beside the clone.
#include "meshprep/core/io.h"
#include "meshprep/preprocess/enhance/enhance.h"
#include "meshprep/quality/report.h"
#include "meshprep/quality/self_intersections.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <map>

using namespace meshprep;

namespace {

const std::filesystem::path kMeshes = std::filesystem::path(MESHPREP_SHARED_DATA_DIR) / "meshes";

struct Enhanced {
  QualityReport input, output;
  TriangleSoup surface;
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
  e.surface = soup_from_mesh(loaded.mesh);
  e.output = analyze_quality(e.surface, q, &reference);
  return e;
}

// The solid's sharpest angle along an edge of a closed surface (180 degrees less the angle between
// the two faces' normals): a fold makes it small, and every tet on that edge is as flat.
double sharpest_edge_deg(const TriangleSoup& s) {
  std::map<std::pair<std::uint32_t, std::uint32_t>, std::vector<Vec3>> normals;
  for (const Triangle& t : s.triangles) {
    const Vec3 n = (s.points[t[1]] - s.points[t[0]]).cross(s.points[t[2]] - s.points[t[0]]).normalized();
    for (int k = 0; k < 3; ++k) normals[std::minmax(t[k], t[(k + 1) % 3])].push_back(n);
  }
  double sharpest = 180;
  for (const auto& [edge, pair] : normals)
    if (pair.size() == 2) sharpest = std::min(sharpest, 180 - std::acos(std::clamp(pair[0].dot(pair[1]), -1.0, 1.0)) * 180 / M_PI);
  return sharpest;
}

void expect_valid(const Enhanced& e) {
  EXPECT_TRUE(e.output.closed);
  EXPECT_TRUE(e.output.manifold);
  EXPECT_EQ(e.output.genus, e.input.genus);
  EXPECT_LE(e.output.self_intersections, e.input_intersections);
  if (e.result.remeshed) {
    // Remeshed edges lie between 4/5 and 4/3 of the sizing field's target, so the faces are within
    // (3/4)^2 and (5/4)^2 of the field's equilateral estimate, and relaxation moves them about
    // (1.08 to 1.64 times on the CAD parts and corpus).
    EXPECT_GE(static_cast<double>(e.output.faces), 0.5 * static_cast<double>(e.result.sizing_faces));
    EXPECT_LE(static_cast<double>(e.output.faces), 2.0 * static_cast<double>(e.result.sizing_faces));
  } else {
    EXPECT_LE(std::abs(static_cast<double>(e.output.faces) / static_cast<double>(e.input_faces) - 1), 0.02);
  }
}

#define SKIP_WITHOUT_SHARED_DATA()                                       \
  if (!std::filesystem::exists(kMeshes / "bunny00.off"))                 \
  GTEST_SKIP() << "../shared/data/meshes not found beside the clone: real-data enhancement figures skipped"

}  // namespace

TEST(SharedEnhance, Bunny10Percent) {
  SKIP_WITHOUT_SHARED_DATA();
  const Enhanced e = enhance_shared("decimated/bunny00_0.1_openmesh.off", "bunny00.off");
  expect_valid(e);
  EXPECT_LE(e.output.faces_min_angle_below_20, 0.02);       // goal 2 % (measured 0.05 %; input 25.7 %)
  EXPECT_LE(e.output.radius_ratio.p95, 1.8);                // goal 1.8 (measured 1.30; input 6.48)
  EXPECT_LE(e.output.reference->hausdorff_relative, 2.5e-3);  // goal (measured 1.92e-3)
  EXPECT_LE(e.output.reference->rms_relative, 3.5e-4);      // goal (measured 2.5e-4)
  EXPECT_LE(std::abs(*e.output.reference->volume_change_percent), 0.1);  // goal 0.1 % (measured 0.02 %)
}

TEST(SharedEnhance, Fandisk30Percent) {
  SKIP_WITHOUT_SHARED_DATA();
  const Enhanced e = enhance_shared("decimated/fandisk_0.3_cgal_gh.off", "fandisk.off");
  expect_valid(e);
  // Every goal of issue #7 (input 17.0 % under 20 degrees; the best peer keeping the surface,
  // angle-and-area smoothing, left 14.4 %). Measured 1.99 % (the fans of needles on its planes are
  // split), Hausdorff 4.6e-4 and RMS 4.75e-5: the default bound is the input's own distance,
  // 4.0e-4 (it was 2e-3: Hausdorff 2.1e-3, RMS 1.25e-4).
  EXPECT_LE(e.output.faces_min_angle_below_20, 0.03);
  EXPECT_LE(e.output.reference->hausdorff_relative, 1.0e-3);
  EXPECT_LE(e.output.reference->rms_relative, 0.5e-4);
}

TEST(SharedEnhance, FemurAsIs) {
  SKIP_WITHOUT_SHARED_DATA();
  const Enhanced e = enhance_shared("femur.off", "femur.off");
  expect_valid(e);
  EXPECT_LE(e.output.faces_min_angle_below_20, 0.01);       // goal 1 % (measured 0.07 %; input 10.7 %)
  EXPECT_LE(e.output.reference->hausdorff_relative, 3e-3);  // goal (measured 2.0e-3)
  EXPECT_GE(e.output.min_angle_deg.min, 15.0);              // goal 15 degrees (measured 15.7; input 0.45)
  // No fold: the input's sharpest edge is 24.6 degrees, the enhancement makes none under 15 (it
  // made 0.06 before its guards refused folds, and TetGen's tets there were 0.6 degrees).
  EXPECT_GT(sharpest_edge_deg(read_soup((kMeshes / "femur.off").string())), 24.0);
  EXPECT_GE(sharpest_edge_deg(e.surface), 15.0);
}
