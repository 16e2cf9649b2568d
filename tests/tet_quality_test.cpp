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
  // Verdict normalises both to 1 on the regular tet.
  EXPECT_NEAR(s.scaled_jacobian, 1.0, kTight);
  EXPECT_NEAR(s.aspect_ratio, 1.0, kTight);
}

TEST(TetShape, RightCornerTet) {
  // The unit right corner: three unit edges at p0, the opposite face equilateral with side sqrt 2.
  // Scaled Jacobian: J = 1; the corners' edge products are 1 at p0 and 1 x sqrt2 x sqrt2 = 2 at
  // the others, so sqrt(2) x 1 / 2. Aspect ratio: longest edge sqrt 2, faces' area 3/2 + sqrt(3)/2,
  // volume 1/6: sqrt(2) (3 + sqrt 3) / 2 / sqrt(6) = (1 + sqrt 3) / 2. Dihedral angles: 90 at the
  // three edges of p0, acos(1/sqrt 3) at the others. Circumsphere: the unit cube's, R = sqrt(3)/2.
  const TetShape s = tet_shape({0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1});
  EXPECT_NEAR(s.volume, 1.0 / 6.0, kTight);
  EXPECT_NEAR(s.scaled_jacobian, std::sqrt(2.0) / 2.0, kTight);
  EXPECT_NEAR(s.aspect_ratio, (1.0 + std::sqrt(3.0)) / 2.0, kTight);
  EXPECT_NEAR(s.min_dihedral_deg, std::acos(1.0 / std::sqrt(3.0)) * 180.0 / M_PI, kAngle);
  EXPECT_NEAR(s.max_dihedral_deg, 90.0, kAngle);
  EXPECT_NEAR(s.radius_edge_ratio, std::sqrt(3.0) / 2.0, kTight);
}

TEST(TetShape, SliverByHand) {
  // The unit square's corners (0,0,0), (1,1,0) and (0,1,h), (1,0,h): h = 1 is the regular tet,
  // h -> 0 the flat square. Every corner has one diagonal edge sqrt 2 and two edges sqrt(1 + h^2);
  // J = 6 V = 2 h; each face has base sqrt 2 and height sqrt(1/2 + h^2). So:
  //   scaled Jacobian sqrt(2) 2h / (sqrt(2) (1 + h^2)) = 2h / (1 + h^2);
  //   aspect ratio sqrt(2) x 2 sqrt(1 + 2h^2) / (6 sqrt(6) h / 3) = sqrt(1 + 2h^2) / (sqrt(3) h);
  //   dihedral at a side edge: cos = 1 / (1 + 2h^2), i.e. tan = 2h sqrt(1 + h^2); at the two
  //   diagonals: cos = (2h^2 - 1) / (1 + 2h^2), sin = 2 sqrt(2) h / (1 + 2h^2);
  //   circumcentre (1/2, 1/2, h/2): R = sqrt(1/2 + h^2/4) over the shortest edge sqrt(1 + h^2).
  // h = 0.0175 makes the 2-degree sliver of the verdict's tests.
  const double h = 0.0175;
  const TetShape s = tet_shape({0, 0, 0}, {1, 1, 0}, {0, 1, h}, {1, 0, h});
  EXPECT_NEAR(s.volume, 2 * h / 6, kTight);
  EXPECT_NEAR(s.scaled_jacobian, 2 * h / (1 + h * h), kTight);
  EXPECT_NEAR(s.aspect_ratio, std::sqrt(1 + 2 * h * h) / (std::sqrt(3.0) * h), 1e-12 * s.aspect_ratio);
  EXPECT_NEAR(s.min_dihedral_deg, std::atan(2 * h * std::sqrt(1 + h * h)) * 180 / M_PI, kAngle);
  EXPECT_NEAR(s.max_dihedral_deg, std::atan2(2 * std::sqrt(2.0) * h, 2 * h * h - 1) * 180 / M_PI, kAngle);
  EXPECT_NEAR(s.radius_edge_ratio, std::sqrt(0.5 + h * h / 4) / std::sqrt(1 + h * h), kTight);
  EXPECT_NEAR(s.min_dihedral_deg, 2.0, 0.01);
}

