#pragma once
/// \file variation_rule.h
/// The text form of the reconstruction's variation threshold (partition_of_unity.h), shared by the
/// CLI and the pipeline's configuration file: "0.3" is a fixed sigma threshold (the paper's),
/// "p90" the 90th percentile of the patches' sigma (the adaptive default).

#include "meshprep/preprocess/reconstruct/partition_of_unity.h"

#include <optional>
#include <string>

namespace meshprep {

/// Sets `params.variation_percentile` (-1 for a fixed threshold) and `params.variation_threshold`
/// from `text`. Returns false, leaving `params` unchanged, if the text is neither a number >= 0
/// nor "p" followed by a number in [0, 100].
bool apply_variation_rule(const std::string& text, PartitionOfUnityParams& params);

/// The rule `params` holds, as apply_variation_rule reads it: "p90" or "0.3".
std::string variation_rule_text(const PartitionOfUnityParams& params);

/// The message for a rejected rule: what is expected and what was given.
std::string variation_rule_error(const std::string& text);

}  // namespace meshprep
