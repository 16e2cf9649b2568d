#pragma once
/// \file errors.h
/// The exception family thrown by every meshprep library. The library never prints and never
/// exits; exit_code_of (exit_codes.h) maps these to the exit codes of the contract.

#include <stdexcept>
#include <string>

namespace meshprep {

/// Base of every meshprep exception.
class Error : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// The input (a file's content, a parameter, a mesh's structure) cannot be used.
/// Messages name the file (when there is one) and the problem, on one line.
class InvalidInput : public Error {
 public:
  using Error::Error;
};

/// A file could not be opened or read (missing, permission), or written (then a WriteError).
class IoError : public Error {
 public:
  using Error::Error;
};

/// An output could not be written (disk full, permission, a folder missing): the input was fine and
/// the work may be done, but it cannot be delivered. Messages name the file.
class WriteError : public IoError {
 public:
  using IoError::IoError;
};

/// An algorithm could not do its work on valid input (e.g. a solver failed to converge).
class SolverError : public Error {
 public:
  using Error::Error;
};

/// The caller asked the work to stop (a cancellation callback said so, or a progress callback
/// threw it): nothing is half-done on the caller's side.
class Cancelled : public Error {
 public:
  using Error::Error;
};

/// The command's time limit (deadline.h) came before anything usable existed: nothing is written.
class TimeLimitReached : public Cancelled {
 public:
  using Cancelled::Cancelled;
};

}  // namespace meshprep