TEST(TetShape, VerdictMetricsInvariantUnderScaleAndRigidMotion) {
  const Vec3 p[4] = {{0.1, 0, 0}, {1, 0.2, 0}, {0.3, 1, 0.1}, {0.2, 0.3, 0.9}};
  const Eigen::Matrix3d rotation = Eigen::AngleAxisd(1.1, Vec3(-2, 1, 4).normalized()).toRotationMatrix();
  const TetShape a = tet_shape(p[0], p[1], p[2], p[3]);
  for (const double scale : {1e-3, 1.0, 1e3}) {
    auto moved = [&](const Vec3& x) -> Vec3 { return scale * (rotation * x) + Vec3(-7, 3, 11) * scale; };
    const TetShape b = tet_shape(moved(p[0]), moved(p[1]), moved(p[2]), moved(p[3]));
    // Ratios of products of differences: round-off of a few ulps per operation only.
    EXPECT_NEAR(b.scaled_jacobian, a.scaled_jacobian, 1e-12) << scale;
    EXPECT_NEAR(b.aspect_ratio, a.aspect_ratio, 1e-12 * a.aspect_ratio) << scale;
    EXPECT_NEAR(b.min_dihedral_deg, a.min_dihedral_deg, kAngle) << scale;
    EXPECT_NEAR(b.max_dihedral_deg, a.max_dihedral_deg, kAngle) << scale;
    EXPECT_NEAR(b.radius_edge_ratio, a.radius_edge_ratio, 1e-12 * a.radius_edge_ratio) << scale;
  }
}

TEST(TetShape, InvertedTetHasNegativeScaledJacobian) {
  // Two corners swapped: the same geometric tet, negative J. Verdict divides by the largest corner
  // product whatever the sign, so the figure is minus the positive tet's; the aspect ratio uses |V|.
  const TetShape regular = tet_shape({1, 1, 1}, {1, -1, -1}, {-1, 1, -1}, {-1, -1, 1});
  EXPECT_LT(regular.volume, 0);
  EXPECT_NEAR(regular.scaled_jacobian, -1.0, kTight);
  EXPECT_NEAR(regular.aspect_ratio, 1.0, kTight);
  const TetShape corner = tet_shape({0, 0, 0}, {0, 1, 0}, {1, 0, 0}, {0, 0, 1});
  EXPECT_NEAR(corner.scaled_jacobian, -std::sqrt(2.0) / 2.0, kTight);
  EXPECT_NEAR(corner.aspect_ratio, (1.0 + std::sqrt(3.0)) / 2.0, kTight);
}

TEST(TetShape, FlatAndCollapsedTets) {
  const TetShape flat = tet_shape({0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0});
  EXPECT_EQ(flat.scaled_jacobian, 0.0);
  EXPECT_TRUE(std::isinf(flat.aspect_ratio));
  const TetShape point = tet_shape({2, 2, 2}, {2, 2, 2}, {2, 2, 2}, {2, 2, 2});
  EXPECT_EQ(point.scaled_jacobian, 0.0);
  EXPECT_TRUE(std::isinf(point.aspect_ratio));
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
  // Verdict: J = 1 over the largest corner product 1 x sqrt2 x sqrt3 (at p0 and p3), times sqrt 2;
  // longest edge sqrt 3, faces' area 1/2 + 1/2 + 2 sqrt(2)/2, so sqrt(3)(1 + sqrt 2) / sqrt(6).
  EXPECT_NEAR(s.scaled_jacobian, 1.0 / std::sqrt(3.0), kTight);
  EXPECT_NEAR(s.aspect_ratio, 1.0 + 1.0 / std::sqrt(2.0), kTight);
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
  EXPECT_NEAR(r.scaled_jacobian.min, 1.0 / std::sqrt(3.0), kTight);
  EXPECT_NEAR(r.scaled_jacobian.max, 1.0 / std::sqrt(3.0), kTight);
  EXPECT_NEAR(r.aspect_ratio.p95, 1.0 + 1.0 / std::sqrt(2.0), kTight);
  EXPECT_EQ(r.min_dihedral_deg.count, r.tetrahedra);
  EXPECT_EQ(r.tets_min_dihedral_below_10, 0.0);
  // n even: the x < size/2 split is exact, half of the tets each.
  const std::map<int, std::size_t> regions{{1, 3 * n * n * n}, {2, 3 * n * n * n}};
  EXPECT_EQ(r.tets_per_region, regions);
  EXPECT_EQ(r.min_dihedral_per_tet.size(), r.tetrahedra);
  EXPECT_EQ(r.radius_edge_per_tet.size(), r.tetrahedra);
  EXPECT_EQ(r.scaled_jacobian_per_tet.size(), r.tetrahedra);
  EXPECT_EQ(r.aspect_ratio_per_tet.size(), r.tetrahedra);
  // All tets tie: the worst list is the first ten by index.
  ASSERT_EQ(r.worst_tets.size(), kDefaultWorstTets);
  for (std::size_t i = 0; i < r.worst_tets.size(); ++i) EXPECT_EQ(r.worst_tets[i].index, i);
}

