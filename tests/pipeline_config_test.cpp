#include "meshprep/pipeline/pipeline_config.h"

#include "meshprep/core/errors.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>

namespace meshprep {
namespace {

using Json = nlohmann::json;

std::string error_of(const Json& json) {
  PipelineConfig config;
  try {
    apply_config(json, "c.json", config);
  } catch (const InvalidInput& e) {
    return e.what();
  }
  return "";
}

TEST(PipelineConfig, DefaultsAreTheStagesOwnWhereTheHeaderSaysSo) {
  const PipelineConfig c;
  EXPECT_EQ(c.simplify.params.min_angle_deg, SimplifyParams().min_angle_deg);
  EXPECT_EQ(c.enhance.params.tail_k, EnhanceParams().tail_k);
  EXPECT_EQ(c.tetrahedralize.params.radius_edge, TetParams().radius_edge);
  EXPECT_EQ(c.verdict.min_dihedral_deg, TetThresholds().min_dihedral_deg);
  EXPECT_EQ(c.verdict.max_dihedral_deg, TetThresholds().max_dihedral_deg);
  EXPECT_EQ(c.verdict.max_inverted_tets, TetThresholds().max_inverted_tets);
  EXPECT_EQ(c.reconstruct.params.fit.neighbors, PartitionOfUnityParams().neighbors);
  // The pipeline's own choices (pipeline_config.h says why).
  EXPECT_TRUE(c.reconstruct.params.fill_holes);
  EXPECT_FALSE(c.smooth.enabled);
  EXPECT_TRUE(c.smooth.params.preserve_volume);
  EXPECT_FALSE(c.simplify.ratio.has_value());
  EXPECT_EQ(c.quality.params.distance_samples, 200000u);
  EXPECT_FALSE(EnhanceParams().max_deviation.has_value());  // enhance: the input's own distance
  EXPECT_EQ(c.enhance.params.max_deviation, 2e-3);
}

TEST(PipelineConfig, TheEffectiveConfigurationReadsBackToItself) {
  PipelineConfig changed;
  apply_config(Json::parse(R"({"simplify": {"ratio": 0.25, "cost": "distance"},
                               "smooth": {"enabled": true, "method": "taubin", "iterations": 3},
                               "reconstruct": {"resolution": [120, 80], "variation_threshold": 0.3},
                               "tetrahedralize": {"format": "inp", "msh_version": "2.2", "extrude_base": 5},
                               "verdict": {"min_dihedral_deg": 15, "max_dihedral_deg": 160, "max_inverted_tets": 2}})"),
               "c.json", changed);
  EXPECT_EQ(changed.verdict.min_dihedral_deg, 15.0);
  EXPECT_EQ(changed.verdict.max_dihedral_deg, 160.0);
  EXPECT_EQ(changed.verdict.max_inverted_tets, 2u);
  EXPECT_EQ(*changed.simplify.ratio, 0.25);
  EXPECT_EQ(changed.simplify.params.cost, CollapseCost::Distance);
  EXPECT_EQ(changed.smooth.params.method, SmoothMethod::Taubin);
  EXPECT_EQ(changed.reconstruct.params.columns, 120u);
  EXPECT_EQ(changed.reconstruct.params.rows, 80u);
  EXPECT_EQ(changed.reconstruct.params.fit.variation_percentile, -1);  // a fixed threshold
  EXPECT_EQ(changed.reconstruct.params.fit.variation_threshold, 0.3);
  EXPECT_EQ(changed.tetrahedralize.export_options.msh_version, MshVersion::V22);
  const nlohmann::ordered_json written = to_json(changed);
  PipelineConfig again;
  apply_config(Json::parse(written.dump()), "again.json", again);
  EXPECT_EQ(to_json(again), written);
  EXPECT_NE(to_json(PipelineConfig()), written);
}

TEST(PipelineConfig, EveryKeyIsDescribedAndWrittenOnce) {
  const nlohmann::ordered_json json = to_json(PipelineConfig());
  std::set<std::string> written;
  for (const auto& [section, keys] : json.items())
    for (const auto& item : keys.items()) written.insert(section + "." + item.key());
  std::set<std::string> described;
  for (const ConfigKeyDoc& doc : describe_config()) {
    EXPECT_FALSE(doc.type.empty()) << doc.key;
    EXPECT_FALSE(doc.description.empty()) << doc.key;
    EXPECT_TRUE(described.insert(doc.key).second) << "twice: " << doc.key;
  }
  EXPECT_EQ(described, written);
}

TEST(PipelineConfig, DocsListEveryKey) {
  std::ifstream in(MESHPREP_DOCS_DIR "/pipeline.md");
  ASSERT_TRUE(in) << "docs/pipeline.md";
  std::stringstream docs;
  docs << in.rdbuf();
  for (const ConfigKeyDoc& doc : describe_config())
    EXPECT_NE(docs.str().find("`" + doc.key + "`"), std::string::npos) << doc.key << " is not in docs/pipeline.md";
}

TEST(PipelineConfig, RepairIsOffByDefaultAndReadsItsTolerance) {
  PipelineConfig c;
  EXPECT_FALSE(c.repair.enabled);
  apply_config(Json::parse(R"({"repair": {"enabled": true, "weld_tolerance": 0.01}})"), "c.json", c);
  EXPECT_TRUE(c.repair.enabled);
  EXPECT_EQ(c.repair.params.weld_tolerance, 0.01);
  EXPECT_THROW(apply_config(Json::parse(R"({"repair": {"weld_tolerance": 0.5}})"), "c.json", c), InvalidInput);
}

TEST(PipelineConfig, UnknownSectionsAndKeysNameTheValidOnes) {
  EXPECT_EQ(error_of(Json::parse(R"({"simplfy": {}})")),
            "c.json: unknown section 'simplfy'; valid sections: repair, reconstruct, patches, simplify, smooth, size, enhance, "
            "knife_edges, quality, tetrahedralize, improve, verdict");
  const std::string key = error_of(Json::parse(R"({"simplify": {"ratoi": 0.5}})"));
  EXPECT_EQ(key.rfind("c.json: unknown key 'simplify.ratoi'; valid keys of simplify: enabled, ratio, target_faces", 0), 0u)
      << key;
}

// Lengths are absolute numbers or percentages of the diagonal; unset is "auto".
TEST(PipelineConfig, SizesAreLengthsOrPercentagesAndReadBack) {
  PipelineConfig changed;
  apply_config(Json::parse(R"({"size": {"size": "2%", "size_min": 0.5, "grading": 1.2, "curvature_points": 12}})"),
               "c.json", changed);
  ASSERT_TRUE(changed.size.size && changed.size.size_min);
  EXPECT_TRUE(changed.size.size->relative);
  EXPECT_DOUBLE_EQ(changed.size.size->value, 0.02);
  EXPECT_FALSE(changed.size.size_min->relative);
  EXPECT_EQ(*changed.size.grading, 1.2);
  EXPECT_EQ(*changed.size.curvature_points, 12.0);
  EXPECT_FALSE(changed.size.size_max);
  const nlohmann::ordered_json written = to_json(changed);
  EXPECT_EQ(written["size"]["size"], "2%");
  EXPECT_EQ(written["size"]["size_max"], "auto");
  PipelineConfig again;
  apply_config(Json::parse(written.dump()), "again.json", again);
  EXPECT_EQ(to_json(again), written);
  EXPECT_NE(error_of(Json::parse(R"({"size": {"size": "big"}})")).find("size.size: expected a positive number, \"N%\""),
            std::string::npos);
  EXPECT_NE(error_of(Json::parse(R"({"size": {"size": -1}})")).find("size.size: expected"), std::string::npos);
  EXPECT_NE(error_of(Json::parse(R"({"size": {"grading": 0.9}})")).find("size.grading"), std::string::npos);
  EXPECT_NE(error_of(Json::parse(R"({"size": {"size_min": 2, "size_max": 1}})")).find("size_min (2) is over size_max (1)"),
            std::string::npos);
}

// A patch's size and the regions' are read, checked and written back as given.
TEST(PipelineConfig, PatchAndRegionSizesReadBack) {
  PipelineConfig changed;
  apply_config(Json::parse(R"({"size": {"patches": {"load_face": "0.1%", "fixed": 0.2},
                                         "regions": [{"box": [0, 0, 0, 1, 2, 3], "size": 0.05},
                                                     {"sphere": [1, 1, 1, 0.5], "size": "0.2%"}]}})"),
               "c.json", changed);
  ASSERT_EQ(changed.size.patch_sizes.size(), 2u);
  EXPECT_TRUE(changed.size.patch_sizes.at("load_face").relative);
  EXPECT_DOUBLE_EQ(changed.size.patch_sizes.at("load_face").value, 0.001);
  EXPECT_EQ(changed.size.patch_sizes.at("fixed").value, 0.2);
  ASSERT_EQ(changed.size.regions.size(), 2u);
  EXPECT_EQ(changed.size.regions[0].hi, Vec3(1, 2, 3));
  EXPECT_EQ(changed.size.regions[1].shape, SizeRegion::Shape::sphere);
  EXPECT_EQ(changed.size.regions[1].radius, 0.5);
  EXPECT_TRUE(changed.size.any_set());
  const nlohmann::ordered_json written = to_json(changed);
  EXPECT_EQ(written["size"]["patches"]["load_face"], "0.1%");
  EXPECT_EQ(written["size"]["regions"][1]["size"], "0.2%");
  PipelineConfig again;
  apply_config(Json::parse(written.dump()), "again.json", again);
  EXPECT_EQ(to_json(again), written);
  EXPECT_NE(error_of(Json::parse(R"({"size": {"patches": {"top": "big"}}})")).find("size.patches: the size of 'top'"),
            std::string::npos);
  EXPECT_NE(error_of(Json::parse(R"({"size": {"patches": {"1st": 0.1}}})")).find("'1st' is no patch name"),
            std::string::npos);
  EXPECT_NE(error_of(Json::parse(R"({"size": {"regions": [{"sphere": [0, 0, 0], "size": 1}]}})")).find("size.regions: expected"),
            std::string::npos);
  EXPECT_NE(error_of(Json::parse(R"({"size": {"regions": [{"box": [0, 0, 0, 1, -1, 1], "size": 1}]}})")).find("lower corner"),
            std::string::npos);
}

