// The parameter descriptors (core/parameter.h): ranges as the command line, the configuration file
// and the stages check them, and every default inside its own range.
#include "meshprep/core/errors.h"
#include "meshprep/core/parameter.h"
#include "meshprep/fem/fem_parameters.h"
#include "meshprep/pipeline/pipeline_config.h"
#include "meshprep/preprocess/enhance/enhance_parameters.h"
#include "meshprep/preprocess/reconstruct/reconstruct_parameters.h"
#include "meshprep/preprocess/simplify/simplify_parameters.h"
#include "meshprep/preprocess/smooth/smooth_parameters.h"
#include "meshprep/quality/quality_parameters.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <utility>
#include <vector>

namespace meshprep {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

TEST(Range, EndsOpenOrClosed) {
  const Range half_open{0, 60, false, true};
  EXPECT_TRUE(half_open.contains(0));
  EXPECT_TRUE(half_open.contains(59.999));
  EXPECT_FALSE(half_open.contains(60));
  EXPECT_FALSE(half_open.contains(-1e-300));
  EXPECT_FALSE(half_open.contains(std::nan("")));
  EXPECT_EQ(half_open.text(), "[0, 60)");
  EXPECT_EQ((Range{0, 1, true, false}.text()), "(0, 1]");
  EXPECT_EQ((Range{1000, 100000000}.text()), "[1000, 100000000]");
}

TEST(Range, InfinityIsAValueOnlyAtAClosedEnd) {
  EXPECT_TRUE((Range{0, kInf}.contains(kInf)));
  EXPECT_EQ((Range{0, kInf}.text()), "[0, inf]");
  EXPECT_FALSE((Range{0, kInf, false, true}.contains(kInf)));
  EXPECT_EQ((Range{0, kInf, false, true}.text()), "[0, inf)");
}

TEST(Range, CheckNamesStageKeyRangeAndValue) {
  try {
    check_parameter("simplify", simplify_parameters().min_angle_deg, 60);
    FAIL() << "60 degrees passed";
  } catch (const InvalidInput& e) {
    EXPECT_STREQ(e.what(), "simplify: min_angle_deg must be in [0, 60), not 60");
  }
  EXPECT_NO_THROW(check_parameter("simplify", simplify_parameters().min_angle_deg, 59.5));
}

// A default outside its own range would make the default configuration unreadable when written back.
TEST(Parameters, EveryDefaultLiesInItsRange) {
  const ReconstructParams reconstruct;
  const SimplifyParams simplify;
  const SmoothParams smooth;
  const EnhanceParams enhance;
  const QualityParams quality;
  const TetParams tets;
  const ImproveParams improve;
  const TetThresholds verdict;
  const ReconstructParameters& r = reconstruct_parameters();
  const SimplifyParameters& s = simplify_parameters();
  const SmoothParameters& m = smooth_parameters();
  const EnhanceParameters& e = enhance_parameters();
  const TetParameters& t = tet_parameters();
  const ImproveParameters& i = improve_parameters();
  const VerdictParameters& v = verdict_parameters();
  const std::vector<std::pair<const ParameterInfo*, double>> defaults = {
      {&r.resolution, static_cast<double>(reconstruct.columns)},
      {&r.resolution, static_cast<double>(reconstruct.rows)},
      {&r.spacing, reconstruct.spacing},
      {&r.vertices, static_cast<double>(reconstruct.vertices)},
      {&r.leaf_size, static_cast<double>(reconstruct.fit.leaf_size)},
      {&r.neighbors, static_cast<double>(reconstruct.fit.neighbors)},
      {&r.variation_growth, reconstruct.fit.variation_growth},
      {&r.max_gap, reconstruct.max_gap},
      {&s.keep_ratio, simplify.keep_ratio},
      {&s.target_faces, static_cast<double>(simplify.target_faces)},
      {&s.min_angle_deg, simplify.min_angle_deg},
      {&s.max_error, simplify.max_error},
      {&m.iterations, static_cast<double>(smooth.iterations)},
      {&m.neighbors, static_cast<double>(smooth.neighbors)},
      {&m.smoothing, smooth.smoothing},
      {&m.relaxation, smooth.relaxation},
      {&m.feature_angle_deg, smooth.feature_angle_deg},
      {&e.iterations, static_cast<double>(enhance.iterations)},
      {&e.max_deviation, EnhanceParams::kLargestAutoDeviation},
      {&e.target_min_angle_deg, enhance.target_min_angle_deg},
      {&e.feature_angle_deg, enhance.feature_angle_deg},
      {&e.time_limit_seconds, enhance.time_limit_seconds},
      {&quality_parameters().distance_samples, static_cast<double>(quality.distance_samples)},
      {&quality_parameters().distance_samples, static_cast<double>(PipelineConfig().quality.params.distance_samples)},
      {&t.radius_edge, tets.radius_edge},
      {&t.min_dihedral_deg, tets.min_dihedral_deg},
      {&t.max_volume_relative, tets.max_volume_relative},
      {&i.goal_min_dihedral_deg, improve.goal_min_dihedral_deg},
      {&i.goal_max_dihedral_deg, improve.goal_max_dihedral_deg},
      {&i.max_passes, static_cast<double>(improve.max_passes)},
      {&i.time_limit_seconds, improve.time_limit_seconds},
      {&v.min_dihedral_deg, verdict.min_dihedral_deg},
      {&v.max_dihedral_deg, verdict.max_dihedral_deg},
      {&v.max_inverted_tets, static_cast<double>(verdict.max_inverted_tets)}};
  for (const auto& [info, value] : defaults)
    EXPECT_TRUE(info->range.contains(value)) << info->key << " = " << value << " outside " << info->range.text();
}

// The configuration file reads the same range as the command line and the stage: an angle bound
// just under 60 degrees is accepted everywhere, 60 nowhere.
TEST(Parameters, ConfigurationKeysUseTheStageRange) {
  PipelineConfig config;
  apply_config(nlohmann::json::parse(R"({"simplify": {"min_angle_deg": 59.5}})"), "c.json", config);
  EXPECT_EQ(config.simplify.params.min_angle_deg, 59.5);
  EXPECT_THROW(apply_config(nlohmann::json::parse(R"({"simplify": {"min_angle_deg": 60}})"), "c.json", config),
               InvalidInput);
  EXPECT_THROW(apply_config(nlohmann::json::parse(R"({"improve": {"goal_max_dihedral_deg": 180}})"), "c.json", config),
               InvalidInput);
}

}  // namespace
}  // namespace meshprep
