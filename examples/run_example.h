#pragma once
// What every example shares: the exit codes of the meshprep CLI contract and the mapping of the
// library's exceptions onto them (the library itself never prints and never exits).

#include "meshprep/core/errors.h"

#include <exception>
#include <iostream>
#include <string>

namespace meshprep::examples {

enum ExitCode : int { kSuccess = 0, kWorkFailed = 1, kBadInput = 2 };

/// The body of an example's main(). `usage` is "NAME [ARGUMENTS]"; -h or --help prints it (exit
/// 0), more than `max_arguments` arguments print it to stderr (exit 2). Otherwise runs `body`
/// (which returns an ExitCode) and turns an exception into one line on stderr and an exit code:
/// InvalidInput and IoError (bad usage, unreadable input) -> 2, any other meshprep error (a solver
/// or TetGen failure, an output that cannot be written: WriteError) -> 1.
template <class Body>
int run_example(int argc, char** argv, const std::string& usage, int max_arguments, Body body) {
  const std::string name = usage.substr(0, usage.find(' '));
  if (argc > 1 && (std::string(argv[1]) == "-h" || std::string(argv[1]) == "--help")) {
    std::cout << "usage: " << usage << '\n';
    return kSuccess;
  }
  if (argc - 1 > max_arguments) {
    std::cerr << "usage: " << usage << '\n';
    return kBadInput;
  }
  try {
    return body();
  } catch (const InvalidInput& e) {
    std::cerr << name << ": " << e.what() << '\n';
    return kBadInput;
  } catch (const WriteError& e) {
    std::cerr << name << ": " << e.what() << '\n';
    return kWorkFailed;
  } catch (const IoError& e) {
    std::cerr << name << ": " << e.what() << '\n';
    return kBadInput;
  } catch (const Error& e) {
    std::cerr << name << ": " << e.what() << '\n';
    return kWorkFailed;
  }
}

/// The positive number in `text`, or InvalidInput naming `what`.
inline double parse_positive(const std::string& text, const std::string& what) {
  std::size_t used = 0;
  double value = 0;
  try {
    value = std::stod(text, &used);
  } catch (const std::exception&) {
    used = 0;
  }
  if (used == 0 || used != text.size() || !(value > 0))
    throw InvalidInput(what + " must be a positive number, not '" + text + "'");
  return value;
}

}  // namespace meshprep::examples
