#pragma once
/// \file exit_codes.h
/// The exit codes of meshprep's contract, the same for every command: the command line returns
/// them, the Python module's exceptions carry them (`exit_code`), the batch summary records them.
/// README.md, "Exit codes".

#include <exception>

namespace meshprep {

enum class ExitCode : int {
  ready = 0,         ///< done, and FEM-ready (or the command's own goal met)
  not_ready = 1,     ///< done and written, but not ready: the report names why
  bad_input = 2,     ///< bad input or arguments, found before any heavy work; nothing written
  failed = 3,        ///< failed while working (a solver, a guard, an output that cannot be written); nothing written
  time_limit = 124,  ///< the time limit ended the work before anything usable existed; nothing written
  interrupted = 130  ///< Ctrl-C (the command line gives 128 + the signal for SIGTERM and SIGHUP)
};

/// The exit code for the work that ended by throwing `failure`: InvalidInput and IoError (but
/// WriteError) -> bad_input, TimeLimitReached -> time_limit, Cancelled -> interrupted, anything
/// else (SolverError, WriteError, std::bad_alloc, ...) -> failed.
ExitCode exit_code_of(const std::exception& failure);

constexpr int as_int(ExitCode code) { return static_cast<int>(code); }

}  // namespace meshprep
