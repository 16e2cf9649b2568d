#pragma once
// Ctrl-C and --timeout: the signal handlers only set a flag; long work polls it at its safe points
// (progress callbacks, stage starts, every 50 ms while TetGen runs) and stops by throwing
// meshprep::Cancelled, so no output is half-written. A second Ctrl-C ends the process at once.

#include <functional>
#include <string>

namespace meshprep::cli {

/// Installs the SIGINT and SIGALRM handlers (once, from main).
void install_interrupt_handlers();

/// Stops the work after `seconds` (0 = never): SIGALRM sets the same flag as Ctrl-C.
void arm_timeout(unsigned seconds);

/// Ctrl-C was pressed or the timeout expired.
bool stop_requested();

/// The timeout (not Ctrl-C) stopped the work.
bool timed_out();

/// \throws Cancelled if a stop was requested: the check for a progress callback.
void throw_if_stop_requested();

/// A progress callback that draws `draw(fraction)` and then stops the work if asked.
std::function<void(double)> stoppable(std::function<void(double)> draw);

}  // namespace meshprep::cli
