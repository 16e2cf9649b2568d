// meshprep: FEM-ready surface and tetrahedral meshes with a clear report, in one command.
#include "cli_common.h"
#include "heap_policy.h"
#include "interrupt.h"
#include "solver_logging.h"

#include "meshprep/core/errors.h"

#include <iostream>
#include <map>

using namespace meshprep;

int main(int argc, char** argv) {
  cli::keep_freed_memory_for_reuse();
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
  CLI::App* help = app.add_subcommand("help", "Show this help");
  cli::refuse_non_finite_numbers(app);

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
    std::cout << app.help();
    return cli::kSuccess;
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
