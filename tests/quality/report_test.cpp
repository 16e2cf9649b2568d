#include "meshprep/quality/report.h"

#include "test_meshes.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace meshprep;

namespace {
QualityParams fast_params() {
  QualityParams p;
  p.distance_samples = 20000;
  return p;
}
}  // namespace

TEST(QualityReport, RegularTetrahedron) {
  const double edge = 2.0;
  const QualityReport r = analyze_quality(test::regular_tetrahedron(edge), fast_params());
  ASSERT_TRUE(r.volume.has_value());
  EXPECT_NEAR(*r.volume, edge * edge * edge / (6.0 * std::sqrt(2.0)), 1e-12);  // a^3 / (6 sqrt 2)
  EXPECT_NEAR(r.area, std::sqrt(3.0) * edge * edge, 1e-12);                    // 4 * sqrt3/4 a^2
  EXPECT_NEAR(r.radius_ratio.max, 1.0, 1e-12);
  EXPECT_NEAR(r.min_angle_deg.min, 60.0, 1e-10);
  EXPECT_EQ(r.euler_characteristic, 2);
  EXPECT_EQ(*r.genus, 0);
  EXPECT_EQ(r.faces_min_angle_below_20, 0.0);
  EXPECT_EQ(r.self_intersections, 0u);
}

TEST(QualityReport, CubeVolumeAndRightTriangles) {
  const QualityReport r = analyze_quality(test::cube(3.0), fast_params());
  EXPECT_NEAR(*r.volume, 27.0, 1e-12);
  EXPECT_NEAR(r.area, 54.0, 1e-12);
  EXPECT_NEAR(r.radius_ratio.mean, (1.0 + std::sqrt(2.0)) / 2.0, 1e-12);
  EXPECT_NEAR(r.max_angle_deg.max, 90.0, 1e-10);
  EXPECT_NEAR(r.bbox_diagonal, 3.0 * std::sqrt(3.0), 1e-12);
  EXPECT_EQ(r.worst_faces.size(), 10u);
}

TEST(QualityReport, InwardOrientationGivesNegativeVolume) {
  TriangleSoup s = test::cube();
  for (auto& t : s.triangles) std::swap(t[1], t[2]);
  EXPECT_NEAR(*analyze_quality(s, fast_params()).volume, -1.0, 1e-12);
}

TEST(QualityReport, SphereVolumeConvergesTo4PiOver3) {
  // The inscribed polyhedron's volume error shrinks ~4x per subdivision (O(h^2)).
  const double exact = 4.0 * M_PI / 3.0;
  double previous_error = INFINITY;
  for (int level = 1; level <= 5; ++level) {
    const double error = exact - *analyze_quality(test::icosphere(level), fast_params()).volume;
    EXPECT_GT(error, 0.0);  // inscribed: always smaller
    EXPECT_LT(error, previous_error / 3.5);
    previous_error = error;
  }
  EXPECT_LT(previous_error / exact, 1e-3);
}

TEST(QualityReport, OpenMeshHasNoVolume) {
  TriangleSoup s = test::icosphere(1);
  s.triangles.pop_back();
  const QualityReport r = analyze_quality(s, fast_params());
  EXPECT_FALSE(r.volume.has_value());
  EXPECT_FALSE(r.genus.has_value());
  EXPECT_EQ(r.boundary_loops, 1u);
}

TEST(QualityReport, DegenerateFacesAreWorstAndExcludedFromDistributions) {
  TriangleSoup s = test::grid(2);
  s.points.emplace_back(0.5, 0, 0);
  s.triangles.push_back({0, 1, static_cast<std::uint32_t>(s.points.size() - 1)});  // collinear corners
  const QualityReport r = analyze_quality(s, fast_params());
  EXPECT_EQ(r.degenerate_faces, 1u);
  EXPECT_EQ(r.worst_faces.front().index, s.triangles.size() - 1);
  EXPECT_EQ(r.radius_ratio.count, s.triangles.size() - 1);
  EXPECT_TRUE(std::isfinite(r.radius_ratio.max));
}

TEST(QualityReport, ReferenceComparison) {
  const TriangleSoup a = test::grid(4), b = test::grid(4, 0.1);
  const QualityReport r = analyze_quality(a, fast_params(), &b);
  ASSERT_TRUE(r.reference.has_value());
  EXPECT_NEAR(r.reference->hausdorff, 0.1, 1e-12);
  EXPECT_NEAR(r.reference->hausdorff_relative, 0.1 / std::sqrt(32.0), 1e-12);  // diagonal of 4 x 4 x 0
  EXPECT_FALSE(r.reference->volume_change_percent.has_value());
}

TEST(QualityReport, VolumeChangeAgainstAScaledCube) {
  const TriangleSoup a = test::cube(1.1), b = test::cube(1.0);
  const QualityReport r = analyze_quality(a, fast_params(), &b);
  ASSERT_TRUE(r.reference->volume_change_percent.has_value());
  EXPECT_NEAR(*r.reference->volume_change_percent, (1.331 - 1.0) * 100.0, 1e-9);
}

// The stages' guarantee counts only the pairs beyond the input's own.
TEST(QualityReport, NewSelfIntersectionsAreThoseBeyondTheInputs) {
  QualityReport output;
  output.self_intersections = 5;
  EXPECT_EQ(new_self_intersections(output, 3), 2u);
  EXPECT_EQ(new_self_intersections(output, 5), 0u);
  EXPECT_EQ(new_self_intersections(output, 8), 0u);  // fewer than the input: none new
  output.self_intersections = 0;
  EXPECT_EQ(new_self_intersections(output, 0), 0u);
}
