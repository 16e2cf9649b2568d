#pragma once
/// \file parameter.h
/// What a stage parameter is to its users: its configuration key, its command-line flag, its range
/// and what it means. Each stage declares one ParameterInfo per field next to its Params struct
/// (e.g. simplify/simplify_parameters.h); the command line (apps/cli_parameters.h), the pipeline's
/// configuration keys (pipeline_config.cpp) and the stage's own check read that one descriptor, so
/// a range or a help text has one home. The default is the Params struct's member initialiser: the
/// descriptor never restates it. docs/architecture.md, "Parameters".

#include <string>
#include <utility>
#include <vector>

namespace meshprep {

/// An interval of numbers; an end may be open and `hi` infinite ([0, inf] takes infinity as a
/// value, [0, inf) does not). Counts use it with whole ends.
struct Range {
  double lo = 0, hi = 0;
  bool lo_open = false, hi_open = false;

  /// False for NaN.
  bool contains(double value) const;
  /// "[0, 60)", "(0, 1]", "[0, inf)"; whole numbers without a decimal point.
  std::string text() const;
};

/// One parameter of a stage, as the command line and the configuration file name it.
struct ParameterInfo {
  std::string key;   ///< configuration key, e.g. "min_angle_deg"
  std::string flag;  ///< CLI11 option name, e.g. "--min-angle"; a switch may also name its negation
  std::string help;  ///< what it means, from a lower-case word (the command line capitalises it)
  Range range;       ///< of a number or a count; unused by switches and choices
};

/// A parameter's named values (an enum's names as the command line and the file spell them).
template <class T>
using Choices = std::vector<std::pair<std::string, T>>;

/// The choices' names, "a, b, c".
template <class T>
std::string choice_names(const Choices<T>& choices) {
  std::string names;
  for (const auto& choice : choices) names += (names.empty() ? "" : ", ") + choice.first;
  return names;
}

/// The name of `value` among `choices` ("" if it has none).
template <class T>
std::string choice_name(const Choices<T>& choices, const T& value) {
  for (const auto& choice : choices)
    if (choice.second == value) return choice.first;
  return {};
}

/// \throws InvalidInput "<stage>: <key> must be in <range>, not <value>" unless the range holds it.
void check_parameter(const char* stage, const ParameterInfo& info, double value);

/// `value` as the messages and help texts write a figure: up to 6 significant digits, "inf".
std::string parameter_text(double value);

}  // namespace meshprep
