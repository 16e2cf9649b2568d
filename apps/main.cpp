// meshprep: FEM-ready surface and tetrahedral meshes with a clear report, in one command.
#include "cli_common.h"
#include "interrupt.h"
#include "solver_logging.h"

#include "meshprep/core/errors.h"
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
               "Exit codes: 0 success, 1 the work could not be done (with the reason), 2 bad usage or unreadable input.",
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
  CLI::App* help = app.add_subcommand("help", "Show this help, or a command's (meshprep help COMMAND)");
  std::string help_topic;
  help->add_option("command", help_topic, "The command to describe");
  cli::refuse_non_finite_numbers(app);

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
  try {
    for (const auto& [command, action] : actions)
      if (command->parsed()) return action();
    return cli::kBadInput;
  } catch (const Cancelled& e) {
    // A signal: 128 + its number, as a shell reports a process it ended; a timeout: the work
    // could not be done in time.
    const bool timeout = cli::timed_out();
    std::cerr << "meshprep: " << (timeout ? "failed: " : "") << e.what() << '\n';
    return timeout ? cli::kWorkFailed : cli::stopped_exit_code();
  } catch (const InvalidInput& e) {
    std::cerr << "meshprep: error: " << e.what() << '\n';
    return cli::kBadInput;
  } catch (const WriteError& e) {  // the input was fine; the result cannot be delivered
    std::cerr << "meshprep: failed: " << e.what() << '\n';
    return cli::kWorkFailed;
  } catch (const IoError& e) {
    std::cerr << "meshprep: error: " << e.what() << '\n';
    return cli::kBadInput;
  } catch (const cli::WorkFailed& e) {
    std::cerr << "meshprep: failed: " << e.what() << '\n';
    return cli::kWorkFailed;
  } catch (const std::bad_alloc&) {
    std::cerr << "meshprep: failed: out of memory\n";
    return cli::kWorkFailed;
  } catch (const std::exception& e) {
    std::cerr << "meshprep: failed: " << e.what() << '\n';
    return cli::kWorkFailed;
  }
}
