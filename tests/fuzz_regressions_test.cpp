// Inputs on which the fuzz targets (fuzz/, scripts/fuzz.sh) found a reader or the configuration
// parser failing otherwise than with InvalidInput, each inlined with what the library does now.
// Part of the pipeline's tests because the configuration file is among the fuzzed inputs.
#include "meshprep/core/errors.h"
#include "meshprep/pipeline/pipeline_config.h"
#include "scratch_dir.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

namespace meshprep {
namespace {

namespace fs = std::filesystem;

using FuzzRegression = test::ScratchDirTest;

// The message of the InvalidInput that reading the configuration file `path` throws ("" if none).
std::string config_error(const std::string& path) {
  PipelineConfig config;
  try {
    read_config_file(path, config);
  } catch (const InvalidInput& error) {
    return error.what();
  }
  return {};
}

bool starts_with(const std::string& text, const std::string& prefix) { return text.rfind(prefix, 0) == 0; }

// nlohmann::json throws out_of_range, not parse_error, for a number beyond the double range; it
// escaped read_config_file, so the CLI exited 1 with a message naming neither the file nor the key.
TEST_F(FuzzRegression, AConfigNumberBeyondTheDoubleRangeIsInvalidJson) {
  for (const char* text : {"55555555555555555555555551e308*", R"({"simplify": {"ratio": 1e400}})"}) {
    const std::string path = file("overflow.json", text);
    const std::string message = config_error(path);
    EXPECT_TRUE(starts_with(message, path + ": not valid JSON: number overflow parsing '")) << message;
  }
}

// The messages quoted the offending value with nlohmann's dump(), which recurses once per level:
// 10^5 nested brackets overflowed the stack (a crash, not a message). Found with a hand-made input:
// the fuzzers' inputs stay under 4 KiB.
TEST_F(FuzzRegression, ADeeplyNestedConfigValueIsNamedNotDumped) {
  const std::string deep = std::string(100000, '[') + std::string(100000, ']');
  const struct {
    std::string text, message;
  } cases[] = {
      {deep, "a configuration is a JSON object of sections, not an array nested over 16 levels deep"},
      {R"({"simplify": {"ratio": )" + deep + "}}",
       "simplify.ratio: expected null or a number in (0, 1], not an array nested over 16 levels deep"},
      {R"({"smooth": {"iterations": [[[[[[[[[[[[[[[[1]]]]]]]]]]]]]]]]}})",
       "smooth.iterations: expected an integer in [1, 1000], not [[[[[[[[[[[[[[[[1]]]]]]]]]]]]]]]]"},
  };
  for (const auto& c : cases) {
    const std::string path = file("deep.json", c.text);
    EXPECT_EQ(config_error(path), path + ": " + c.message);
  }
}

}  // namespace
}  // namespace meshprep
