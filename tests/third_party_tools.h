#pragma once
// The third-party programs some tests use to write, read or solve on tet meshes (gmsh, Python's
// meshio, CalculiX), and
// whether they are here: a test that needs a missing one skips with a message.

#include <sys/wait.h>

#include <cstdlib>
#include <string>

namespace meshprep::test {

/// Whether the shell command exits with 0.
inline bool succeeds(const std::string& command) {
  const int status = std::system(command.c_str());
  return status != -1 && WIFEXITED(status) && WEXITSTATUS(status) == 0;
}

/// The first Python 3 that can import `modules` ("dolfinx", "meshio, numpy"), or "" if none: the
/// one on PATH, else the system one.
inline std::string python_with(const std::string& modules) {
  for (const char* python : {"python3", "/usr/bin/python3"})
    if (succeeds(std::string(python) + " -c 'import " + modules + "' >/dev/null 2>&1")) return python;
  return "";
}

/// The first Python 3 that can import meshio and numpy, or "" if none (a pyenv or venv python3
/// on PATH does not see Debian's python3-meshio).
inline std::string python_with_meshio() { return python_with("meshio, numpy"); }

/// Whether gmsh is on PATH.
inline bool has_gmsh() { return succeeds("command -v gmsh >/dev/null 2>&1"); }

/// Whether CalculiX's ccx is on PATH.
inline bool has_ccx() { return succeeds("command -v ccx >/dev/null 2>&1"); }

}  // namespace meshprep::test
