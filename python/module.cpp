// `import sylva`: the engine's bindings as an extension module for Debian's python3 (and so
// for Debian's Blender).
#include "python/bindings/engine.h"

PYBIND11_MODULE(sylva, m) {
    m.doc() = "Sylva: procedural trees and forests (species, growth, forests, export).";
    sylva::python::bindEngine(m);
}
