#pragma once
/// \file quality_gate.h
/// A quality gate for scripts and CI: conditions on the report's JSON that must NOT hold.
/// Syntax: comma-separated `KEY OP VALUE`, KEY a dotted path into the JSON report
/// (`radius_ratio.p95`, `reference.hausdorff_relative`, `closed`), OP one of > >= < <= = !=,
/// VALUE a finite number or true/false. Example: "radius_ratio.p95>3,faces_min_angle_below_20>0.05,closed=false".

#include <nlohmann/json.hpp>

#include <string>
#include <vector>

namespace meshprep {

struct GateCondition {
  std::string text;  ///< as written, trimmed
  std::string key;
  std::string op;
  nlohmann::json value;
  nlohmann::json actual;  ///< the report's value, set by failed_conditions
};

/// Parse a gate specification. \throws InvalidInput naming the malformed condition.
std::vector<GateCondition> parse_quality_gate(const std::string& spec);

/// The conditions that hold for `report` (the gate fails if any does). A condition on a null
/// value (e.g. volume of an open mesh) does not hold.
/// \throws InvalidInput if a key does not exist in the report, or compares a flag with a number.
std::vector<GateCondition> failed_conditions(const std::vector<GateCondition>& gate, const nlohmann::ordered_json& report);

}  // namespace meshprep
