#pragma once
// How a Python call runs meshprep's work: without the GIL (other Python threads go on), stopped
// within a poll by Ctrl-C (KeyboardInterrupt), by a CancelToken or by the progress callback
// raising, with progress(stage, fraction) called on the caller's thread; and meshprep's errors
// raised as the module's exceptions (Error -> InputError, NotReadyError, WorkError, TimeoutError,
// Cancelled), each with the CLI's exit code as `exit_code`.

#include "meshprep/commands/outcome.h"
#include "meshprep/core/errors.h"
#include "meshprep/core/parameter.h"

#include <pybind11/pybind11.h>
#include <tbb/task_arena.h>

#include <atomic>
#include <chrono>
#include <exception>
#include <mutex>
#include <optional>
#include <string>
#include <thread>

namespace meshprep::python {

namespace py = pybind11;

/// A flag another thread sets to stop a call: meshprep.CancelToken().
struct CancelToken {
  std::atomic<bool> cancelled{false};
};

/// The module's exception types, made once by register_exceptions.
struct ExceptionTypes {
  py::object error, input_error, not_ready_error, work_error, timeout_error, cancelled;
};
const ExceptionTypes& exception_types();

/// Makes the exception classes in `module` and the translator from meshprep's C++ errors.
void register_exceptions(py::module_& module);

/// The keywords of every call beside the configuration's: `threads` > 0 bounds the threads of the
/// call's parallel parts (a TBB arena of its own, so concurrent calls keep their own bounds);
/// `time_limit_seconds` > 0 is the call's deadline (0: none).
struct CallOptions {
  std::size_t threads = 0;
  double time_limit_seconds = 0;
};

/// One call's link to Python: its hooks poll Ctrl-C and the callback on the caller's thread.
class CallControl {
 public:
  /// With the GIL held. `progress` may be None, `cancel` null; the deadline starts now.
  CallControl(py::object progress, CancelToken* cancel, const CallOptions& options);

  const Deadline& deadline() const { return deadline_; }

  /// Hooks for the command, usable without the GIL; `stage` names the work to the callback.
  CommandHooks hooks(const std::string& stage);
  /// The pipeline's: it names its stages as they start.
  void set_stage(const std::string& stage);

  /// Runs `work` without the GIL; a Python error raised meanwhile (KeyboardInterrupt, the callback's)
  /// is raised in its place.
  template <class Work>
  auto run(Work&& work) -> decltype(work()) {
    std::optional<decltype(work())> result;
    std::exception_ptr failure;
    {
      py::gil_scoped_release release;
      try {
        if (threads_ > 0) {
          tbb::task_arena arena(static_cast<int>(threads_));
          arena.execute([&] { result.emplace(work()); });
        } else {
          result.emplace(work());
        }
      } catch (const Cancelled& e) {
        // Stopped at the deadline rather than by the user: TimeoutError.
        failure = !stop_ && !(cancel_ && cancel_->cancelled) && deadline_.passed()
                      ? std::make_exception_ptr(TimeLimitReached(std::string(e.what()) + ": the time limit (time_limit=" +
                                                                 parameter_text(time_limit_seconds_) + " s) came first"))
                      : std::current_exception();
      } catch (...) {
        failure = std::current_exception();
      }
    }
    raise_pending();
    if (failure) std::rethrow_exception(failure);
    return std::move(*result);
  }

  /// True when the work should stop; on the caller's thread, at most every 20 ms, takes the GIL to
  /// look for Ctrl-C and to call the progress callback with `fraction` (when >= 0).
  bool poll(double fraction);

 private:
  void raise_pending();

  py::object progress_;
  CancelToken* cancel_;
  std::size_t threads_;
  double time_limit_seconds_;
  Deadline deadline_;
  std::thread::id caller_ = std::this_thread::get_id();
  std::atomic<bool> stop_{false};
  std::mutex mutex_;  // guards stage_ and pending_
  std::string stage_;
  std::optional<py::error_already_set> pending_;
  std::chrono::steady_clock::time_point last_poll_{};
};

}  // namespace meshprep::python
