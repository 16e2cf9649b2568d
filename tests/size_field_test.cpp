// The size field (core/size_field.h): the closed form of gradient limiting, h(x) = min over
// demands of h_s + (G - 1) |x - s|, clamped; and the lengths users write ("0.5", "2%").
#include "meshprep/core/errors.h"
#include "meshprep/core/size_field.h"
#include "meshprep/core/size_parameters.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

namespace meshprep {
namespace {

TEST(SizeField, WithoutDemandsIsTheLongestLengthEverywhere) {
  const SizeField field({}, 2.5, 1.3);
  EXPECT_EQ(field(Vec3(0, 0, 0)), 2.5);
  EXPECT_EQ(field(Vec3(1e6, -3, 7)), 2.5);
  EXPECT_EQ(field.demands(), 0u);
}

TEST(SizeField, OneDemandGrowsByTheGradingLessOnePerUnitOfDistance) {
  const SizeField field({{Vec3(0, 0, 0), 0.1}}, 1.0, 1.3);
  EXPECT_DOUBLE_EQ(field(Vec3(0, 0, 0)), 0.1);
  EXPECT_DOUBLE_EQ(field(Vec3(1, 0, 0)), 0.1 + 0.3);
  EXPECT_DOUBLE_EQ(field(Vec3(0, 2, 0)), 0.1 + 0.6);
  EXPECT_DOUBLE_EQ(field(Vec3(0, 0, 10)), 1.0);  // capped at the longest
}

TEST(SizeField, DemandsAtOrOverTheLongestChangeNothing) {
  const SizeField field({{Vec3(0, 0, 0), 3.0}}, 1.0, 1.3);
  EXPECT_EQ(field.demands(), 0u);
  EXPECT_EQ(field(Vec3(0, 0, 0)), 1.0);
}

TEST(SizeField, TheFloorHoldsUnderEveryDemand) {
  const SizeField field({{Vec3(0, 0, 0), 1e-6}}, 1.0, 1.5, 0.01);
  EXPECT_DOUBLE_EQ(field(Vec3(0, 0, 0)), 0.01);
  EXPECT_DOUBLE_EQ(field.shortest(), 0.01);
  EXPECT_DOUBLE_EQ(field(Vec3(1, 0, 0)), 0.01 + 0.5);  // the demand grows from the floor
}

TEST(SizeField, GradingOneMakesTheSmallestDemandHoldEverywhere) {
  const SizeField field({{Vec3(0, 0, 0), 0.2}, {Vec3(5, 0, 0), 0.4}}, 1.0, 1.0);
  EXPECT_DOUBLE_EQ(field(Vec3(100, 0, 0)), 0.2);
}

// The levels' pruned search (each level searched only as far as it can still win) against the
// minimum over every demand, on demands whose lengths span six levels; and the gradient bound
// |h(x) - h(y)| <= (G - 1) |x - y| that gradient limiting promises.
TEST(SizeField, EqualsTheMinimumOverAllDemandsAndIsLipschitzInTheGrading) {
  std::mt19937 random(49);
  std::uniform_real_distribution<double> coordinate(-1, 1), exponent(-6, 0);
  std::vector<SizeDemand> demands;
  for (int i = 0; i < 2000; ++i)
    demands.push_back({Vec3(coordinate(random), coordinate(random), coordinate(random)), 0.5 * std::exp2(exponent(random))});
  const double longest = 0.4, grading = 1.3;
  const SizeField field(demands, longest, grading);
  for (int i = 0; i < 500; ++i) {
    const Vec3 x(1.5 * coordinate(random), 1.5 * coordinate(random), 1.5 * coordinate(random));
    double expected = longest;
    for (const SizeDemand& d : demands) expected = std::min(expected, d.length + (grading - 1) * (x - d.point).norm());
    ASSERT_DOUBLE_EQ(field(x), expected) << "at " << x.transpose();
    const Vec3 y = x + 0.05 * Vec3(coordinate(random), coordinate(random), coordinate(random));
    EXPECT_LE(std::abs(field(x) - field(y)), (grading - 1) * (x - y).norm() * (1 + 1e-12));
  }
}

TEST(SizeField, ScaledAndMoved) {
  SizeField field({{Vec3(0, 0, 0), 0.1}}, 1.0, 1.5);
  field.scale(2);
  EXPECT_DOUBLE_EQ(field(Vec3(0, 0, 0)), 0.2);
  EXPECT_DOUBLE_EQ(field.longest(), 2.0);
  field.move(Vec3(10, 0, 0));
  EXPECT_DOUBLE_EQ(field(Vec3(10, 0, 0)), 0.2);
  EXPECT_DOUBLE_EQ(field(Vec3(11, 0, 0)), 2 * (0.1 + 0.5));
}

TEST(SizeField, BoundsOutOfRangeAreRefused) {
  EXPECT_THROW(SizeField({}, 0, 1.3), InvalidInput);
  EXPECT_THROW(SizeField({}, INFINITY, 1.3), InvalidInput);
  EXPECT_THROW(SizeField({}, 1, 0.9), InvalidInput);
  EXPECT_THROW(SizeField({}, 1, 1.3, 2), InvalidInput);
}

TEST(Length, AbsoluteOrAPercentageOfTheDiagonal) {
  const Length absolute = parse_length("0.5", "--size");
  EXPECT_FALSE(absolute.relative);
  EXPECT_EQ(absolute.resolved(10), 0.5);
  const Length relative = parse_length("2%", "--size");
  EXPECT_TRUE(relative.relative);
  EXPECT_DOUBLE_EQ(relative.resolved(10), 0.2);
  EXPECT_EQ(length_text(relative), "2%");
  EXPECT_EQ(length_text(absolute), "0.5");
  for (const char* bad : {"", "%", "0", "-1", "abc", "2%%", "1e999", "nan"}) {
    try {
      parse_length(bad, "--size");
      ADD_FAILURE() << "'" << bad << "' was taken";
    } catch (const InvalidInput& e) {
      EXPECT_NE(std::string(e.what()).find("--size: expected a positive length"), std::string::npos) << e.what();
    }
  }
}

TEST(SizeParams, CheckedAgainstTheirRanges) {
  EXPECT_NO_THROW(check_size_params(SizeParams()));
  SizeParams p;
  p.grading = 0.5;
  EXPECT_THROW(check_size_params(p), InvalidInput);
  p = SizeParams();
  p.size_min = Length{2, false};
  p.size_max = Length{1, false};
  EXPECT_THROW(check_size_params(p), InvalidInput);
  p = SizeParams();
  p.curvature_points = 0;
  EXPECT_THROW(check_size_params(p), InvalidInput);
  EXPECT_FALSE(SizeParams().any_set());
  EXPECT_EQ(SizeParams().grading_used(), kSurfaceGrading);
  p = SizeParams();
  p.size = Length{0.02, true};
  EXPECT_TRUE(p.any_set());
  EXPECT_EQ(p.grading_used(), kSizeGrading);
  p.grading = 1.1;
  EXPECT_EQ(p.grading_used(), 1.1);
}

}  // namespace
}  // namespace meshprep
