// libFuzzer target: the pipeline's configuration file (read_config_file) on arbitrary bytes
// (scripts/fuzz.sh runs it). A configuration it accepts must replay: its effective configuration
// (what pipeline.json holds) reads back to itself.
#include "config_text.h"
#include "fuzz_support.h"

#include "meshprep/core/errors.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace meshprep;
  PipelineConfig config;
  try {
    detail::apply_config_text(fuzz::as_text(data, size), "input.json", config);
  } catch (const InvalidInput&) {
    return 0;  // refused as documented; any other exception escapes
  }
  const nlohmann::ordered_json written = to_json(config);
  PipelineConfig replayed;
  detail::apply_config_text(written.dump(), "pipeline.json", replayed);  // any error here is a bug: escapes
  fuzz::require(to_json(replayed) == written, "the effective configuration reads back to itself");
  return 0;
}