// The goals' preset sets the goals; written back, the goals say which preset they are.
TEST(PipelineConfig, TheTetQualityPresetSetsTheGoals) {
  PipelineConfig high;
  apply_config(Json::parse(R"({"improve": {"tet_quality": "high"}})"), "c.json", high);
  EXPECT_EQ(high.improve.params.goal_min_dihedral_deg, 20);
  EXPECT_EQ(high.improve.params.goal_max_dihedral_deg, 150);
  EXPECT_EQ(to_json(high)["improve"]["tet_quality"], "high");
  PipelineConfig custom;
  apply_config(Json::parse(R"({"improve": {"tet_quality": "high", "goal_min_dihedral_deg": 18}})"), "c.json", custom);
  EXPECT_EQ(custom.improve.params.goal_min_dihedral_deg, 18);
  EXPECT_EQ(custom.improve.params.goal_max_dihedral_deg, 150);
  EXPECT_EQ(to_json(custom)["improve"]["tet_quality"], "custom");
  PipelineConfig again;
  apply_config(Json::parse(to_json(custom).dump()), "again.json", again);
  EXPECT_EQ(to_json(again), to_json(custom));
  EXPECT_NE(error_of(Json::parse(R"({"improve": {"tet_quality": "best"}})")).find("improve.tet_quality: expected one of"),
            std::string::npos);
}

