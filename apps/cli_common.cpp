#include "cli_common.h"

#include "meshprep/core/atomic_file.h"
#include "meshprep/core/errors.h"

#include <algorithm>
#include <filesystem>
#include <iostream>
#include <thread>

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

void add_samples_option(CLI::App& cmd, std::size_t& samples) {
  cmd.add_option("--samples", samples, "Random samples per direction for the reference distances of the report")
      ->capture_default_str()
      ->check(CLI::Range(std::size_t{1000}, std::size_t{100000000}));
}

void add_threads_option(CLI::App& cmd, std::size_t& threads) {
  cmd.add_option("--threads", threads, "Threads for the parallel parts (default: all cores)")
      ->check(CLI::Range(std::size_t{1}, std::size_t{1024}));
}

ThreadLimit::ThreadLimit(std::size_t threads)
    : threads_(threads > 0 ? threads : std::max(1u, std::thread::hardware_concurrency())),
      control_(tbb::global_control::max_allowed_parallelism, threads_) {}

void refuse_new_intersections(const QualityReport& output, std::size_t input_intersections, const std::string& path,
                              const std::string& what, const std::string& advice) {
  if (output.self_intersections <= input_intersections) return;
  throw WorkFailed(path + ": the " + what + " surface intersects itself at " +
                   std::to_string(output.self_intersections - input_intersections) +
                   " more face pairs than the input (first: faces " +
                   std::to_string(output.self_intersecting_pairs.front().first) + " and " +
                   std::to_string(output.self_intersecting_pairs.front().second) + "); nothing written. " + advice);
}

}  // namespace meshprep::cli
