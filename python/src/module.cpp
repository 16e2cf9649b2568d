// The extension module meshprep._meshprep; meshprep/__init__.py is its public face.
#include "calls.h"
#include "stages.h"

#include <pybind11/pybind11.h>

PYBIND11_MODULE(_meshprep, module) {
  module.doc() = "meshprep's C++ core: meshes as numpy arrays and the commands (see meshprep/__init__.py)";
  meshprep::python::register_exceptions(module);
  meshprep::python::register_meshes(module);
  meshprep::python::register_stages(module);
}
