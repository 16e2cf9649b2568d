#include "meshprep/quality/quality_gate.h"

#include "meshprep/core/errors.h"

#include <gtest/gtest.h>

#include <string>

using namespace meshprep;

namespace {
nlohmann::ordered_json sample_report() {
  return nlohmann::ordered_json::parse(R"({"closed": true, "faces_min_angle_below_20": 0.08,
      "radius_ratio": {"p95": 2.5}, "volume": null, "reference": null})");
}
}  // namespace

TEST(QualityGate, ReportsConditionsThatHold) {
  const auto gate = parse_quality_gate("radius_ratio.p95>3, faces_min_angle_below_20>0.05,closed=false");
  ASSERT_EQ(gate.size(), 3u);
  const auto failed = failed_conditions(gate, sample_report());
  ASSERT_EQ(failed.size(), 1u);
  EXPECT_EQ(failed[0].text, "faces_min_angle_below_20>0.05");
}

TEST(QualityGate, OperatorsAndFlags) {
  const auto r = sample_report();
  EXPECT_EQ(failed_conditions(parse_quality_gate("radius_ratio.p95>=2.5"), r).size(), 1u);
  EXPECT_EQ(failed_conditions(parse_quality_gate("radius_ratio.p95<=2.4"), r).size(), 0u);
  EXPECT_EQ(failed_conditions(parse_quality_gate("radius_ratio.p95!=2.5"), r).size(), 0u);
  EXPECT_EQ(failed_conditions(parse_quality_gate("closed!=false"), r).size(), 1u);
}

TEST(QualityGate, NullValuesNeverHold) {
  EXPECT_TRUE(failed_conditions(parse_quality_gate("volume<0,reference.hausdorff_relative>0.01"), sample_report()).empty());
}

TEST(QualityGate, BadSpecificationsAreInvalidInput) {
  EXPECT_THROW(parse_quality_gate("radius_ratio.p95"), InvalidInput);
  EXPECT_THROW(parse_quality_gate("radius_ratio.p95>abc"), InvalidInput);
  // NaN compares false with everything: "p95>nan" would never hold, whatever the mesh (issue 30).
  for (const char* value : {"nan", "-nan", "inf", "-inf", "infinity"})
    EXPECT_THROW(parse_quality_gate(std::string("radius_ratio.p95>") + value), InvalidInput) << value;
  EXPECT_THROW(parse_quality_gate(" , "), InvalidInput);
  EXPECT_THROW(failed_conditions(parse_quality_gate("no_such_key>1"), sample_report()), InvalidInput);
  EXPECT_THROW(failed_conditions(parse_quality_gate("closed>1"), sample_report()), InvalidInput);
}