TEST(PipelineConfig, ValuesOfTheWrongTypeOrRangeAreRefusedWithTheKey) {
  EXPECT_EQ(error_of(Json::parse(R"({"simplify": {"ratio": 0}})")),
            "c.json: simplify.ratio: expected null or a number in (0, 1], not 0");
  EXPECT_EQ(error_of(Json::parse(R"({"simplify": {"enabled": "yes"}})")),
            "c.json: simplify.enabled: expected true or false, not \"yes\"");
  EXPECT_EQ(error_of(Json::parse(R"({"smooth": {"iterations": 2.5}})")),
            "c.json: smooth.iterations: expected an integer in [1, 1000], not 2.5");
  EXPECT_EQ(error_of(Json::parse(R"({"smooth": {"iterations": -1}})")),
            "c.json: smooth.iterations: expected an integer in [1, 1000], not -1");
  EXPECT_EQ(error_of(Json::parse(R"({"tetrahedralize": {"format": "stl"}})")),
            "c.json: tetrahedralize.format: expected one of msh, vtu, mesh, inp, node, xdmf, not \"stl\"");
  EXPECT_NE(error_of(Json::parse(R"({"enhance": {"max_deviation": 0}})")).find("number in (0, 1]"), std::string::npos);
  EXPECT_EQ(error_of(Json::parse(R"({"verdict": {"min_dihedral_deg": 200}})")),
            "c.json: verdict.min_dihedral_deg: expected a number in [0, 180], not 200");
  EXPECT_EQ(error_of(Json::parse(R"({"verdict": {"max_inverted_tets": -1}})")),
            "c.json: verdict.max_inverted_tets: expected an integer in [0, 1000000000], not -1");
  EXPECT_NE(error_of(Json::parse(R"({"reconstruct": {"resolution": [1, 5]}})")).find("[NX, NY]"), std::string::npos);
  EXPECT_NE(error_of(Json::parse(R"({"reconstruct": {"variation_threshold": "q9"}})")).find("percentile"),
            std::string::npos);
  EXPECT_EQ(error_of(Json::parse(R"({"smooth": 3})")), "c.json: smooth: expected an object of keys, not 3");
  EXPECT_EQ(error_of(Json::parse(R"([1])")), "c.json: a configuration is a JSON object of sections, not [1]");
}

