// The engine bindings inside an embedded interpreter, as the editor's `sylva` module uses them:
// PYBIND11_EMBEDDED_MODULE calls bindEngine beside its own names. Runs the script given as
// argument with the module importable; exits 1 on a Python exception.
#include <cstdio>

#include <pybind11/embed.h>

#include "python/bindings/engine.h"

namespace py = pybind11;

PYBIND11_EMBEDDED_MODULE(sylva, m) {
    m.def("embedded", [] { return true; }); // stands for the editor's document(), window()
    sylva::python::bindEngine(m);
}

int main(int argc, char** argv) {
    if (argc != 2) {
        std::fprintf(stderr, "usage: %s script.py\n", argv[0]);
        return 2;
    }
    py::scoped_interpreter python;
    try {
        py::eval_file(argv[1]);
    } catch (const py::error_already_set& e) {
        std::fprintf(stderr, "%s\n", e.what());
        return 1;
    }
    return 0;
}
