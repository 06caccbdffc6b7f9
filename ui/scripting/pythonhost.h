#pragma once

#include <QString>

namespace sylva::ui {

class MainWindow;

/// The Python interpreter embedded in the editor (pybind11 over Debian's python3), with the
/// `sylva` module bound to the running window's document (bindings.cpp; docs/scripting.md).
/// Everything runs on the GUI thread: a script that waits (sylva.wait, doc.generate) runs the
/// event loop, so the window, its timers and the generation worker keep going.
class PythonHost {
public:
    /// The embedded Python's version, e.g. "3.11.2".
    static QString version();
    /// Starts the interpreter once and imports `sylva`. Safe to call repeatedly.
    static void ensureStarted();
    /// The window the `sylva` module talks to (set by MainWindow).
    static void setWindow(MainWindow* window);
    static MainWindow* window();

    /// Runs a script file as `__main__`. Returns its exit status: 0 when it ends, the code of a
    /// SystemExit (sylva.quit(code)), 1 after an exception, whose traceback goes to stderr;
    /// Ctrl-C or SIGTERM while it runs raise KeyboardInterrupt where it is (also in a wait)
    /// and give 128 + the signal's number, with the traceback.
    static int runScript(const QString& path);

    /// One line of the console: `more` when the statement continues on the next line; the
    /// output and the errors (tracebacks) it printed. \p quitRequested when it called
    /// sylva.quit() or exit().
    struct ConsoleReply {
        bool more = false;
        QString output, errors;
        bool quitRequested = false;
        int exitCode = 0;
    };
    static ConsoleReply pushConsoleLine(const QString& line);
};

} // namespace sylva::ui
