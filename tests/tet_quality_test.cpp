#include "meshprep/core/errors.h"
#include "meshprep/fem/tet_quality.h"
#include "tet_test_meshes.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace meshprep;

namespace {

constexpr double kTight = 1e-12;   // closed-form values computed in double: round-off only
constexpr double kAngle = 1e-10;   // degrees: atan2 is accurate to ~1e-16 rad, times 57.3
const double kRegularDihedral = std::acos(1.0 / 3.0) * 180.0 / M_PI;  // 70.5288 degrees

TetMesh single_tet(const Vec3& p0, const Vec3& p1, const Vec3& p2, const Vec3& p3) {
  TetMesh m;
  m.points = {p0, p1, p2, p3};
  m.tets = {{0, 1, 2, 3}};
  m.tet_regions = {1};
  return m;
}

}  // namespace

TEST(TetShape, RegularTet) {
  // Alternate corners of the cube [-1, 1]^3: edge 2 sqrt 2, volume L^3 / (6 sqrt 2) = 8/3.
  const TetShape s = tet_shape({1, 1, 1}, {1, -1, -1}, {-1, -1, 1}, {-1, 1, -1});
  EXPECT_NEAR(s.volume, 8.0 / 3.0, kTight);
  EXPECT_NEAR(s.min_dihedral_deg, kRegularDihedral, kAngle);
  EXPECT_NEAR(s.max_dihedral_deg, kRegularDihedral, kAngle);
  EXPECT_NEAR(s.radius_edge_ratio, std::sqrt(6.0) / 4.0, kTight);  // R = L sqrt(6)/4
}

TEST(TetShape, OrientationOnlyFlipsTheVolume) {
  const Vec3 p0(0.1, 0, 0), p1(1, 0.2, 0), p2(0.3, 1, 0.1), p3(0.2, 0.3, 0.9);
  const TetShape a = tet_shape(p0, p1, p2, p3);
  const TetShape b = tet_shape(p0, p1, p3, p2);
  EXPECT_GT(a.volume, 0);
  EXPECT_NEAR(b.volume, -a.volume, kTight);
  EXPECT_NEAR(b.min_dihedral_deg, a.min_dihedral_deg, kAngle);
  EXPECT_NEAR(b.max_dihedral_deg, a.max_dihedral_deg, kAngle);
  EXPECT_NEAR(b.radius_edge_ratio, a.radius_edge_ratio, kTight);
}

TEST(TetShape, ScaleAndRotationInvariant) {
  const Vec3 p[4] = {{0.1, 0, 0}, {1, 0.2, 0}, {0.3, 1, 0.1}, {0.2, 0.3, 0.9}};
  const Eigen::Matrix3d rotation = Eigen::AngleAxisd(0.7, Vec3(1, 2, 3).normalized()).toRotationMatrix();
  auto moved = [&](const Vec3& x) -> Vec3 { return 10.0 * (rotation * x) + Vec3(5, -4, 2); };
  const TetShape a = tet_shape(p[0], p[1], p[2], p[3]);
  const TetShape b = tet_shape(moved(p[0]), moved(p[1]), moved(p[2]), moved(p[3]));
  EXPECT_NEAR(b.volume, 1000.0 * a.volume, 1e-10 * b.volume);
  EXPECT_NEAR(b.min_dihedral_deg, a.min_dihedral_deg, kAngle);
  EXPECT_NEAR(b.max_dihedral_deg, a.max_dihedral_deg, kAngle);
  EXPECT_NEAR(b.radius_edge_ratio, a.radius_edge_ratio, kTight);
}

