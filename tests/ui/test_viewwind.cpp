// Wind in the editor (issue 31) as a user meets it: View ▸ Wind on, the trees of a project
// sway (two grabs at two times of the frozen wind clock differ), off they stand still (the
// same two grabs are identical); the project's wind set in the Properties panel is one undo
// step, and undo gives back the exact file bytes; the species preview sways too.
#include <memory>

#include <QAction>
#include <QApplication>
#include <QDir>
#include <QDoubleSpinBox>
#include <QMenu>
#include <QMenuBar>
#include <QSettings>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QTest>

#include "document/document.h"
#include "document/presetlibrary.h"
#include "ui/document/propertiespanel.h"
#include "ui/mainwindow.h"
#include "ui/viewport/viewport.h"
#include "uitest.h"

using namespace sylva;
using namespace sylva::ui;

namespace {

constexpr int kTimeoutMs = 120000;

/// Pixels that differ between two grabs of one size.
int differingPixels(const QImage& a, const QImage& b) {
    if (a.size() != b.size()) return a.width() * a.height();
    int n = 0;
    for (int y = 0; y < a.height(); ++y) {
        const auto* pa = reinterpret_cast<const QRgb*>(a.constScanLine(y));
        const auto* pb = reinterpret_cast<const QRgb*>(b.constScanLine(y));
        for (int x = 0; x < a.width(); ++x)
            n += pa[x] != pb[x] ? 1 : 0;
    }
    return n;
}

} // namespace

class TestViewWind : public QObject {
    Q_OBJECT

private:
    std::unique_ptr<MainWindow> mWindow;
    QTemporaryDir mDir;

    doc::Document& document() { return mWindow->document(); }
    QAction* windAction() { return mWindow->findChild<QAction*>(QStringLiteral("actionViewWind")); }
    QImage grabAt(double seconds) {
        mWindow->setWindTime(seconds);
        return mWindow->viewport()->grabSharp().convertToFormat(QImage::Format_RGB32);
    }

private Q_SLOTS:
    void initTestCase() {
        QStandardPaths::setTestModeEnabled(true); // settings in a test folder
        QSettings().remove(QStringLiteral("view/wind"));
        QVERIFY(mDir.isValid());
        doc::Document demo;
        demo.open(QDir(doc::PresetLibrary::directory())
                      .filePath("../resources/demo/alder-reference.sylva"));
        const QString project = mDir.filePath(QStringLiteral("demo.sylva"));
        demo.save(project);
        mWindow = std::make_unique<MainWindow>();
        mWindow->setAskHandler([](const QString&, bool) { return MainWindow::Answer::Discard; });
        mWindow->resize(1000, 700);
        mWindow->show();
        QVERIFY(QTest::qWaitForWindowExposed(mWindow.get()));
        QVERIFY(mWindow->openProject(project));
        QVERIFY(mWindow->waitForGeneration(kTimeoutMs));
        QVERIFY2(mWindow->lastError().isEmpty(), qPrintable(mWindow->lastError()));
        QVERIFY(!mWindow->viewport()->trees().empty());
    }

    void cleanupTestCase() { mWindow.reset(); }

    /// View ▸ Wind is a checkable action of the View menu, off at first, remembered.
    void viewMenuHasWind() {
        QAction* wind = windAction();
        QVERIFY(wind);
        QVERIFY(wind->isCheckable());
        QVERIFY(!wind->isChecked());
        QMenu* view = mWindow->menuBar()->findChild<QMenu*>(QStringLiteral("viewMenu"));
        QVERIFY(view);
        QVERIFY(view->actions().contains(wind));
        wind->setChecked(true);
        QCOMPARE(QSettings().value(QStringLiteral("view/wind")).toBool(), true);
        QVERIFY(mWindow->viewport()->windEnabled());
        wind->setChecked(false);
        QCOMPARE(QSettings().value(QStringLiteral("view/wind")).toBool(), false);
        QVERIFY(!mWindow->viewport()->windEnabled());
    }

