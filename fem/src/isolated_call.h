#pragma once
// Running work in a forked child process, so that a crash or abort there (TetGen may still abort
// on some inputs, e.g. through assertions or exit()) is reported instead of ending meshprep.

#include <functional>
#include <string>

namespace meshprep::detail {

struct IsolatedResult {
  bool crashed = false;  ///< the child died from a signal or exited without sending its result
  int signal = 0;        ///< the signal that ended it (0 if none)
  int exit_status = 0;
  std::string output;    ///< the bytes `work` returned in the child
};

/// Runs `work` in a child process and returns what it produced. The child must not touch shared
/// state it expects the parent to see; its stdout/stderr are the parent's. While it runs,
/// `cancelled` (if given) is asked every 50 ms; when it says yes the child is killed.
/// \throws IoError if the process cannot be created; Cancelled if it was stopped.
IsolatedResult call_isolated(const std::function<std::string()>& work,
                             const std::function<bool()>& cancelled = {});

}  // namespace meshprep::detail
