#include "ui/scripting/pythonhost.h"

#include <cstdio>

#include <pybind11/embed.h>

#include <QFile>
#include <QFileInfo>

namespace py = pybind11;

namespace sylva::ui {

void linkSylvaModule(); // bindings.cpp

namespace {

MainWindow* gWindow = nullptr;

const char* const kConsoleCode = R"(
import code as _code, io as _io, sys as _sys
import sylva as _sylva

class _SylvaConsole(_code.InteractiveConsole):
    pass

_console = _SylvaConsole({"__name__": "__console__", "sylva": _sylva,
                          "doc": _sylva.document()})

def _push(line):
    out, err = _io.StringIO(), _io.StringIO()
    old = _sys.stdout, _sys.stderr
    _sys.stdout, _sys.stderr = out, err
    code = None
    try:
        more = _console.push(line)
    except SystemExit as e:
        more = False
        code = e.code if isinstance(e.code, int) else (0 if e.code is None else 1)
    finally:
        _sys.stdout, _sys.stderr = old
    return more, out.getvalue(), err.getvalue(), code
)";

void flushStreams() {
    try {
        py::module_ sys = py::module_::import("sys");
        for (const char* name : {"stdout", "stderr"}) {
            py::object stream = sys.attr(name);
            if (!stream.is_none()) stream.attr("flush")();
        }
    } catch (const py::error_already_set&) {
    }
}

} // namespace

QString PythonHost::version() {
    return QStringLiteral(PY_VERSION);
}

void PythonHost::ensureStarted() {
    linkSylvaModule();
    if (Py_IsInitialized()) return;
    py::initialize_interpreter(/*init_signal_handlers=*/false);
    py::module_::import("sylva");
    // The interpreter stays for the life of the process; the GUI thread holds the GIL.
}

void PythonHost::setWindow(MainWindow* window) {
    gWindow = window;
}

MainWindow* PythonHost::window() {
    return gWindow;
}

int PythonHost::runScript(const QString& path) {
    ensureStarted();
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly)) {
        std::fprintf(stderr, "sylva: cannot read script %s: %s\n", path.toLocal8Bit().constData(),
                     file.errorString().toLocal8Bit().constData());
        return 1;
    }
    const std::string source = file.readAll().toStdString();
    int status = 0;
    try {
        py::dict globals;
        globals["__name__"] = "__main__";
        globals["__file__"] = QFileInfo(path).absoluteFilePath().toStdString();
        globals["__builtins__"] = py::module_::import("builtins");
        py::module_::import("sys").attr("argv") = py::make_tuple(path.toStdString());
        py::object compiled =
            py::module_::import("builtins").attr("compile")(source, path.toStdString(), "exec");
        py::module_::import("builtins").attr("exec")(compiled, globals);
    } catch (py::error_already_set& e) {
        if (e.matches(PyExc_SystemExit)) {
            py::object code = e.value().attr("code");
            status = code.is_none() ? 0 : (py::isinstance<py::int_>(code) ? code.cast<int>() : 1);
            if (!code.is_none() && !py::isinstance<py::int_>(code))
                std::fprintf(stderr, "%s\n", py::str(code).cast<std::string>().c_str());
        } else {
            e.restore();
            PyErr_Print(); // the traceback, as python3 prints it
            status = 1;
        }
    }
    flushStreams();
    return status;
}

PythonHost::ConsoleReply PythonHost::pushConsoleLine(const QString& line) {
    ensureStarted();
    ConsoleReply reply;
    try {
        py::module_ main = py::module_::import("__main__");
        if (!py::hasattr(main, "_sylva_console_push")) {
            py::dict scope;
            py::exec(kConsoleCode, scope);
            main.attr("_sylva_console_push") = scope["_push"];
        }
        py::tuple r = main.attr("_sylva_console_push")(line.toStdString());
        reply.more = r[0].cast<bool>();
        reply.output = QString::fromStdString(r[1].cast<std::string>());
        reply.errors = QString::fromStdString(r[2].cast<std::string>());
        if (!r[3].is_none()) {
            reply.quitRequested = true;
            reply.exitCode = r[3].cast<int>();
        }
    } catch (const py::error_already_set& e) {
        reply.errors = QString::fromUtf8(e.what());
    }
    return reply;
}

} // namespace sylva::ui
