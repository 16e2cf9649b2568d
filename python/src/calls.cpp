#include "calls.h"

#include "meshprep/core/errors.h"
#include "meshprep/core/exit_codes.h"

#include <algorithm>

namespace meshprep::python {
namespace {

ExceptionTypes& types() {
  static ExceptionTypes* instance = new ExceptionTypes();  // never destroyed: Python owns the classes
  return *instance;
}

// A class `name`(bases...) in `module` with the CLI's exit code as a class attribute.
py::object make_exception(py::module_& module, const char* name, py::tuple bases, int exit_code, const char* doc) {
  py::dict attributes;
  attributes["exit_code"] = exit_code;
  attributes["__doc__"] = doc;
  attributes["__module__"] = "meshprep";
  py::object type = py::reinterpret_borrow<py::object>(reinterpret_cast<PyObject*>(&PyType_Type))(name, bases, attributes);
  module.attr(name) = type;
  return type;
}

void raise(const py::object& type, const char* message) { PyErr_SetString(type.ptr(), message); }

}  // namespace

const ExceptionTypes& exception_types() { return types(); }

void register_exceptions(py::module_& module) {
  ExceptionTypes& t = types();
  const py::object builtins = py::module_::import("builtins");
  t.error = make_exception(module, "Error", py::make_tuple(builtins.attr("Exception")), 3,
                           "Base of meshprep's exceptions; exit_code is the command line's for the same failure.");
  t.input_error = make_exception(module, "InputError", py::make_tuple(t.error, builtins.attr("ValueError")), 2,
                                 "The input cannot be used (a file, an array, a keyword): nothing was done.");
  t.not_ready_error = make_exception(
      module, "NotReadyError", py::make_tuple(t.error), 1,
      "The work is done but the result is not FEM-ready: .result holds it (mesh and figures), .report its figures.");
  t.work_error = make_exception(module, "WorkError", py::make_tuple(t.error), 3,
                                "The work failed on valid input (a solver, a guard, a file that cannot be written).");
  t.timeout_error = make_exception(module, "TimeoutError", py::make_tuple(t.error, builtins.attr("TimeoutError")), 124,
                                   "The work ran out of its time limit: nothing was written.");
  t.cancelled = make_exception(module, "Cancelled", py::make_tuple(t.error), 130,
                               "A CancelToken stopped the work: nothing was written.");
  // One mapping for the command line and the module: the exception's exit code picks its class.
  py::register_exception_translator([](std::exception_ptr failure) {
    if (!failure) return;
    const ExceptionTypes& raised = exception_types();
    try {
      std::rethrow_exception(failure);
    } catch (const Error& e) {
      switch (exit_code_of(e)) {
        case ExitCode::bad_input: return raise(raised.input_error, e.what());
        case ExitCode::time_limit: return raise(raised.timeout_error, e.what());
        case ExitCode::interrupted: return raise(raised.cancelled, e.what());
        default: return raise(raised.work_error, e.what());
      }
    }
  });
}

CallControl::CallControl(py::object progress, CancelToken* cancel, const CallOptions& options)
    : progress_(std::move(progress)),
      cancel_(cancel),
      threads_(options.threads),
      time_limit_seconds_(options.time_limit_seconds),
      deadline_(Deadline::in_seconds(options.time_limit_seconds)) {}

CommandHooks CallControl::hooks(const std::string& stage) {
  set_stage(stage);
  CommandHooks hooks;
  hooks.progress = [this](double fraction) {
    if (poll(fraction)) throw Cancelled("cancelled");
  };
  hooks.cancelled = [this] { return poll(-1); };
  hooks.deadline = deadline_;
  return hooks;
}

void CallControl::set_stage(const std::string& stage) {
  std::lock_guard<std::mutex> lock(mutex_);
  stage_ = stage;
}

bool CallControl::poll(double fraction) {
  if (stop_ || (cancel_ && cancel_->cancelled)) return true;
  if (std::this_thread::get_id() != caller_) return false;  // TBB's workers: only the flags
  const auto now = std::chrono::steady_clock::now();
  if (now - last_poll_ < std::chrono::milliseconds(20) && fraction < 1) return false;
  last_poll_ = now;
  py::gil_scoped_acquire acquire;
  try {
    if (PyErr_CheckSignals() != 0) throw py::error_already_set();  // Ctrl-C: KeyboardInterrupt
    if (fraction >= 0 && !progress_.is_none()) {
      std::string stage;
      {
        std::lock_guard<std::mutex> lock(mutex_);
        stage = stage_;
      }
      progress_(stage, std::min(fraction, 1.0));
    }
  } catch (py::error_already_set& e) {
    std::lock_guard<std::mutex> lock(mutex_);
    if (!pending_) pending_.emplace(std::move(e));
    stop_ = true;
  }
  return stop_;
}

void CallControl::raise_pending() {
  std::optional<py::error_already_set> pending;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    pending.swap(pending_);
  }
  if (pending) throw std::move(*pending);
}

}  // namespace meshprep::python
