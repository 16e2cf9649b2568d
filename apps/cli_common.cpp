#include "cli_common.h"

#include "meshprep/core/atomic_file.h"
#include "meshprep/core/errors.h"

#include <filesystem>

#include <iostream>

namespace meshprep::cli {

void emit_json(const nlohmann::ordered_json& json, const std::string& target) {
  if (target == "-") {
    std::cout << json.dump(2) << '\n';
    return;
  }
  write_file_atomically(target, [&](std::ostream& out) { out << json.dump(2) << '\n'; });
}

void ensure_not_input(const std::string& output, const std::string& input) {
  if (output.empty() || input.empty() || output == "-") return;
  std::error_code ec;
  if (output == input || std::filesystem::equivalent(output, input, ec))
    throw InvalidInput(output + ": output would overwrite the input file");
}

}  // namespace meshprep::cli
