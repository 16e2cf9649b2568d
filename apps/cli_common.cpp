#include "cli_common.h"

#include "cli_parameters.h"
#include "interrupt.h"
#include "progress_bar.h"

#include "meshprep/core/atomic_file.h"
#include "meshprep/core/errors.h"
#include "meshprep/core/patch_names.h"
#include "meshprep/core/size_parameters.h"
#include "meshprep/fem/fem_parameters.h"
#include "meshprep/fem/solver_targets.h"
#include "meshprep/fem/tet_quality.h"
#include "meshprep/quality/quality_parameters.h"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <iomanip>
#include <iostream>
#include <memory>
#include <sstream>
#include <thread>

#include <unistd.h>

namespace meshprep::cli {

void emit_json(const nlohmann::ordered_json& json, const std::string& target) {
  if (target == "-") {
    std::cout << json.dump(2) << '\n';
    return;
  }
  write_file_atomically(target, [&](std::ostream& out) { out << json.dump(2) << '\n'; });
}

namespace {

namespace fs = std::filesystem;

// Whether two paths name one file: the same file on disk (also through a hard link), or the same
// place once symlinks and ".." are resolved (for files yet to be written).
bool same_file(const std::string& a, const std::string& b) {
  std::error_code ec, ec_b;
  if (fs::equivalent(a, b, ec)) return true;
  const fs::path place_a = fs::weakly_canonical(fs::absolute(a), ec), place_b = fs::weakly_canonical(fs::absolute(b), ec_b);
  return !ec && !ec_b && place_a == place_b;
}

bool is_character_device(const std::string& path) {
  std::error_code ec;
  return fs::is_character_file(path, ec);
}

// Refuses an output that cannot be written, before any work: found when it is written, it would
// cost the whole run (issue 45: a missing folder after 7 s of work, exit 1).
void check_writable(const std::string& output, MissingFolders folders) {
  std::error_code ec;
  if (fs::is_directory(output, ec)) throw InvalidInput(output + ": cannot write: it is a folder");
  if (fs::is_character_file(output, ec)) return;  // /dev/null, /dev/stdout
  fs::path folder = fs::absolute(output, ec).parent_path();
  if (folders == MissingFolders::made)
    while (!fs::exists(folder, ec) && folder != folder.parent_path()) folder = folder.parent_path();
  if (!fs::exists(folder, ec)) throw InvalidInput(output + ": cannot write: the folder " + folder.string() + " does not exist");
  if (!fs::is_directory(folder, ec)) throw InvalidInput(output + ": cannot write: " + folder.string() + " is not a folder");
  if (::access(folder.c_str(), W_OK | X_OK) != 0)
    throw InvalidInput(output + ": cannot write in " + folder.string() + ": " + std::strerror(errno));
}

}  // namespace

std::vector<std::string> files_of(const std::string& path) {
  if (extension_of(path) == "ele") return tet_mesh_files(fs::path(path).replace_extension(".node").string());
  return tet_mesh_files(path);
}

void check_output_files(const std::vector<std::string>& inputs, const std::vector<std::string>& outputs,
                        MissingFolders folders) {
  const auto expanded = [](const std::vector<std::string>& paths) {
    std::vector<std::string> files;
    for (const std::string& path : paths)
      if (!path.empty() && path != "-")
        for (const std::string& file : files_of(path)) files.push_back(file);
    return files;
  };
  const std::vector<std::string> input_files = expanded(inputs), output_files = expanded(outputs);
  for (std::size_t i = 0; i < output_files.size(); ++i) {
    const std::string& output = output_files[i];
    for (const std::string& input : input_files)
      if (same_file(output, input)) throw InvalidInput(output + ": output would overwrite the input file " + input);
    for (std::size_t j = 0; j < i; ++j)
      if (same_file(output, output_files[j]) && !is_character_device(output))
        throw InvalidInput(output + ": two outputs would be the same file (also given as " + output_files[j] +
                           "); give each output its own file");
  }
  for (const std::string& output : output_files) check_writable(output, folders);
}

void print_messages(const CommandMessages& messages) {
  for (const std::string& message : messages) std::cerr << "meshprep: " << message << '\n';
}

CommandHooks terminal_hooks(std::function<void(double)> draw) {
  CommandHooks hooks;
  hooks.cancelled = stop_requested;
  hooks.deadline = time_limit();
  if (draw) {
    hooks.progress = stoppable(std::move(draw));
    hooks.step = [](const std::string& what) {
      if (::isatty(STDERR_FILENO)) std::cerr << "meshprep: " << what << '\n';
    };
    return hooks;
  }
  // Each long step gets its own bar, labelled with the step; the cancellation polls (every 50 ms
  // while TetGen runs) keep it moving off a terminal. Polls from other threads leave it alone.
  auto bar = std::make_shared<std::unique_ptr<ProgressBar>>();
  const std::thread::id caller = std::this_thread::get_id();
  hooks.step = [bar](const std::string& what) { *bar = std::make_unique<ProgressBar>(what); };
  hooks.progress = stoppable([bar](double fraction) {
    if (*bar) (*bar)->update(fraction);
  });
  hooks.cancelled = [bar, caller] {
    if (*bar && std::this_thread::get_id() == caller) (*bar)->tick();
    return stop_requested();
  };
  return hooks;
}

CLI::Validator positive() {
  return CLI::Validator(
      [](std::string& value) {
        char* end = nullptr;
        const double number = std::strtod(value.c_str(), &end);
        if (end == value.c_str() || *end != '\0') return std::string();  // not a number: the conversion says so
        return number > 0 ? std::string() : "must be positive, not " + value;
      },
      "POSITIVE");
}

void refuse_non_finite_numbers(CLI::App& app) {
  const auto refuse = [](bool infinity_allowed) {
    return CLI::Validator(
        [infinity_allowed](std::string& value) {
          char* end = nullptr;
          const double number = std::strtod(value.c_str(), &end);
          if (end == value.c_str() || *end != '\0') return std::string();  // not a number: the conversion says so
          if (std::isnan(number)) return "expected a number, not '" + value + "'";
          if (std::isinf(number) && !infinity_allowed) return "expected a finite number, not '" + value + "'";
          return std::string();
        },
        "");  // no description: the help keeps showing the range
  };
  for (CLI::App* command : app.get_subcommands({}))
    for (CLI::Option* option : command->get_options()) {
      if (option->get_type_name().rfind("FLOAT", 0) != 0) continue;
      bool infinity_allowed = true;
      try {
        option->get_validator(kInfinityMeaningful);
      } catch (const CLI::OptionNotFound&) {
        infinity_allowed = false;
      }
      option->check(refuse(infinity_allowed));
    }
}

void add_samples_option(CLI::App& cmd, std::size_t& samples) {
  add_parameter(cmd, quality_parameters().distance_samples, samples);
}

void add_threads_option(CLI::App& cmd, std::size_t& threads) {
  cmd.add_option("--threads", threads, "Threads for the parallel parts (default: all cores)")
      ->check(CLI::Range(std::size_t{1}, std::size_t{1024}));
}

TetThresholds ThresholdFlags::applied_to(TetThresholds thresholds) const {
  if (min_dihedral_deg) thresholds.min_dihedral_deg = *min_dihedral_deg;
  if (max_dihedral_deg) thresholds.max_dihedral_deg = *max_dihedral_deg;
  if (max_inverted_tets) thresholds.max_inverted_tets = *max_inverted_tets;
  return thresholds;
}

void add_threshold_options(CLI::App& cmd, ThresholdFlags& flags) {
  const TetThresholds defaults;
  const VerdictParameters& p = verdict_parameters();
  add_override(cmd, p.min_dihedral_deg, flags.min_dihedral_deg, defaults.min_dihedral_deg);
  add_override(cmd, p.max_dihedral_deg, flags.max_dihedral_deg, defaults.max_dihedral_deg);
  add_override(cmd, p.max_inverted_tets, flags.max_inverted_tets, defaults.max_inverted_tets);
}

void add_encoding_options(CLI::App& cmd, EncodingFlags& flags, const std::string& binary_help) {
  auto* binary = cmd.add_flag("--binary", flags.binary, binary_help);
  cmd.add_flag("--ascii", flags.ascii, "ASCII .vtu instead of its zlib-compressed binary data")->excludes(binary);
}

TetExportOptions tet_export_options(const std::string& output, const std::string& target, const std::string& msh_version,
                                    const EncodingFlags& encoding) {
  TetExportOptions options;
  if (!target.empty()) {
    const SolverTarget& t = find_solver_target(target);
    if (extension_of(output) != t.extension.substr(1))
      throw InvalidInput(output + ": target " + t.name + " reads " + t.extension + " files");
    if (encoding.binary && !t.options.binary)
      throw InvalidInput(output + ": --binary: target " + t.name + " reads ASCII " + t.extension + " files");
    options = t.options;
  } else {
    options.msh_version = msh_version == "2.2" ? MshVersion::V22 : MshVersion::V41;
    options.binary = encoding.binary;
  }
  options.ascii = encoding.ascii;
  check_tet_export_options(output, options);
  return options;
}

void note_export_rounding(const std::string& output, const TetExportReport& report) {
  if (report.rounded_coordinates == 0) return;
  std::ostringstream bound;  // two digits, without touching std::cerr's precision
  bound << std::setprecision(2) << report.max_relative_rounding;
  std::cerr << "meshprep: note: " << output << ": " << report.rounded_coordinates
            << " coordinates rounded to fit the format's 20-character fields (relative error at most " << bound.str()
            << ")\n";
}

ImproveParams ImproveFlags::applied_to(ImproveParams params) const {
  if (tet_quality) apply_tet_quality(params, *tet_quality);
  if (goal_min_dihedral_deg) params.goal_min_dihedral_deg = *goal_min_dihedral_deg;
  if (goal_max_dihedral_deg) params.goal_max_dihedral_deg = *goal_max_dihedral_deg;
  if (time_limit_seconds) params.time_limit_seconds = *time_limit_seconds;
  if (boundary_deviation_flag && boundary_deviation_flag->count() > 0) params.boundary_deviation = boundary_deviation;
  return params;
}

void add_improve_options(CLI::App& cmd, ImproveFlags& flags, bool can_switch_off) {
  const ImproveParams defaults;
  const ImproveParameters& p = improve_parameters();
  if (can_switch_off)
    cmd.add_flag("--no-improve", flags.off, "Keep TetGen's tets as they are (no flips, smoothing or new inner vertices)");
  cmd.add_option(p.tet_quality.flag, flags.tet_quality, capitalised(p.tet_quality.help) + " (default: default)")
      ->check(CLI::IsMember({"default", "high", "custom"}));
  add_override(cmd, p.goal_min_dihedral_deg, flags.goal_min_dihedral_deg, defaults.goal_min_dihedral_deg);
  add_override(cmd, p.goal_max_dihedral_deg, flags.goal_max_dihedral_deg, defaults.goal_max_dihedral_deg);
  flags.boundary_deviation_flag = add_auto_parameter(cmd, p.boundary_deviation, flags.boundary_deviation);
  add_override(cmd, p.time_limit_seconds, flags.time_limit_seconds, defaults.time_limit_seconds);
}

SizeParams SizeFlags::applied_to(SizeParams params) const {
  if (given.size) params.size = given.size;
  if (given.size_min) params.size_min = given.size_min;
  if (given.size_max) params.size_max = given.size_max;
  if (given.curvature_points) params.curvature_points = given.curvature_points;
  if (given.thickness_layers) params.thickness_layers = given.thickness_layers;
  if (given.grading) params.grading = given.grading;
  for (const auto& [name, size] : given.patch_sizes) params.patch_sizes[name] = size;
  return params;
}

void add_size_options(CLI::App& cmd, SizeFlags& flags) {
  const SizeParameters& p = size_parameters();
  const auto length_check = [](const std::string& key) {
    return CLI::Validator(
        [key](std::string& text) {
          try {
            parse_length(text, key);
            return std::string();
          } catch (const InvalidInput&) {
            return "expected a positive length or a percentage of the diagonal such as 2%, not '" + text + "'";
          }
        },
        "LENGTH|N%");
  };
  // --size LENGTH and --size NAME=LENGTH (a patch's), one value per flag so that an input after
  // it is not read as a size; the last global LENGTH holds.
  SizeParams& given = flags.given;
  cmd.add_option_function<std::vector<std::string>>(
         p.size.flag,
         [&given](const std::vector<std::string>& values) {
           for (const std::string& value : values) {
             const std::size_t equals = value.find('=');
             if (equals == std::string::npos) given.size = parse_length(value, "--size");
             else given.patch_sizes[value.substr(0, equals)] = parse_length(value.substr(equals + 1), "--size " + value);
           }
         },
         capitalised(p.size.help) + ". NAME=LENGTH (the flag repeated, e.g. --size 2% --size load=0.4%): " + p.patch_sizes.help)
      ->expected(1)
      ->take_all()
      ->type_name("LENGTH|NAME=LENGTH")
      ->check(CLI::Validator(
          [length_check](std::string& value) {
            const std::size_t equals = value.find('=');
            std::string length = value;
            if (equals != std::string::npos) {
              const std::string name = value.substr(0, equals);
              if (!is_valid_name(name)) return "'" + name + "' is no patch name: " + std::string(kNameRule);
              length = value.substr(equals + 1);
            }
            return length_check("size")(length);
          },
          ""));
  for (const auto& [info, field] : {std::pair{&p.size_min, &flags.given.size_min}, {&p.size_max, &flags.given.size_max}}) {
    std::optional<Length>* target = field;
    const std::string key = info->key;
    cmd.add_option_function<std::string>(
           info->flag, [target, key](const std::string& text) { *target = parse_length(text, "--" + key); },
           capitalised(info->help))
        ->check(length_check(key));
  }
  add_auto_parameter(cmd, p.grading, flags.given.grading);
  add_auto_parameter(cmd, p.curvature_points, flags.given.curvature_points);
  add_auto_parameter(cmd, p.thickness_layers, flags.given.thickness_layers);
}

void print_failed_thresholds(const std::string& input, const std::vector<ThresholdCheck>& checks,
                             const ImproveResult* improvement) {
  for (const ThresholdCheck& c : checks) {
    if (c.ok) continue;
    std::cerr << "meshprep: " << input << ": not FEM-ready: " << describe(c);
    const std::string limit =
        c.check == "min_dihedral_deg" && improvement ? surface_limit_note(*improvement, c.threshold) : "";
    std::cerr << (limit.empty() ? "" : "; " + limit) << '\n';
  }
}

std::string failed_names(const TetVerdict& verdict) {
  std::string names;
  for (const ThresholdCheck& c : verdict.failed()) names += (names.empty() ? "" : ", ") + c.check;
  return names;
}

ThreadLimit::ThreadLimit(std::size_t threads)
    : threads_(threads > 0 ? threads : std::max(1u, std::thread::hardware_concurrency())),
      control_(tbb::global_control::max_allowed_parallelism, threads_) {}

}  // namespace meshprep::cli
