#pragma once
/// \file config_text.h
/// read_config_file on text already in memory, for the fuzz target in fuzz/.

#include "meshprep/pipeline/pipeline_config.h"

#include <string>
#include <string_view>

namespace meshprep::detail {

/// Parse `text` as JSON and apply it onto `config`; `origin` (a file name) starts every message.
/// \throws InvalidInput for malformed JSON (with the line and column) and as apply_config.
void apply_config_text(std::string_view text, const std::string& origin, PipelineConfig& config);

}  // namespace meshprep::detail
