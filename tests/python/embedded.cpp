// The engine bindings inside an embedded interpreter, as the editor's `sylva` module uses them:
// PYBIND11_EMBEDDED_MODULE calls bindEngine beside its own names. Runs the script given as
// argument with the module importable; exits 1 on a Python exception.
#include <cstdio>

#include <pybind11/embed.h>

#include "python/bindings/engine.h"

namespace py = pybind11;

namespace {
// The editor's own names in the same module (ui/scripting/bindings.cpp): none may clash with
// bindEngine's (its trees are bindEngine's sylva.Tree).
struct DocumentApi {};
struct WindowApi {};
} // namespace

PYBIND11_EMBEDDED_MODULE(sylva, m) {
    sylva::python::bindEngine(m);
    py::class_<DocumentApi>(m, "Document");
    py::class_<WindowApi>(m, "Window");
    m.def("document", [] { return DocumentApi{}; });
    m.def("window", [] { return WindowApi{}; });
    m.def("wait", [](double) {});
    m.def("quit", [](int) {});
    m.def("embedded", [] { return true; });
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
