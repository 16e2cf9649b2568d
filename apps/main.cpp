// meshprep: FEM-ready surface and tetrahedral meshes with a clear report, in one command.
#include "cli_common.h"
#include "interrupt.h"
#include "solver_logging.h"

#include "meshprep/core/errors.h"
#include "meshprep/core/exit_codes.h"
#include "meshprep/core/heap_policy.h"

#include <algorithm>
#include <iostream>
#include <map>
#include <string>
#include <vector>

using namespace meshprep;

namespace {

// Levenshtein distance: the fewest insertions, deletions and substitutions from a to b.
std::size_t edit_distance(const std::string& a, const std::string& b) {
  std::vector<std::size_t> row(b.size() + 1);
  for (std::size_t j = 0; j <= b.size(); ++j) row[j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    std::size_t diagonal = row[0];
    row[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const std::size_t above = row[j];
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (a[i - 1] == b[j - 1] ? 0 : 1)});
      diagonal = above;
    }
  }
  return row[b.size()];
}

// "unknown command 'word'", with the closest command's name when a typo can explain it (at most
// a third of the word's letters changed).
std::string unknown_command(const CLI::App& app, const std::string& word) {
  std::string closest;
  std::size_t best = word.size() / 3 + 1;
  for (const CLI::App* command : app.get_subcommands({}))
    if (const std::size_t d = edit_distance(word, command->get_name()); d < best) best = d, closest = command->get_name();
  return "unknown command '" + word + "'" + (closest.empty() ? "" : " (did you mean '" + closest + "'?)");
}

// "INPUT: " of the command's input (its first positional argument), for the messages main prints
// ("" without one).
std::string input_of(const CLI::App& command) {
  const std::vector<const CLI::Option*> positionals =
      command.get_options([](const CLI::Option* option) { return option->get_positional(); });
  return !positionals.empty() && positionals.front()->count() > 0 ? positionals.front()->as<std::string>() + ": " : "";
}

const CLI::App* find_command(const CLI::App& app, const std::string& name) {
  for (const CLI::App* command : app.get_subcommands({}))
    if (command->check_name(name)) return command;
  return nullptr;
}

}  // namespace

int main(int argc, char** argv) {
  keep_freed_memory_for_reuse();
  cli::quiet_solver_logging(argv[0]);
  CLI::App app{"meshprep " MESHPREP_VERSION
               " - turn raw geometry into meshes a finite-element solver can trust.\n"
               "Exit codes (every command): 0 done and FEM-ready (or the command's goal met), 1 done and written but "
               "not ready (the report says why), 2 bad input or arguments (nothing written), 3 failed while working "
               "(nothing written), 124 --time-limit reached with nothing usable, 130 interrupted (143 SIGTERM, 129 SIGHUP).",
               "meshprep"};
  app.set_version_flag("--version", "meshprep " MESHPREP_VERSION);
  app.require_subcommand(1);
  app.fallthrough(false);
  std::map<const CLI::App*, cli::Action> actions;
  auto add = [&](cli::Action (*make)(CLI::App&)) {
    const std::size_t before = app.get_subcommands({}).size();
    cli::Action action = make(app);
    actions[app.get_subcommands({})[before]] = std::move(action);
  };
  add(cli::add_quality_command);
  add(cli::add_convert_command);
  add(cli::add_reconstruct_command);
  add(cli::add_simplify_command);
  add(cli::add_smooth_command);
  add(cli::add_enhance_command);
  add(cli::add_tetrahedralize_command);
  add(cli::add_improve_command);
  add(cli::add_pipeline_command);
  add(cli::add_repair_command);
  add(cli::add_patches_command);
  add(cli::add_batch_command);
  CLI::App* help = app.add_subcommand("help", "Show this help, or a command's (meshprep help COMMAND)");
  std::string help_topic;
  help->add_option("command", help_topic, "The command to describe");
  // One --time-limit for every command: the whole command's deadline (interrupt.h).
  double time_limit_seconds = 0;
  for (CLI::App* command : app.get_subcommands({}))
    if (command != help && command->get_name() != "batch")  // the batch's is each part's
      command
          ->add_option("--time-limit,--timeout", time_limit_seconds,
                       "Stop the whole command after this many seconds: the enhancement and the tet improvement end "
                       "with their best result (\"stopped\": \"time limit\" in --json), any other step with "
                       "nothing written (exit 124)")
          ->check(cli::positive());
  cli::refuse_non_finite_numbers(app);

  // The batch's arguments are its driver's, `--` and the pipeline flags after it included.
  if (argc >= 2 && std::string(argv[1]) == "batch") {
    try {
      return cli::run_batch(std::vector<std::string>(argv + 2, argv + argc));
    } catch (const std::exception& e) {
      std::cerr << "meshprep: error: " << e.what() << '\n';
      return cli::kBadInput;
    }
  }
  // CLI11 takes an unknown first word for a stray argument ("A subcommand is required").
  if (argc >= 2 && argv[1][0] != '-' && !find_command(app, argv[1])) {
    std::cerr << "meshprep: error: " << unknown_command(app, argv[1]) << " (see meshprep --help)\n";
    return cli::kBadInput;
  }
  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForVersion& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    std::cerr << "meshprep: error: " << e.what() << " (see meshprep --help)\n";
    return cli::kBadInput;
  }
  if (help->parsed()) {
    if (help_topic.empty()) {
      std::cout << app.help();
      return cli::kSuccess;
    }
    if (const CLI::App* command = find_command(app, help_topic)) {
      std::cout << command->help();
      return cli::kSuccess;
    }
    std::cerr << "meshprep: error: " << unknown_command(app, help_topic) << " (see meshprep --help)\n";
    return cli::kBadInput;
  }
  cli::install_interrupt_handlers();
  cli::set_time_limit(time_limit_seconds);
  const CLI::App* command = nullptr;
  for (const auto& [candidate, action] : actions)
    if (candidate->parsed()) command = candidate;
  if (command == nullptr) return cli::kBadInput;
  try {
    return actions.at(command)();
  } catch (const cli::NotReady& e) {  // written, not ready
    std::cerr << "meshprep: not ready: " << e.what() << '\n';
    return cli::kNotReady;
  } catch (const Cancelled& e) {
    // A signal: 128 + its number, as a shell reports a process it ended. Otherwise the deadline
    // came before anything usable existed (the improvement, which has its best tets, ends there).
    if (cli::stop_requested() || !cli::time_limit().passed()) {
      std::cerr << "meshprep: " << e.what() << '\n';
      return cli::stopped_exit_code();
    }
    std::cerr << "meshprep: failed: " << input_of(*command) << "the time limit (--time-limit "
              << CLI::detail::to_string(time_limit_seconds) << " s) came before anything usable was made; nothing written\n";
    return as_int(ExitCode::time_limit);
  } catch (const std::bad_alloc&) {
    std::cerr << "meshprep: failed: " << input_of(*command) << "out of memory; nothing written\n";
    return as_int(ExitCode::failed);
  } catch (const std::exception& e) {
    const ExitCode code = exit_code_of(e);
    std::cerr << "meshprep: " << (code == ExitCode::bad_input ? "error: " : "failed: ") << e.what() << '\n';
    return as_int(code);
  }
}
