#pragma once
// The module's functions: read and write, and one call per command (commands/) plus the pipeline,
// each with keywords from the configuration key table (keywords.h) and run as calls.h says.

#include <pybind11/pybind11.h>

namespace meshprep::python {

/// Registers Surface, TetMesh, CancelToken, read() and the _<command> calls on `module`.
void register_meshes(pybind11::module_& module);
void register_stages(pybind11::module_& module);

}  // namespace meshprep::python
