#pragma once
// A library stage that cannot do its work on valid input throws SolverError naming itself, and
// InvalidInput for what it cannot take; the command adds its input's name, so that every failure
// line names the file.

#include "meshprep/core/errors.h"

#include <string>

namespace meshprep {

/// `stage()`'s result; its SolverError and InvalidInput rethrown with "INPUT: " in front.
template <class Stage>
auto run_stage_on(const std::string& input, Stage&& stage) -> decltype(stage()) {
  try {
    return stage();
  } catch (const SolverError& e) {
    throw SolverError(input + ": " + e.what());
  } catch (const InvalidInput& e) {
    throw InvalidInput(input + ": " + e.what());
  }
}

}  // namespace meshprep