TEST(TetShape, KuhnTet) {
  // A Freudenthal tet of the unit cube: dihedral angles 45, 45, 60, 90, 90, 90; its circumsphere
  // is the cube's (R = sqrt(3)/2), its shortest edge 1.
  const TetShape s = tet_shape({0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {1, 1, 1});
  EXPECT_NEAR(s.volume, 1.0 / 6.0, kTight);
  EXPECT_NEAR(s.min_dihedral_deg, 45.0, kAngle);
  EXPECT_NEAR(s.max_dihedral_deg, 90.0, kAngle);
  EXPECT_NEAR(s.radius_edge_ratio, std::sqrt(3.0) / 2.0, kTight);
}

TEST(TetShape, FlatTetHasInfiniteRadiusEdgeRatio) {
  const TetShape s = tet_shape({0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0});
  EXPECT_EQ(s.volume, 0.0);
  EXPECT_TRUE(std::isinf(s.radius_edge_ratio));
  EXPECT_NEAR(s.min_dihedral_deg, 0.0, kAngle);
  EXPECT_NEAR(s.max_dihedral_deg, 180.0, kAngle);
}

TEST(TetShape, SliverHasTinyDihedralButModestRadiusEdgeRatio) {
  // The corners of the unit square, two of them lifted by e: the circumsphere stays close to the
  // square's circle (R -> sqrt(2)/2 with shortest edge 1), so the radius-edge ratio (~0.707) does
  // not see the sliver; the dihedral angles at the diagonals go to 0 and 180 degrees as O(e).
  const double e = 1e-2;
  const TetShape s = tet_shape({0, 0, 0}, {1, 1, 0}, {0, 1, e}, {1, 0, e});
  EXPECT_GT(s.volume, 0);
  EXPECT_LT(s.min_dihedral_deg, 2.0);
  EXPECT_GT(s.max_dihedral_deg, 178.0);
  EXPECT_NEAR(s.radius_edge_ratio, std::sqrt(2.0) / 2.0, 1e-3);
}

TEST(TetQuality, FreudenthalCube) {
  const int n = 4;
  const double size = 2.0;
  const TetQualityReport r = analyze_tet_quality(test::cube_tets(n, size));
  EXPECT_EQ(r.points, std::size_t((n + 1) * (n + 1) * (n + 1)));
  EXPECT_EQ(r.tetrahedra, std::size_t(6 * n * n * n));
  EXPECT_NEAR(r.volume, size * size * size, kTight * size * size * size);
  EXPECT_EQ(r.inverted_tets, 0u);
  // Every tet is congruent to the Kuhn tet: min 45, max 90, radius-edge sqrt(3)/2.
  EXPECT_NEAR(r.min_dihedral_deg.min, 45.0, kAngle);
  EXPECT_NEAR(r.min_dihedral_deg.max, 45.0, kAngle);
  EXPECT_NEAR(r.max_dihedral_deg.min, 90.0, kAngle);
  EXPECT_NEAR(r.max_dihedral_deg.max, 90.0, kAngle);
  EXPECT_NEAR(r.radius_edge_ratio.p50, std::sqrt(3.0) / 2.0, kTight);
  EXPECT_EQ(r.min_dihedral_deg.count, r.tetrahedra);
  EXPECT_EQ(r.tets_min_dihedral_below_10, 0.0);
  // n even: the x < size/2 split is exact, half of the tets each.
  const std::map<int, std::size_t> regions{{1, 3 * n * n * n}, {2, 3 * n * n * n}};
  EXPECT_EQ(r.tets_per_region, regions);
  EXPECT_EQ(r.min_dihedral_per_tet.size(), r.tetrahedra);
  EXPECT_EQ(r.radius_edge_per_tet.size(), r.tetrahedra);
}

TEST(TetQuality, FlatTetCountsAsInverted) {
  const TetQualityReport r = analyze_tet_quality(single_tet({0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}));
  EXPECT_EQ(r.inverted_tets, 1u);
  EXPECT_EQ(r.tets_min_dihedral_below_10, 1.0);
  EXPECT_EQ(r.radius_edge_ratio.count, 0u);  // the only value is +inf: ignored
  EXPECT_TRUE(std::isnan(r.radius_edge_ratio.max));
  EXPECT_TRUE(to_json(r)["radius_edge_ratio"]["max"].is_null());
}

TEST(TetQuality, InvertedTetCounted) {
  TetMesh m = test::cube_tets(2);
  std::swap(m.tets[5][2], m.tets[5][3]);
  const TetQualityReport r = analyze_tet_quality(m);
  EXPECT_EQ(r.inverted_tets, 1u);
  EXPECT_NEAR(r.volume, 1.0 - 2.0 / 48.0, kTight);  // one tet of volume 1/48 counted negatively
}

TEST(TetQuality, SliverFraction) {
  TetMesh m = test::cube_tets(1);  // 6 tets, none below 10 degrees
  m.points.push_back({0, 0, 0});
  m.points.push_back({1, 1, 0});
  m.points.push_back({0, 1, 0.01});
  m.points.push_back({1, 0, 0.01});
  m.tets.push_back({8, 9, 10, 11});
  m.tet_regions.push_back(3);
  const TetQualityReport r = analyze_tet_quality(m);
  EXPECT_DOUBLE_EQ(r.tets_min_dihedral_below_10, 1.0 / 7.0);
  EXPECT_EQ(r.tets_per_region.at(3), 1u);
}

TEST(TetQuality, EmptyMesh) {
  const TetQualityReport r = analyze_tet_quality(TetMesh{});
  EXPECT_EQ(r.tetrahedra, 0u);
  EXPECT_EQ(r.tets_min_dihedral_below_10, 0.0);
  EXPECT_TRUE(to_json(r)["min_dihedral_deg"]["mean"].is_null());
}

TEST(TetQuality, RejectsInconsistentMesh) {
  TetMesh m = test::cube_tets(1);
  m.tet_regions.pop_back();
  EXPECT_THROW(analyze_tet_quality(m), InvalidInput);
  m = test::cube_tets(1);
  m.tets[0][3] = 8;  // 8 points
  EXPECT_THROW(analyze_tet_quality(m), InvalidInput);
}

TEST(TetQuality, JsonKeys) {
  const nlohmann::ordered_json j = to_json(analyze_tet_quality(test::cube_tets(2)));
  std::vector<std::string> keys;
  for (const auto& item : j.items()) keys.push_back(item.key());
  const std::vector<std::string> expected{"points",           "tetrahedra",       "volume",
                                          "inverted_tets",    "min_dihedral_deg", "max_dihedral_deg",
                                          "radius_edge_ratio", "tets_min_dihedral_below_10", "tets_per_region"};
  EXPECT_EQ(keys, expected);
  EXPECT_EQ(j["tets_per_region"]["1"], 24);
  EXPECT_EQ(j["tets_per_region"]["2"], 24);
  for (const char* key : {"min", "mean", "p5", "p50", "p95", "max"}) EXPECT_TRUE(j["min_dihedral_deg"].contains(key));
  EXPECT_NEAR(j["min_dihedral_deg"]["p5"].get<double>(), 45.0, kAngle);
}
