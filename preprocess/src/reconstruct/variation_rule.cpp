#include "meshprep/preprocess/reconstruct/variation_rule.h"

#include "meshprep/core/parameter.h"

#include <exception>

namespace meshprep {

bool apply_variation_rule(const std::string& text, PartitionOfUnityParams& params) {
  const bool percentile = !text.empty() && text[0] == 'p';
  const std::string number = text.substr(percentile ? 1 : 0);
  try {
    std::size_t used = 0;
    const double value = std::stod(number, &used);
    if (used != number.size() || !(value >= 0) || (percentile && value > 100)) return false;
    params.variation_percentile = percentile ? value : -1;
    if (!percentile) params.variation_threshold = value;
    return true;
  } catch (const std::exception&) {
    return false;
  }
}

std::string variation_rule_text(const PartitionOfUnityParams& params) {
  return params.variation_percentile >= 0 ? "p" + parameter_text(params.variation_percentile)
                                          : parameter_text(params.variation_threshold);
}

std::string variation_rule_error(const std::string& text) {
  return "expected a sigma threshold >= 0 (e.g. 0.3) or a percentile p0..p100 (e.g. p90), not '" + text + "'";
}

}  // namespace meshprep
