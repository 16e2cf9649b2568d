#include "meshprep/fem/fem_verdict.h"
#include "tet_test_meshes.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace meshprep;

namespace {

// cube_tets(2) and, as tet 48, the 2-degree sliver of tet_quality_test's SliverByHand: smallest
// dihedral atan(2h sqrt(1 + h^2)) = 2.0048 deg, largest 177.16 deg (region 3).
TetMesh cube_with_sliver() {
  TetMesh m = test::cube_tets(2);
  const double h = 0.0175;
  const auto first = static_cast<std::uint32_t>(m.points.size());
  for (const Vec3& p : {Vec3(0, 0, 0), Vec3(1, 1, 0), Vec3(0, 1, h), Vec3(1, 0, h)}) m.points.push_back(p);
  m.tets.push_back({first, first + 1, first + 2, first + 3});
  m.tet_regions.push_back(3);
  return m;
}

}  // namespace

TEST(FemVerdict, DefaultsAreTheDocumentedOnes) {
  const TetThresholds t;
  EXPECT_EQ(t.min_dihedral_deg, 10.0);
  EXPECT_EQ(t.max_dihedral_deg, 165.0);
  EXPECT_EQ(t.max_inverted_tets, 0u);
}

TEST(FemVerdict, KuhnTetsPassEveryThreshold) {
  const TetVerdict v = judge_tets(analyze_tet_quality(test::cube_tets(2)));
  ASSERT_EQ(v.checks.size(), 3u);
  EXPECT_TRUE(v.ok());
  EXPECT_TRUE(v.failed().empty());
  EXPECT_EQ(v.checks[0].check, "min_dihedral_deg");
  EXPECT_NEAR(v.checks[0].value, 45.0, 1e-10);
  EXPECT_EQ(v.checks[0].threshold, 10.0);
  EXPECT_EQ(v.checks[1].check, "max_dihedral_deg");
  EXPECT_NEAR(v.checks[1].value, 90.0, 1e-10);
  EXPECT_EQ(v.checks[2].check, "max_inverted_tets");
  EXPECT_EQ(v.checks[2].value, 0.0);
  EXPECT_EQ(describe(v.checks[1]), "largest dihedral angle 90 deg <= 165 deg (max_dihedral_deg)");
  EXPECT_EQ(requirement(v.checks[0]), "smallest dihedral angle >= 10 deg");
  EXPECT_EQ(requirement(v.checks[2]), "inverted tets <= 0");
}

TEST(FemVerdict, OneTwoDegreeSliverFailsBothAngleThresholds) {
  const TetQualityReport q = analyze_tet_quality(cube_with_sliver());
  const TetVerdict v = judge_tets(q);
  EXPECT_FALSE(v.ok());
  const std::vector<ThresholdCheck> failed = v.failed();
  ASSERT_EQ(failed.size(), 2u);
  EXPECT_EQ(failed[0].check, "min_dihedral_deg");
  EXPECT_NEAR(failed[0].value, 2.0048, 1e-4);
  EXPECT_EQ(failed[1].check, "max_dihedral_deg");
  EXPECT_NEAR(failed[1].value, 177.16, 1e-2);
  EXPECT_TRUE(v.checks[2].ok);
  EXPECT_EQ(describe(failed[0]), "smallest dihedral angle 2.005 deg < 10 deg (min_dihedral_deg)");
  EXPECT_EQ(describe(failed[1]), "largest dihedral angle 177.2 deg > 165 deg (max_dihedral_deg)");
  // The worst tet the report lists is the one that fails.
  ASSERT_FALSE(q.worst_tets.empty());
  EXPECT_EQ(q.worst_tets[0].index, 48u);
}

TEST(FemVerdict, ThresholdsAreInclusiveAndAdjustable) {
  const TetQualityReport q = analyze_tet_quality(cube_with_sliver());
  TetThresholds t;
  t.min_dihedral_deg = q.min_dihedral_deg.min;  // a figure equal to its threshold holds
  t.max_dihedral_deg = q.max_dihedral_deg.max;
  EXPECT_TRUE(judge_tets(q, t).ok());
  t.min_dihedral_deg = std::nextafter(q.min_dihedral_deg.min, 90.0);
  EXPECT_FALSE(judge_tets(q, t).checks[0].ok);
  t = TetThresholds{0, 180, 0};  // every angle allowed
  EXPECT_TRUE(judge_tets(q, t).ok());
}

TEST(FemVerdict, InvertedTetsAreCountedAgainstTheirThreshold) {
  TetMesh m = test::cube_tets(2);
  std::swap(m.tets[5][2], m.tets[5][3]);
  const TetQualityReport q = analyze_tet_quality(m);
  const TetVerdict v = judge_tets(q);
  ASSERT_EQ(v.failed().size(), 1u);  // the angles are those of the geometric tet: they pass
  EXPECT_EQ(v.failed()[0].check, "max_inverted_tets");
  EXPECT_EQ(describe(v.failed()[0]), "inverted tets 1 > 0 (max_inverted_tets)");
  TetThresholds one;
  one.max_inverted_tets = 1;
  EXPECT_TRUE(judge_tets(q, one).ok());
}

TEST(FemVerdict, NoTetsIsNotReady) {
  const TetVerdict v = judge_tets(analyze_tet_quality(TetMesh{}));
  EXPECT_FALSE(v.ok());
  EXPECT_EQ(v.failed().size(), 2u);  // the two angles; no tet is inverted
  EXPECT_EQ(describe(v.checks[0]), "smallest dihedral angle undefined (no tets) < 10 deg (min_dihedral_deg)");
  EXPECT_TRUE(to_json(v.checks[0])["value"].is_null());
}

TEST(FemVerdict, Json) {
  const nlohmann::ordered_json j = to_json(judge_tets(analyze_tet_quality(cube_with_sliver())));
  ASSERT_TRUE(j.is_array());
  ASSERT_EQ(j.size(), 3u);
  std::vector<std::string> keys;
  for (const auto& item : j[0].items()) keys.push_back(item.key());
  EXPECT_EQ(keys, (std::vector<std::string>{"check", "threshold", "value", "ok"}));
  EXPECT_EQ(j[0]["check"], "min_dihedral_deg");
  EXPECT_EQ(j[0]["threshold"], 10.0);
  EXPECT_NEAR(j[0]["value"].get<double>(), 2.0048, 1e-4);
  EXPECT_EQ(j[0]["ok"], false);
  EXPECT_EQ(j[2]["ok"], true);
}