// The ranges the stage libraries define hold for a configuration file too, naming the file.
TEST(PipelineConfig, TheLibrariesRangesAreCheckedWithTheFile) {
  EXPECT_EQ(error_of(Json::parse(R"({"tetrahedralize": {"radius_edge": 0.5}})")).rfind(
                "c.json: tetrahedralize: radius_edge must be 0 (no refinement) or in [1, 100]", 0),
            0u);
  // A configuration the command line built (flags bypass apply_config) meets the same checks.
  PipelineConfig config;
  config.verdict.min_dihedral_deg = std::nan("");
  EXPECT_THROW(check_config(config), InvalidInput);
  config = PipelineConfig();
  config.tetrahedralize.extrude_base = INFINITY;
  EXPECT_THROW(check_config(config), InvalidInput);
  config = PipelineConfig();
  config.improve.params.time_limit_seconds = INFINITY;
  EXPECT_THROW(check_config(config), InvalidInput);
  config = PipelineConfig();
  config.enhance.params.time_limit_seconds = -0.5;  // in the key's range [-1, inf), neither automatic nor a limit
  EXPECT_THROW(check_config(config), InvalidInput);
  EXPECT_NO_THROW(check_config(PipelineConfig()));
}

// binary and ascii as the tet format can store them: binary inp or ASCII xdmf are refused by the key.
TEST(PipelineConfig, TheTetFormatMustHonourBinaryOrAscii) {
  EXPECT_EQ(error_of(Json::parse(R"({"tetrahedralize": {"format": "inp", "binary": true}})")),
            "c.json: tetrahedralize: binary: tets.inp: cannot write Abaqus/CalculiX (.inp) binary: it is a text format "
            "(binary: .msh .vtu .xdmf)");
  EXPECT_EQ(error_of(Json::parse(R"({"tetrahedralize": {"format": "xdmf", "ascii": true}})")).rfind(
                "c.json: tetrahedralize: ascii: tets.xdmf: cannot write XDMF + HDF5 (.xdmf) as ASCII", 0),
            0u);
  EXPECT_EQ(error_of(Json::parse(R"({"tetrahedralize": {"format": "vtu", "binary": true, "ascii": true}})")),
            "c.json: tetrahedralize: binary, ascii: tets.vtu: cannot be written both binary and ASCII");
  PipelineConfig config;
  apply_config(Json::parse(R"({"tetrahedralize": {"format": "vtu", "ascii": true}})"), "c.json", config);
  EXPECT_TRUE(config.tetrahedralize.export_options.ascii);
  EXPECT_FALSE(config.tetrahedralize.export_options.binary);
}

TEST(PipelineConfig, ARefusedValueIsNotApplied) {
  PipelineConfig config;
  EXPECT_THROW(apply_config(Json::parse(R"({"simplify": {"ratio": 2}})"), "c.json", config), InvalidInput);
  EXPECT_FALSE(config.simplify.ratio.has_value());
}

TEST(PipelineConfig, TheRunSectionOfAPipelineJsonIsIgnored) {
  EXPECT_EQ(error_of(Json::parse(R"({"run": {"input": "x.off", "versions": {}}, "quality": {"distance_samples": 5000}})")),
            "");
}

TEST(PipelineConfig, FilesAreReadWithTheirErrors) {
  const std::filesystem::path dir = std::filesystem::temp_directory_path() / "meshprep_config_test";
  std::filesystem::create_directories(dir);
  const std::string path = (dir / "bad.json").string();
  std::ofstream(path) << "{\"simplify\": {\"ratio\": 0.5,}}";
  PipelineConfig config;
  try {
    read_config_file(path, config);
    ADD_FAILURE() << "malformed JSON accepted";
  } catch (const InvalidInput& e) {
    EXPECT_EQ(std::string(e.what()).rfind(path + ": not valid JSON: parse error at line 1, column 28", 0), 0u) << e.what();
  }
  EXPECT_THROW(read_config_file((dir / "missing.json").string(), config), IoError);
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace meshprep
