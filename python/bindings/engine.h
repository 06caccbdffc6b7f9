#pragma once

#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

namespace sylva::python {

/// Adds Sylva's engine to \p m: species (load, parameters, grow → skeleton and mesh as numpy
/// arrays), projects and forests (build, statistics, CO2, obstacles from files or arrays),
/// export to OBJ/glTF/FBX, and the exception translation (ValueError, OSError,
/// KeyboardInterrupt, MemoryError with the CLI's messages). The extension module `sylva` is only
/// this; the editor's embedded `sylva` module calls it too, beside its document and window.
/// The names are a public contract: docs/python.md.
void bindEngine(pybind11::module_& m);

} // namespace sylva::python
