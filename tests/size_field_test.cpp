// The size field (core/size_field.h): the closed form of gradient limiting, h(x) = min over
// demands of h_s + (G - 1) |x - s|, clamped; and the lengths users write ("0.5", "2%").
#include "meshprep/core/errors.h"
#include "meshprep/core/size_field.h"
#include "meshprep/core/size_parameters.h"
#include "meshprep/core/user_size_demands.h"
#include "test_meshes.h"

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

// A region asks for its length inside it and grows by the grading outside, as a point does.
TEST(SizeField, ARegionHoldsInsideAndIsGradedOutside) {
  SizeRegion box;
  box.lo = Vec3(0, 0, 0);
  box.hi = Vec3(1, 2, 3);
  SizeRegion ball;
  ball.shape = SizeRegion::Shape::sphere;
  ball.center = Vec3(10, 0, 0);
  ball.radius = 1;
  EXPECT_EQ(box.distance(Vec3(0.5, 1, 2)), 0);
  EXPECT_DOUBLE_EQ(box.distance(Vec3(4, 2.5, 3)), std::hypot(3.0, 0.5));
  EXPECT_EQ(ball.distance(Vec3(10.5, 0, 0)), 0);
  EXPECT_DOUBLE_EQ(ball.distance(Vec3(10, 3, 0)), 2);
  const SizeField field({}, 1.0, 1.3, 0, {{box, 0.1}, {ball, 0.2}});
  EXPECT_DOUBLE_EQ(field(Vec3(0.5, 1, 2)), 0.1);
  EXPECT_DOUBLE_EQ(field(Vec3(1.5, 1, 2)), 0.1 + 0.3 * 0.5);
  EXPECT_DOUBLE_EQ(field(Vec3(10, 0, 1.5)), 0.2 + 0.3 * 0.5);
  EXPECT_DOUBLE_EQ(field(Vec3(5, 10, 0)), 1.0);
  EXPECT_EQ(field.regions(), 2u);
  EXPECT_DOUBLE_EQ(field.shortest(), 0.1);
}

// A patch's size covers its faces (the field there within (1 + (G - 1) / 4) of it: the demands
// are no farther apart than half the size) and not the others' beyond the grading; a name is
// matched without regard to case, and an unknown one is named with the surface's.
TEST(SizeField, APatchSizeCoversItsFacesOnly) {
  TriangleSoup cube = test::cube(1.0);
  cube.patches.assign(cube.triangles.size(), 2);
  cube.patch_names = {{1, "Top"}, {2, "rest"}};
  for (std::size_t f = 0; f < cube.triangles.size(); ++f) {
    bool top = true;
    for (const auto v : cube.triangles[f]) top = top && cube.points[v].z() == 1;
    if (top) cube.patches[f] = 1;
  }
  SizeParams params;
  params.size = Length{0.5, false};
  params.patch_sizes["top"] = Length{0.05, false};
  const auto field = user_size_field(params, cube);
  ASSERT_TRUE(field);
  std::mt19937 random(7);
  std::uniform_real_distribution<double> unit(0, 1);
  for (int i = 0; i < 200; ++i) {
    const Vec3 on_top(unit(random), unit(random), 1);
    EXPECT_LE((*field)(on_top), 0.05 * (1 + 0.3 / 4) + 1e-12) << on_top.transpose();
    EXPECT_GE((*field)(on_top), 0.05);
    const Vec3 on_bottom(unit(random), unit(random), 0);
    EXPECT_GE((*field)(on_bottom), 0.05 + 0.3 * 1.0);  // one unit from the top
    EXPECT_NEAR((*field)(on_bottom), 0.05 + 0.3 * 1.0, 0.3 * 1e-3);
  }
  params.patch_sizes = {{"tpo", Length{0.05, false}}};
  try {
    user_size_field(params, cube);
    ADD_FAILURE() << "an unknown patch was taken";
  } catch (const InvalidInput& e) {
    EXPECT_EQ(std::string(e.what()), "size: no patch named 'tpo' (the surface's patches: Top, rest)");
  }
}

// Without a size, the user's field follows the surface's own density (Gmsh's default): finer
// where its faces are, graded into the volume; with nothing set there is no field.
TEST(SizeField, WithoutASizeTheSurfacesDensityHolds) {
  const TriangleSoup fine = test::subdivided_cube(8);  // edges 1 and sqrt 2 on a cube of side 8
  SizeParams params;
  EXPECT_FALSE(user_size_field(params, fine));
  params.size_max = Length{3, false};
  const auto field = user_size_field(params, fine);
  ASSERT_TRUE(field);
  const double mean_edge = (2 + std::sqrt(2.0)) / 3;
  EXPECT_NEAR((*field)(Vec3(0.5, 0.5, 0)), mean_edge + 0.3 * std::sqrt(2.0) / 6, 1e-9);  // a face's centroid is 1/3 off
  EXPECT_DOUBLE_EQ((*field)(Vec3(4, 4, 30)), 3.0);  // capped by size_max far away
  params.curvature_points = 12;  // the surface's demand: the enhancement's, none here
  params.size_max.reset();
  EXPECT_FALSE(user_size_field(params, fine));
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
  p = SizeParams();
  p.patch_sizes["1st"] = Length{0.1, false};
  EXPECT_THROW(check_size_params(p), InvalidInput);
  EXPECT_TRUE(p.any_set());
  p = SizeParams();
  SizeRegion region;
  region.lo = Vec3(0, 0, 0);
  region.hi = Vec3(1, -1, 1);
  region.size = Length{0.1, false};
  p.regions = {region};
  EXPECT_THROW(check_size_params(p), InvalidInput);
  p.regions[0].shape = SizeRegion::Shape::sphere;
  EXPECT_THROW(check_size_params(p), InvalidInput);  // radius 0
  p.regions[0].radius = 1;
  EXPECT_NO_THROW(check_size_params(p));
}

}  // namespace
}  // namespace meshprep
