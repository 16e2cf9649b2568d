#pragma once
// Ctrl-C, SIGTERM, SIGHUP and --timeout: the signal handlers only set a flag; long work polls it at its safe points
// (progress callbacks, stage starts, every 50 ms while TetGen runs) and stops by throwing
// meshprep::Cancelled, so no output is half-written. A second signal ends the process at once.

#include <functional>
#include <string>

namespace meshprep::cli {

/// Installs the SIGINT, SIGTERM, SIGHUP and SIGALRM handlers (once, from main).
void install_interrupt_handlers();

/// Stops the work after `seconds` (0 = never): SIGALRM sets the same flag as Ctrl-C.
void arm_timeout(unsigned seconds);

/// Ctrl-C was pressed, SIGTERM or SIGHUP came, or the timeout expired.
bool stop_requested();

/// The timeout (not a signal) stopped the work.
bool timed_out();

/// The exit code of a run a signal stopped, as a shell reports a process the signal ended:
/// 128 + the signal (130 for Ctrl-C, 143 for SIGTERM, 129 for SIGHUP).
int stopped_exit_code();

/// What stopped the work: "interrupted", "terminated (SIGTERM)", "hung up (SIGHUP)" or "timed out".
std::string stop_reason();

/// \throws Cancelled if a stop was requested: the check for a progress callback.
void throw_if_stop_requested();

/// A progress callback that draws `draw(fraction)` and then stops the work if asked.
std::function<void(double)> stoppable(std::function<void(double)> draw);

}  // namespace meshprep::cli
