#pragma once
/// \file json_values.h
/// How figures become JSON everywhere in meshprep: JSON has no inf/NaN, so non-finite numbers
/// become null, and a distribution is {min, mean, p5, p50, p95, max}.

#include "meshprep/quality/statistics.h"

#include <nlohmann/json.hpp>

#include <cmath>

namespace meshprep {

/// A finite number, or null.
inline nlohmann::ordered_json json_number(double v) {
  return std::isfinite(v) ? nlohmann::ordered_json(v) : nlohmann::ordered_json(nullptr);
}

/// {"min", "mean", "p5", "p50", "p95", "max"}, each a json_number.
inline nlohmann::ordered_json json_distribution(const Distribution& d) {
  return {{"min", json_number(d.min)}, {"mean", json_number(d.mean)}, {"p5", json_number(d.p5)},
          {"p50", json_number(d.p50)}, {"p95", json_number(d.p95)}, {"max", json_number(d.max)}};
}

}  // namespace meshprep
