#include "meshprep/fem/fem_verdict.h"

#include "meshprep/core/errors.h"
#include "meshprep/quality/json_values.h"
#include "meshprep/report/number_format.h"

#include <cmath>
#include <utility>

namespace meshprep {
namespace {

// How a check reads and which way it holds.
struct CheckText {
  const char* name;
  const char* figure;  ///< what the value is
  const char* unit;    ///< after a number, with its space
  bool at_least;       ///< the value must be >= the threshold (else <=)
};

constexpr CheckText kChecks[] = {{"min_dihedral_deg", "smallest dihedral angle", " deg", true},
                                 {"max_dihedral_deg", "largest dihedral angle", " deg", false},
                                 {"max_inverted_tets", "inverted tets", "", false}};

// The text of a check judge_tets made; null for a name it does not make.
const CheckText* text_of(const ThresholdCheck& check) {
  for (const CheckText& t : kChecks)
    if (check.check == t.name) return &t;
  return nullptr;
}

ThresholdCheck judged(const CheckText& text, double threshold, double value) {
  // NaN compares false both ways: no figure never passes.
  return {text.name, threshold, value, text.at_least ? value >= threshold : value <= threshold};
}

}  // namespace

bool TetVerdict::ok() const {
  for (const ThresholdCheck& c : checks)
    if (!c.ok) return false;
  return true;
}

std::vector<ThresholdCheck> TetVerdict::failed() const {
  std::vector<ThresholdCheck> list;
  for (const ThresholdCheck& c : checks)
    if (!c.ok) list.push_back(c);
  return list;
}

void check_thresholds(const TetThresholds& thresholds) {
  for (const auto& [field, value] : {std::pair<const char*, double>{"min_dihedral_deg", thresholds.min_dihedral_deg},
                                     std::pair<const char*, double>{"max_dihedral_deg", thresholds.max_dihedral_deg}})
    if (!(value >= 0 && value <= 180))
      throw InvalidInput(std::string("verdict: ") + field + " must be in [0, 180], not " + format_number(value, 6));
}

TetVerdict judge_tets(const TetQualityReport& report, const TetThresholds& thresholds) {
  check_thresholds(thresholds);
  TetVerdict verdict;
  verdict.checks.push_back(judged(kChecks[0], thresholds.min_dihedral_deg, report.min_dihedral_deg.min));
  verdict.checks.push_back(judged(kChecks[1], thresholds.max_dihedral_deg, report.max_dihedral_deg.max));
  verdict.checks.push_back(judged(kChecks[2], static_cast<double>(thresholds.max_inverted_tets),
                                  static_cast<double>(report.quadratic ? report.quadratic->nonpositive_jacobian_tets
                                                                          : report.inverted_tets)));
  return verdict;
}

std::string requirement(const ThresholdCheck& check) {
  const CheckText* t = text_of(check);
  if (!t) return check.check + " " + format_number(check.threshold, 4);
  return std::string(t->figure) + (t->at_least ? " >= " : " <= ") + format_number(check.threshold, 4) + t->unit;
}

std::string describe(const ThresholdCheck& check) {
  const std::string value = std::isnan(check.value) ? "undefined (no tets)" : format_number(check.value, 4);
  const CheckText* t = text_of(check);
  if (!t) return check.check + " " + value + (check.ok ? " within " : " beyond ") + format_number(check.threshold, 4);
  const char* relation = t->at_least ? (check.ok ? " >= " : " < ") : (check.ok ? " <= " : " > ");
  return std::string(t->figure) + " " + value + (std::isnan(check.value) ? "" : t->unit) + relation +
         format_number(check.threshold, 4) + t->unit + " (" + check.check + ")";
}

nlohmann::ordered_json to_json(const ThresholdCheck& check) {
  return {{"check", check.check}, {"threshold", check.threshold}, {"value", json_number(check.value)}, {"ok", check.ok}};
}

nlohmann::ordered_json to_json(const TetVerdict& verdict) {
  nlohmann::ordered_json list = nlohmann::ordered_json::array();
  for (const ThresholdCheck& c : verdict.checks) list.push_back(to_json(c));
  return list;
}

}  // namespace meshprep
