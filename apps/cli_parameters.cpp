#include "cli_parameters.h"

#include "meshprep/preprocess/patches/patches_parameters.h"

#include "cli_common.h"

#include <cctype>
#include <cmath>
#include <cstdlib>

namespace meshprep::cli {

std::string capitalised(std::string text) {
  // "rbf: ..." names the method the parameter belongs to: a label, kept as written.
  const std::size_t word_end = text.find_first_of(" :");
  const bool label = word_end != std::string::npos && text[word_end] == ':';
  if (!text.empty() && !label) text[0] = static_cast<char>(std::toupper(static_cast<unsigned char>(text[0])));
  return text;
}

CLI::Validator range_check(const Range& range) {
  return CLI::Validator(
      [range](std::string& value) {
        char* end = nullptr;
        const double number = std::strtod(value.c_str(), &end);
        if (end == value.c_str() || *end != '\0') return std::string();  // not a number: the conversion says so
        return range.contains(number) ? std::string() : "Value " + value + " not in " + range.text();
      },
      "in " + range.text());
}

ParameterInfo renamed(ParameterInfo info, std::string flag) {
  info.flag = std::move(flag);
  return info;
}

CLI::Option* add_parameter(CLI::App& cmd, const ParameterInfo& info, double& field) {
  CLI::Option* option =
      cmd.add_option(info.flag, field, capitalised(info.help))->check(range_check(info.range))->capture_default_str();
  // A closed infinite end takes infinity as a value (--smoothing inf): refuse_non_finite_numbers
  // then leaves the option alone.
  if (std::isinf(info.range.hi) && !info.range.hi_open) option->check(CLI::Validator("").name(kInfinityMeaningful));
  return option;
}

CLI::Option* add_parameter(CLI::App& cmd, const ParameterInfo& info, std::size_t& field) {
  return cmd.add_option(info.flag, field, capitalised(info.help))
      ->check(range_check(info.range))
      ->capture_default_str();
}

CLI::Option* add_parameter(CLI::App& cmd, const ParameterInfo& info, bool& field) {
  return cmd.add_flag(info.flag, field, capitalised(info.help) + (field ? " (default on)" : ""));
}

CLI::Option* add_auto_parameter(CLI::App& cmd, const ParameterInfo& info, std::optional<double>& field) {
  const Range range = info.range;
  return cmd
      .add_option_function<std::string>(
          info.flag,
          [&field](const std::string& value) {
            if (value == "auto") field.reset();
            else field = std::stod(value);  // checked below
          },
          capitalised(info.help))
      ->check(CLI::Validator(
          [range](std::string& value) {
            if (value == "auto") return std::string();
            char* end = nullptr;
            const double number = std::strtod(value.c_str(), &end);
            if (end == value.c_str() || *end != '\0')
              return "expected a number in " + range.text() + " or auto, not '" + value + "'";
            return range.contains(number) ? std::string() : "Value " + value + " not in " + range.text() + " (or auto)";
          },
          "E|auto"))
      ->default_str(field ? parameter_text(*field) : "auto");
}

void add_patch_edits(CLI::App& cmd, PatchParams& params) {
  const PatchParameters& info = patch_parameters();
  cmd.add_option_function<std::vector<std::string>>(
         info.renames.flag,
         [&params](const std::vector<std::string>& pairs) {
           for (const std::string& pair : pairs) {
             const std::size_t equals = pair.find('=');
             params.renames.emplace_back(pair.substr(0, equals), pair.substr(equals + 1));
           }
         },
         capitalised(info.renames.help))
      ->check(CLI::Validator(
          [](std::string& pair) {
            const std::size_t equals = pair.find('=');
            return equals == std::string::npos || equals == 0 || equals + 1 == pair.size()
                       ? "expected OLD=NEW, not '" + pair + "'"
                       : std::string();
          },
          ""))
      ->type_name("OLD=NEW");
  cmd.add_option_function<std::vector<std::string>>(
         info.merges.flag,
         [&params](const std::vector<std::string>& lists) {
           for (const std::string& list : lists) {
             std::vector<std::string> names;
             std::size_t start = 0;
             for (std::size_t comma = list.find(','); ; comma = list.find(',', start)) {
               names.push_back(list.substr(start, comma - start));
               if (comma == std::string::npos) break;
               start = comma + 1;
             }
             params.merges.push_back(names);
           }
         },
         capitalised(info.merges.help))
      ->type_name("A,B,...");
}

CLI::Option* add_override(CLI::App& cmd, const ParameterInfo& info, std::optional<double>& given,
                          double default_value) {
  return cmd.add_option(info.flag, given, capitalised(info.help) + " (default " + parameter_text(default_value) + ")")
      ->check(range_check(info.range));
}

CLI::Option* add_override(CLI::App& cmd, const ParameterInfo& info, std::optional<std::size_t>& given,
                          std::size_t default_value) {
  return cmd.add_option(info.flag, given, capitalised(info.help) + " (default " + std::to_string(default_value) + ")")
      ->check(range_check(info.range));
}

}  // namespace meshprep::cli
