#pragma once
// Command-line options made from the stages' parameter descriptors (core/parameter.h): the flag,
// the help, the range check and the default shown all come from the one descriptor and the Params
// struct's default, so no command restates them.

#include "meshprep/core/parameter.h"
#include "meshprep/preprocess/patches/patches.h"

#include <CLI/CLI.hpp>

#include <optional>
#include <string>

namespace meshprep::cli {

/// `text` with its first letter in upper case (a descriptor's help as a sentence), unless its first
/// word is a label ("rbf: ...").
std::string capitalised(std::string text);

/// Refuses numbers outside `range`; its description ("in [0, 60)") is what the help shows.
CLI::Validator range_check(const Range& range);

/// The descriptor under another flag (the pipeline's --target-faces is simplify's --faces).
ParameterInfo renamed(ParameterInfo info, std::string flag);

/// A number or a count bound to `field`, its current value shown as the default.
CLI::Option* add_parameter(CLI::App& cmd, const ParameterInfo& info, double& field);
CLI::Option* add_parameter(CLI::App& cmd, const ParameterInfo& info, std::size_t& field);

/// A switch bound to `field` (info.flag may name its negation: "--flips,!--no-flips").
CLI::Option* add_parameter(CLI::App& cmd, const ParameterInfo& info, bool& field);

/// A number or "auto" (unset), bound to `field`; the default shown is "auto" when unset.
CLI::Option* add_auto_parameter(CLI::App& cmd, const ParameterInfo& info, std::optional<double>& field);

/// A number given or not: `given` stays unset unless the flag is, so that it can override a value
/// from elsewhere (a configuration file); the help names `default_value`.
CLI::Option* add_override(CLI::App& cmd, const ParameterInfo& info, std::optional<double>& given, double default_value);
CLI::Option* add_override(CLI::App& cmd, const ParameterInfo& info, std::optional<std::size_t>& given,
                          std::size_t default_value);

/// --rename OLD=NEW and --merge A,B,... (patches_parameters.h), each repeatable, appended to
/// `params`' renames and merges (after those of a configuration file).
void add_patch_edits(CLI::App& cmd, PatchParams& params);

/// One of `choices` by name, bound to `field`, its current name shown as the default.
template <class T>
CLI::Option* add_choice(CLI::App& cmd, const ParameterInfo& info, T& field, const Choices<T>& choices) {
  std::vector<std::string> names;
  for (const auto& choice : choices) names.push_back(choice.first);
  return cmd
      .add_option_function<std::string>(
          info.flag,
          [&field, choices](const std::string& name) {
            for (const auto& choice : choices)
              if (choice.first == name) field = choice.second;
          },
          capitalised(info.help))
      ->check(CLI::IsMember(names))
      ->default_str(choice_name(choices, field));
}

}  // namespace meshprep::cli
