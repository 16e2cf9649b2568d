#pragma once
// A library stage that cannot do its work on valid input throws SolverError naming itself, and
// InvalidInput for what it cannot take; the front end adds the file, so that every failure line
// names the file.

#include "cli_common.h"

#include "meshprep/core/errors.h"

#include <string>

namespace meshprep::cli {

/// `stage()`'s result; its SolverError rethrown as WorkFailed ("INPUT: what", exit 1), its
/// InvalidInput as InvalidInput("INPUT: what", exit 2).
template <class Stage>
auto run_stage_on(const std::string& input, Stage&& stage) -> decltype(stage()) {
  try {
    return stage();
  } catch (const SolverError& e) {
    throw WorkFailed(input + ": " + e.what());
  } catch (const InvalidInput& e) {
    throw InvalidInput(input + ": " + e.what());
  }
}

}  // namespace meshprep::cli
