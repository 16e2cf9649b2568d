#pragma once
// Ceres (the enhancement's solver) logs through glog. A residual it cannot evaluate (a degenerate
// face) makes it print a 36-line warning per face on stderr; the stages report their own failures,
// so the command line keeps its one error line.

namespace meshprep::cli {

/// Before any stage runs: glog to stderr only (no log files under /tmp), fatal messages only.
void quiet_solver_logging(const char* program);

}  // namespace meshprep::cli
