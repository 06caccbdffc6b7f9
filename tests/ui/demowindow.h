#pragma once

// The editor window most QtTest suites start from: the reference alder demo copied into a
// scratch folder (so a test may save over it) and opened in a shown, exposed, active window that
// discards unsaved edits when it asks.

#include <memory>

#include <QApplication>
#include <QDir>
#include <QSize>
#include <QString>
#include <QTemporaryDir>
#include <QTest>

#include "document/document.h"
#include "document/presetlibrary.h"
#include "ui/mainwindow.h"

namespace sylva::ui::test {

/// The reference alder demo saved into \p dir as demo.sylva (its species paths rebased);
/// returns the copy's path.
inline QString copyDemoProject(const QTemporaryDir& dir) {
    doc::Document demo;
    demo.open(
        QDir(doc::PresetLibrary::directory()).filePath("../resources/demo/alder-reference.sylva"));
    const QString project = dir.filePath(QStringLiteral("demo.sylva"));
    demo.save(project);
    return project;
}

/// A new editor window of \p size, shown and active, answering "Discard" to every question;
/// null when it was not exposed.
inline std::unique_ptr<MainWindow> showEditorWindow(QSize size) {
    auto window = std::make_unique<MainWindow>();
    window->setAskHandler([](const QString&, bool) { return MainWindow::Answer::Discard; });
    window->resize(size);
    window->show();
    if (!QTest::qWaitForWindowExposed(window.get())) return nullptr;
    window->activateWindow();
    QApplication::setActiveWindow(window.get());
    return window;
}

/// The demo copied into \p dir and opened in a window from showEditorWindow (generation may
/// still be running); null when the window was not exposed or the project did not open.
inline std::unique_ptr<MainWindow> openDemoWindow(const QTemporaryDir& dir, QSize size) {
    const QString project = copyDemoProject(dir);
    auto window = showEditorWindow(size);
    if (!window || !window->openProject(project)) return nullptr;
    return window;
}

} // namespace sylva::ui::test
