#include "ui/scripting/pythonhost.h"

#include <csignal>
#include <cstdio>
#include <string>
#include <utility>
#include <vector>

#include <signal.h>
#include <unistd.h>

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

/// The signal that stopped the running script (0: none), and the handlers that stood before
/// onStopSignal() (the chain below).
int gStopSignal = 0;
struct sigaction gBeforeStop[NSIG];
volatile std::sig_atomic_t gStopping = 0;

/// The first of the chain (async-signal-safe): a script stuck in native code never reaches
/// Python's handler, so the signal's own ending follows 10 s later (SIGALRM's default action
/// ends the process, as the signal would have); then faulthandler, then Python's handler.
extern "C" void onStopSignal(int number, siginfo_t* info, void* context) {
    // `timeout` signals its child and then the whole group: one stack printed is enough.
    if (gStopping != 0) return;
    gStopping = 1;
    alarm(10);
    const struct sigaction& next = gBeforeStop[number];
    if ((next.sa_flags & SA_SIGINFO) != 0) {
        if (next.sa_sigaction != nullptr) next.sa_sigaction(number, info, context);
    } else if (next.sa_handler != SIG_DFL && next.sa_handler != SIG_IGN) {
        next.sa_handler(number);
    }
}

/// While a script runs, Ctrl-C and SIGTERM (`timeout`, a job scheduler) stop it where it is, as
/// Ctrl-C stops python3: KeyboardInterrupt is raised at the line it runs or in the sylva wait
/// it is in (they let signals in), its traceback goes to stderr and the editor exits with 128 +
/// the signal's number, the status the signal alone gives. faulthandler first prints the
/// script's stack from the signal handler itself: `timeout N xvfb-run sylva` ends the X server
/// at the same moment, and the editor then leaves ("The X11 connection broke") before Python
/// runs. Before, the process died silently: a script in sylva.wait(500) (seconds; meant as
/// milliseconds) looked like a hang in the undo calls after it. A signal the caller ignores
/// (nohup) stays ignored.
class ScriptSignals {
public:
    ScriptSignals() {
        gStopSignal = 0;
        gStopping = 0;
        py::module_ signal = py::module_::import("signal");
        py::module_ faulthandler = py::module_::import("faulthandler");
        const py::cpp_function stop([](int number, const py::object&) {
            gStopSignal = number;
            const std::string message =
                "stopped by " +
                py::str(py::module_::import("signal").attr("Signals")(number).attr("name"))
                    .cast<std::string>();
            PyErr_SetString(PyExc_KeyboardInterrupt, message.c_str());
            throw py::error_already_set();
        });
        for (const int number : {SIGINT, SIGTERM}) {
            if (!signal.attr("getsignal")(number).equal(signal.attr("SIG_DFL"))) continue;
            mSaved.emplace_back(number, signal.attr("signal")(number, stop));
            faulthandler.attr("register")(
                number, py::arg("file") = py::module_::import("sys").attr("stderr"),
                py::arg("all_threads") = true, py::arg("chain") = true);
            struct sigaction ours {};
            ours.sa_sigaction = onStopSignal;
            ours.sa_flags = SA_SIGINFO | SA_ONSTACK;
            sigemptyset(&ours.sa_mask);
            sigaction(number, &ours, &gBeforeStop[number]);
        }
    }
    ~ScriptSignals() {
        try {
            py::module_ signal = py::module_::import("signal");
            py::module_ faulthandler = py::module_::import("faulthandler");
            for (auto& [number, handler] : mSaved) {
                sigaction(number, &gBeforeStop[number], nullptr);
                faulthandler.attr("unregister")(number);
                signal.attr("signal")(number, handler);
            }
        } catch (const py::error_already_set&) {
        }
    }
    ScriptSignals(const ScriptSignals&) = delete;
    ScriptSignals& operator=(const ScriptSignals&) = delete;

private:
    std::vector<std::pair<int, py::object>> mSaved;
};

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
    const ScriptSignals stopOnSignals;
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
            const bool interrupted = e.matches(PyExc_KeyboardInterrupt);
            e.restore();
            PyErr_Print(); // the traceback, as python3 prints it
            status = interrupted ? 128 + (gStopSignal != 0 ? gStopSignal : SIGINT) : 1;
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
