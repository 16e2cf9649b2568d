#pragma once
/// \file json_values.h
/// How figures become JSON everywhere in meshprep: JSON has no inf/NaN, so non-finite numbers
/// become null, and a distribution is {min, mean, p5, p50, p95, max}.

#include "meshprep/core/taken_back.h"
#include "meshprep/quality/statistics.h"

#include <nlohmann/json.hpp>

#include <cmath>

namespace meshprep {

/// The key every report lists a stage's taken-back work under.
inline constexpr const char* kGuardsTakenBackKey = "guards_taken_back";

/// A finite number, or null.
inline nlohmann::ordered_json json_number(double v) {
  return std::isfinite(v) ? nlohmann::ordered_json(v) : nlohmann::ordered_json(nullptr);
}

/// {"min", "mean", "p5", "p50", "p95", "max"}, each a json_number.
inline nlohmann::ordered_json json_distribution(const Distribution& d) {
  return {{"min", json_number(d.min)}, {"mean", json_number(d.mean)}, {"p5", json_number(d.p5)},
          {"p50", json_number(d.p50)}, {"p95", json_number(d.p95)}, {"max", json_number(d.max)}};
}

/// [{"stage", "guard", "work", "count", "reason", "before": {name: value}, "after": {...}}, ...].
inline nlohmann::ordered_json json_taken_back(const std::vector<TakenBack>& list) {
  nlohmann::ordered_json json = nlohmann::ordered_json::array();
  for (const TakenBack& t : list) {
    nlohmann::ordered_json before = nlohmann::ordered_json::object(), after = nlohmann::ordered_json::object();
    for (const GuardFigure& f : t.before) before[f.name] = json_number(f.value);
    for (const GuardFigure& f : t.after) after[f.name] = json_number(f.value);
    json.push_back({{"stage", t.stage}, {"guard", t.guard}, {"work", t.work}, {"count", t.count},
                    {"reason", t.reason}, {"before", std::move(before)}, {"after", std::move(after)}});
  }
  return json;
}

}  // namespace meshprep
