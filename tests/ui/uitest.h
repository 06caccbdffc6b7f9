#pragma once

// Helpers the editor's QtTest suites share: where screenshots go, and a mouse drag as a hand
// makes it (press, moves with the button held, release).

#include <vector>

#include <QApplication>
#include <QDir>
#include <QMouseEvent>
#include <QPoint>
#include <QString>
#include <QTest>
#include <QWidget>

namespace sylva::ui::test {

/// A file in the tests' output folder (screenshots a person looks at).
inline QString outputPath(const QString& name) {
    return QDir(QStringLiteral(SYLVA_UI_TEST_OUTPUT_DIR)).filePath(name);
}

/// Presses the left button at path.front(), moves through each point of \p path (\p steps moves
/// per leg, the button held) and releases at path.back().
inline void dragThrough(QWidget* w, const std::vector<QPoint>& path,
                        Qt::KeyboardModifiers modifiers = {}, int steps = 10) {
    QTest::mousePress(w, Qt::LeftButton, modifiers, path.front());
    for (std::size_t leg = 1; leg < path.size(); ++leg)
        for (int i = 1; i <= steps; ++i) {
            const QPoint p = path[leg - 1] + (path[leg] - path[leg - 1]) * i / steps;
            QMouseEvent move(QEvent::MouseMove, p, w->mapToGlobal(p), Qt::NoButton, Qt::LeftButton,
                             modifiers);
            QApplication::sendEvent(w, &move);
        }
    QTest::mouseRelease(w, Qt::LeftButton, modifiers, path.back());
}

} // namespace sylva::ui::test
