// The extension module meshprep._meshprep; meshprep/__init__.py is its public face.
#include "calls.h"
#include "stages.h"

#include "meshprep/core/heap_policy.h"

#include <pybind11/pybind11.h>

PYBIND11_MODULE(_meshprep, module) {
  module.doc() = "meshprep's C++ core: meshes as numpy arrays and the commands (see meshprep/__init__.py)";
  // The command line's heap policy: mesh-sized arrays freed by one call are reused by the next
  // instead of being faulted in again (quality() on 1.2 M faces: 2.4 -> 1.8 s, bench/RESULTS.md).
  meshprep::keep_freed_memory_for_reuse();
  meshprep::python::register_exceptions(module);
  meshprep::python::register_meshes(module);
  meshprep::python::register_stages(module);
}
