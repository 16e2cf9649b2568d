#include "meshprep/quality/quality_gate.h"

#include "meshprep/core/errors.h"

#include <array>
#include <charconv>
#include <cmath>
#include <sstream>

namespace meshprep {
namespace {

std::string trim(const std::string& s) {
  const auto b = s.find_first_not_of(" \t");
  if (b == std::string::npos) return {};
  return s.substr(b, s.find_last_not_of(" \t") - b + 1);
}

GateCondition parse_condition(const std::string& raw) {
  GateCondition c;
  c.text = trim(raw);
  // Two-character operators first, so that ">=" is not read as ">" followed by "=3".
  static const std::array<const char*, 6> ops{">=", "<=", "!=", ">", "<", "="};
  for (const char* op : ops) {
    const auto at = c.text.find(op);
    if (at == std::string::npos) continue;
    c.key = trim(c.text.substr(0, at));
    c.op = op;
    const std::string value = trim(c.text.substr(at + c.op.size()));
    if (value == "true" || value == "false") {
      c.value = value == "true";
    } else {
      double number = 0;
      const auto [end, ec] = std::from_chars(value.data(), value.data() + value.size(), number);
      if (value.empty() || ec != std::errc() || end != value.data() + value.size())
        throw InvalidInput("quality gate: condition '" + c.text + "': value '" + value + "' is not a number or true/false");
      // NaN compares false with everything and infinities bound nothing: such a gate would never act.
      if (!std::isfinite(number))
        throw InvalidInput("quality gate: condition '" + c.text + "': value '" + value + "' is not a finite number");
      c.value = number;
    }
    if (c.key.empty()) throw InvalidInput("quality gate: condition '" + c.text + "' has no key");
    return c;
  }
  throw InvalidInput("quality gate: condition '" + c.text + "' has no operator (one of > >= < <= = !=)");
}

const nlohmann::ordered_json* lookup(const nlohmann::ordered_json& report, const std::string& key) {
  const nlohmann::ordered_json* node = &report;
  std::istringstream parts(key);
  for (std::string part; std::getline(parts, part, '.');) {
    if (node->is_null()) return node;  // e.g. reference.x of a null reference: condition cannot hold
    if (!node->is_object() || !node->contains(part)) return nullptr;
    node = &(*node)[part];
  }
  return node;
}

bool compare(double lhs, const std::string& op, double rhs) {
  if (op == ">") return lhs > rhs;
  if (op == ">=") return lhs >= rhs;
  if (op == "<") return lhs < rhs;
  if (op == "<=") return lhs <= rhs;
  if (op == "=") return lhs == rhs;
  return lhs != rhs;
}

}  // namespace

std::vector<GateCondition> parse_quality_gate(const std::string& spec) {
  std::vector<GateCondition> gate;
  std::istringstream in(spec);
  for (std::string part; std::getline(in, part, ',');)
    if (!trim(part).empty()) gate.push_back(parse_condition(part));
  if (gate.empty()) throw InvalidInput("quality gate: no condition given");
  return gate;
}

std::vector<GateCondition> failed_conditions(const std::vector<GateCondition>& gate,
                                             const nlohmann::ordered_json& report) {
  std::vector<GateCondition> failed;
  for (const GateCondition& c : gate) {
    const nlohmann::ordered_json* value = lookup(report, c.key);
    if (!value) throw InvalidInput("quality gate: unknown key '" + c.key + "' in condition '" + c.text + "'");
    if (value->is_null()) continue;
    bool holds = false;
    if (value->is_boolean() && c.value.is_boolean()) {
      if (c.op != "=" && c.op != "!=")
        throw InvalidInput("quality gate: condition '" + c.text + "': a flag only compares with = or !=");
      holds = (value->get<bool>() == c.value.get<bool>()) == (c.op == "=");
    } else if (value->is_number() && c.value.is_number()) {
      holds = compare(value->get<double>(), c.op, c.value.get<double>());
    } else {
      throw InvalidInput("quality gate: condition '" + c.text + "' compares '" + c.key + "' (" + value->type_name() +
                         ") with " + c.value.type_name());
    }
    if (holds) {
      failed.push_back(c);
      failed.back().actual = *value;
    }
  }
  return failed;
}

}  // namespace meshprep
