#pragma once
// Ctrl-C, SIGTERM, SIGHUP and --time-limit: the signal handlers only set a flag; long work polls it at
// its safe points (progress callbacks, stage starts, every 50 ms while TetGen runs) and stops by
// throwing meshprep::Cancelled, so no output is half-written. A second signal ends the process at
// once. The time limit is a deadline the hooks carry (meshprep/core/deadline.h): the steps with
// nothing usable stop at it, the tet improvement ends there with its best tets.

#include "meshprep/core/deadline.h"

#include <functional>
#include <string>

namespace meshprep::cli {

/// Installs the SIGINT, SIGTERM and SIGHUP handlers (once, from main).
void install_interrupt_handlers();

/// Sets the whole command's deadline `seconds` from now (0: none), from --time-limit.
void set_time_limit(double seconds);

/// The deadline set_time_limit set (none unless --time-limit was given).
const Deadline& time_limit();

/// Ctrl-C was pressed, or SIGTERM or SIGHUP came.
bool stop_requested();

/// The exit code of a run a signal stopped, as a shell reports a process the signal ended:
/// 128 + the signal (130 for Ctrl-C, 143 for SIGTERM, 129 for SIGHUP).
int stopped_exit_code();

/// What stopped the work: "interrupted", "terminated (SIGTERM)" or "hung up (SIGHUP)".
std::string stop_reason();

/// \throws Cancelled if a stop was requested: the check for a progress callback.
void throw_if_stop_requested();

/// A progress callback that draws `draw(fraction)` and then stops the work if asked.
std::function<void(double)> stoppable(std::function<void(double)> draw);

}  // namespace meshprep::cli