TEST(TetQuality, FlatTetCountsAsInverted) {
  const TetQualityReport r = analyze_tet_quality(single_tet({0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}));
  EXPECT_EQ(r.inverted_tets, 1u);
  EXPECT_EQ(r.tets_min_dihedral_below_10, 1.0);
  EXPECT_EQ(r.radius_edge_ratio.count, 0u);  // the only value is +inf: ignored
  EXPECT_TRUE(std::isnan(r.radius_edge_ratio.max));
  EXPECT_TRUE(to_json(r)["radius_edge_ratio"]["max"].is_null());
  EXPECT_EQ(r.aspect_ratio.count, 0u);  // +inf too
  EXPECT_TRUE(to_json(r)["worst_tets"][0]["aspect_ratio"].is_null());
  EXPECT_EQ(r.scaled_jacobian.max, 0.0);
}

TEST(TetQuality, InvertedTetCounted) {
  TetMesh m = test::cube_tets(2);
  std::swap(m.tets[5][2], m.tets[5][3]);
  const TetQualityReport r = analyze_tet_quality(m);
  EXPECT_EQ(r.inverted_tets, 1u);
  EXPECT_NEAR(r.volume, 1.0 - 2.0 / 48.0, kTight);  // one tet of volume 1/48 counted negatively
  EXPECT_NEAR(r.scaled_jacobian.min, -1.0 / std::sqrt(3.0), kTight);  // the Kuhn tet's, negated
  EXPECT_NEAR(r.scaled_jacobian_per_tet[5], -1.0 / std::sqrt(3.0), kTight);
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

TEST(TetQuality, WorstTetsListTheSliverFirstWithItsCentre) {
  TetMesh m = test::cube_tets(1);  // 6 Kuhn tets: smallest dihedral 45 degrees
  const double h = 0.0175;         // the 2-degree sliver of SliverByHand, centred at (0.5, 0.5, h/2)
  for (const Vec3& p : {Vec3(0, 0, 0), Vec3(1, 1, 0), Vec3(0, 1, h), Vec3(1, 0, h)}) m.points.push_back(p);
  m.tets.push_back({8, 9, 10, 11});
  m.tet_regions.push_back(3);
  const TetQualityReport r = analyze_tet_quality(m, 3);
  ASSERT_EQ(r.worst_tets.size(), 3u);
  const WorstTet& w = r.worst_tets[0];
  EXPECT_EQ(w.index, 6u);
  EXPECT_EQ(w.region, 3);
  EXPECT_NEAR((w.centre - Vec3(0.5, 0.5, h / 2)).norm(), 0.0, kTight);
  EXPECT_NEAR(w.shape.min_dihedral_deg, r.min_dihedral_deg.min, 0.0);
  EXPECT_NEAR(w.shape.scaled_jacobian, 2 * h / (1 + h * h), kTight);
  EXPECT_EQ(r.worst_tets[1].index, 0u);  // then the tied Kuhn tets, by index
  EXPECT_EQ(r.worst_tets[2].index, 1u);
  EXPECT_EQ(analyze_tet_quality(m, 100).worst_tets.size(), 7u);  // no more than there are
  EXPECT_TRUE(analyze_tet_quality(m, 0).worst_tets.empty());
  const nlohmann::ordered_json j = to_json(r)["worst_tets"][0];
  EXPECT_EQ(j["index"], 6);
  EXPECT_EQ(j["centre"].size(), 3u);
  EXPECT_NEAR(j["centre"][2].get<double>(), h / 2, kTight);
  EXPECT_NEAR(j["min_dihedral_deg"].get<double>(), w.shape.min_dihedral_deg, 0.0);
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
  // The released keys first, in their order; the Verdict metrics and the worst tets after them.
  const std::vector<std::string> expected{"points",           "tetrahedra",       "volume",
                                          "inverted_tets",    "min_dihedral_deg", "max_dihedral_deg",
                                          "radius_edge_ratio", "tets_min_dihedral_below_10", "tets_per_region",
                                          "scaled_jacobian",  "aspect_ratio",     "worst_tets"};
  EXPECT_EQ(keys, expected);
  std::vector<std::string> worst_keys;
  for (const auto& item : j["worst_tets"][0].items()) worst_keys.push_back(item.key());
  EXPECT_EQ(worst_keys, (std::vector<std::string>{"index", "region", "centre", "min_dihedral_deg", "max_dihedral_deg",
                                                  "radius_edge_ratio", "scaled_jacobian", "aspect_ratio"}));
  for (const char* key : {"min", "mean", "p5", "p50", "p95", "max"}) {
    EXPECT_TRUE(j["scaled_jacobian"].contains(key));
    EXPECT_TRUE(j["aspect_ratio"].contains(key));
  }
  EXPECT_EQ(j["tets_per_region"]["1"], 24);
  EXPECT_EQ(j["tets_per_region"]["2"], 24);
  for (const char* key : {"min", "mean", "p5", "p50", "p95", "max"}) EXPECT_TRUE(j["min_dihedral_deg"].contains(key));
  EXPECT_NEAR(j["min_dihedral_deg"]["p5"].get<double>(), 45.0, kAngle);
}