    /// The Properties panel's wind rows (nothing selected: the project): each change one
    /// "Change wind" step that the viewport plays at once; undo gives back the exact bytes.
    void propertiesSetTheWindInOneUndoStep() {
        document().setSelection({});
        const QByteArray before = document().serialized();
        const int steps = document().undoStack()->count();
        QVERIFY(!document().project().wind);
        auto* strength =
            mWindow->properties()->findChild<QDoubleSpinBox*>(QStringLiteral("windStrength"));
        auto* direction =
            mWindow->properties()->findChild<QDoubleSpinBox*>(QStringLiteral("windDirection"));
        auto* gustiness =
            mWindow->properties()->findChild<QDoubleSpinBox*>(QStringLiteral("windGustiness"));
        QVERIFY(strength && direction && gustiness);
        QCOMPARE(strength->value(), 0.5); // the engine's default until the project sets it
        strength->setFocus();
        strength->selectAll();
        QTest::keyClicks(strength, QStringLiteral("1.5"));
        QTest::keyClick(strength, Qt::Key_Return);
        QVERIFY(document().project().wind);
        QCOMPARE(document().project().wind->strength, 1.5f);
        QCOMPARE(document().undoStack()->count(), steps + 1);
        QCOMPARE(document().undoStack()->undoText(), QStringLiteral("Change wind"));
        QCOMPARE(mWindow->viewport()->wind().strength, 1.5f);
        QVERIFY(!mWindow->isGenerating()); // the wind regrows nothing
        document().undoStack()->undo();
        QCOMPARE(document().serialized(), before);
        QCOMPARE(strength->value(), 0.5);
        QCOMPARE(mWindow->viewport()->wind().strength, 0.5f);

        // Direction as an angle about the vertical: 90° blows along +Z.
        direction->setValue(90.0);
        QVERIFY(document().project().wind);
        const glm::vec3 d = document().project().wind->direction;
        QCOMPARE(d.x, 0.0f);
        QCOMPARE(d.z, 1.0f);
        QCOMPARE(document().undoStack()->count(), steps + 1);
        document().undoStack()->undo();
        QCOMPARE(document().serialized(), before);

        // A storm for the grabs below (kept: the test's own project).
        strength->setValue(1.6);
        gustiness->setValue(0.6);
        QCOMPARE(document().project().wind->gustiness, 0.6f);
    }

    /// Wind on: two times of the wind clock draw different pictures, and the trees are drawn
    /// swaying; off: the same two times draw the same picture.
    void windMovesTheTreesOnlyWhenOn() {
        Viewport* view = mWindow->viewport();
        // The coarser levels and impostors made first: a frame that draws a new one differs.
        QTRY_VERIFY_WITH_TIMEOUT((view->grabSharp(), view->lodPending() == 0), kTimeoutMs);
        mWindow->setViewWind(true);
        const QImage a = grabAt(0.4);
        QVERIFY(view->drawnWindTriangles() > 0);
        const QImage b = grabAt(1.3);
        const QImage a2 = grabAt(0.4);
        a.save(test::outputPath(QStringLiteral("wind-on-a.png")));
        b.save(test::outputPath(QStringLiteral("wind-on-b.png")));
        const int moved = differingPixels(a, b);
        QVERIFY2(moved > 500, qPrintable(QString::number(moved)));
        // The frozen clock gives the same frame again.
        QCOMPARE(differingPixels(a, a2), 0);

        mWindow->setViewWind(false);
        const QImage c = grabAt(0.4);
        QCOMPARE(view->drawnWindTriangles(), std::size_t(0));
        const QImage d = grabAt(1.3);
        QCOMPARE(differingPixels(c, d), 0);
        mWindow->setWindTime(std::nullopt);
    }
};

QTEST_MAIN(TestViewWind)
#include "test_viewwind.moc"
