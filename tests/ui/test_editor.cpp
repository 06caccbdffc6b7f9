// The editor as a user drives it: a project opened into the document, a tree picked in the
// outliner and edited in the Properties panel with keys, undo and redo with the shortcuts,
// Delete and Duplicate, Save through the menu action, a corrupt file, questions before unsaved
// edits are lost (also when the file changes on disk), the Python console, Cancel, per-tree GPU
// uploads, and a screenshot of the whole window with every dock.
#include <memory>

#include <QAction>
#include <QApplication>
#include <QDialog>
#include <QDir>
#include <QDockWidget>
#include <QDoubleSpinBox>
#include <QFile>
#include <QFileDialog>
#include <QFileInfo>
#include <QLineEdit>
#include <QScrollArea>
#include <QScrollBar>
#include <QSignalSpy>
#include <QSpinBox>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QTest>
#include <QTimer>
#include <QToolButton>
#include <QTreeView>
#include <functional>

#include "demowindow.h"
#include "document/autosave.h"
#include "document/document.h"
#include "document/presetlibrary.h"
#include "ui/document/messagespanel.h"
#include "ui/document/outlinermodel.h"
#include "ui/document/propertiespanel.h"
#include "ui/document/statspanel.h"
#include "ui/generation/documentgenerator.h"
#include "ui/mainwindow.h"
#include "ui/scripting/pythonconsole.h"
#include "ui/speciesworkbench.h"
#include "ui/viewport/viewport.h"
#include "uitest.h"

using namespace sylva;
using namespace sylva::ui;

namespace {

constexpr int kTimeoutMs = 120000;

using sylva::ui::test::outputPath;

/// Answers the next modal dialog: a file dialog gets \p file and is accepted; another dialog
/// is handed to \p other.
void answerNextDialog(const QString& file, std::function<void(QDialog*)> other = {}) {
    QTimer::singleShot(200, [file, other] {
        QWidget* modal = QApplication::activeModalWidget();
        if (auto* dialog = qobject_cast<QFileDialog*>(modal)) {
            dialog->setDirectory(QFileInfo(file).absolutePath());
            dialog->selectFile(QFileInfo(file).fileName());
            // As a user types the name (selectFile keeps a save dialog's suggested name).
            if (auto* name = dialog->findChild<QLineEdit*>(QStringLiteral("fileNameEdit")))
                name->setText(QFileInfo(file).fileName());
            static_cast<QDialog*>(dialog)->done(QDialog::Accepted); // caller reads selectedFiles()
        } else if (auto* d = qobject_cast<QDialog*>(modal); d && other) {
            other(d);
        } else {
            answerNextDialog(file, other); // not shown yet
        }
    });
}

QByteArray readFile(const QString& path) {
    QFile f(path);
    return f.open(QIODevice::ReadOnly) ? f.readAll() : QByteArray();
}

} // namespace

class TestEditor : public QObject {
    Q_OBJECT

private:
    std::unique_ptr<MainWindow> mWindow;
    QTemporaryDir mDir;
    QString mProject;
    int mQuestions = 0;
    QString mLastQuestion;
    MainWindow::Answer mAnswer = MainWindow::Answer::Cancel;

    doc::Document& document() { return mWindow->document(); }

    void settle() {
        QVERIFY(mWindow->waitForGeneration(kTimeoutMs));
        QTest::qWait(50); // a frame
    }

    QModelIndex treeIndex(int row) {
        OutlinerModel* model = mWindow->outlinerModel();
        return model->index(row, 0, model->groupIndex(OutlinerModel::TreesGroup));
    }

    void clickTreeInOutliner(int row) {
        QTreeView* view = mWindow->outliner();
        const QModelIndex index = treeIndex(row);
        QVERIFY(index.isValid());
        view->scrollTo(index);
        const QRect rect = view->visualRect(index);
        QVERIFY(!rect.isEmpty());
        // Click the label, right of the check box.
        QTest::mouseClick(view->viewport(), Qt::LeftButton, {},
                          QPoint(rect.right() - 10, rect.center().y()));
    }

private Q_SLOTS:
    void initTestCase() {
        QStandardPaths::setTestModeEnabled(true); // settings and autosave in a test folder
        QVERIFY(mDir.isValid());
        // The demo project saved into a scratch folder (paths rebased), so saving is safe.
        mProject = test::copyDemoProject(mDir);

        mWindow = std::make_unique<MainWindow>();
        mWindow->setAskHandler([this](const QString& question, bool) {
            ++mQuestions;
            mLastQuestion = question;
            return mAnswer;
        });
        mWindow->resize(1400, 900);
        mWindow->show();
        QVERIFY(QTest::qWaitForWindowExposed(mWindow.get()));
        // Window shortcuts (Ctrl+Z, Delete) act in the active window, as for a user.
        // (Xvfb has no window manager to activate it: the application is told instead.)
        mWindow->activateWindow();
        QApplication::setActiveWindow(mWindow.get());
        QCOMPARE(QApplication::activeWindow(), mWindow.get());
        QVERIFY(mWindow->openProject(mProject));
        settle();
        QVERIFY2(mWindow->lastError().isEmpty(), qPrintable(mWindow->lastError()));
        QCOMPARE(mWindow->viewport()->trees().size(), std::size_t(42));
    }

    void cleanupTestCase() {
        mAnswer = MainWindow::Answer::Discard;
        mWindow.reset();
    }

    void titleShowsFileAndModifiedMarker() {
        QVERIFY(mWindow->windowTitle().contains(QStringLiteral("demo.sylva")));
        QVERIFY(!mWindow->isWindowModified());
        // The scene's wood and biomass are the engine's sums over the trees.
        const GenerationResult& r = mWindow->generator().result();
        double wood = 0.0;
        for (const DrawnTree& t : r.trees)
            wood += t.metrics.woodVolumeM3;
        QVERIFY(std::abs(r.stats.at("wood_m3") - wood) < 1e-9 * std::max(1.0, wood));
        QVERIFY2(
            mWindow->statsPanel()->value(QStringLiteral("statWood")).contains(QStringLiteral("m³")),
            qPrintable(mWindow->statsPanel()->value(QStringLiteral("statWood"))));
    }

    /// Click a tree in the outliner, type a new x in the Properties panel: one "Move tree"
    /// step; Ctrl+Z and Ctrl+Shift+Z undo and redo it; File > Save writes what is shown.
    void editInPropertiesUndoRedoAndSave() {
        const QByteArray original = document().serialized();
        clickTreeInOutliner(0);
        QCOMPARE(document().selectedTrees(), QList<doc::TreeId>{1});
        QCOMPARE(mWindow->viewport()->highlightedTrees(), QSet<std::uint32_t>{1});
        auto* x = mWindow->properties()->findChild<QDoubleSpinBox*>(QStringLiteral("spin0"));
        QVERIFY(x);
        x->setFocus();
        x->selectAll();
        QTest::keyClicks(x, QStringLiteral("5"));
        QTest::keyClick(x, Qt::Key_Return);
        QCOMPARE(document().tree(1).position.x, 5.0f);
        QCOMPARE(document().undoStack()->undoText(), QStringLiteral("Move tree"));
        QVERIFY(mWindow->isWindowModified());
        settle();

        mWindow->viewport()->setFocus();
        QTest::keyClick(mWindow.get(), Qt::Key_Z, Qt::ControlModifier);
        QCOMPARE(document().serialized(), original);
        QVERIFY(!mWindow->isWindowModified());
        QCOMPARE(x->value(), 2.0); // the panel follows the document
        QTest::keyClick(mWindow.get(), Qt::Key_Z, Qt::ControlModifier | Qt::ShiftModifier);
        QCOMPARE(document().tree(1).position.x, 5.0f);
        settle();

        QAction* save = mWindow->findChild<QAction*>(QStringLiteral("actionSave"));
        QVERIFY(save);
        save->trigger();
        QVERIFY(!mWindow->isWindowModified());
        QCOMPARE(readFile(mProject), document().serialized());
    }

    /// Issue 30: moving the demo's hand-placed alder 30 m (typed into the Properties panel)
    /// regrows only it and the trees whose crowns it left or now touches (12 of 43 before:
    /// domain trees were scattered after it on one random stream); undo does the same back.
    void movingATreeRegrowsOnlyItsNeighbours() {
        settle();
        const QByteArray original = document().serialized();
        const std::size_t trees = mWindow->viewport()->trees().size();
        clickTreeInOutliner(0);
        QCOMPARE(document().selectedTrees(), QList<doc::TreeId>{1});
        auto* x = mWindow->properties()->findChild<QDoubleSpinBox*>(QStringLiteral("spin0"));
        QVERIFY(x);
        const float from = document().tree(1).position.x;
        x->setFocus();
        x->selectAll();
        QTest::keyClicks(x, QString::number(double(from) + 30.0));
        QTest::keyClick(x, Qt::Key_Return);
        QCOMPARE(document().tree(1).position.x, from + 30.0f);
        settle();
        const double regrown = mWindow->generator().result().stats.at("regrown");
        qInfo("moving the alder 30 m regrew %g of %zu trees", regrown,
              mWindow->viewport()->trees().size());
        QVERIFY2(regrown >= 1.0 && regrown <= 4.0, qPrintable(QString::number(regrown)));
        QVERIFY(mWindow->viewport()->trees().size() + 2 >= trees); // one may be displaced
        document().undoStack()->undo();
        settle();
        QCOMPARE(document().serialized(), original);
        const double back = mWindow->generator().result().stats.at("regrown");
        QVERIFY2(back >= 1.0 && back <= 4.0, qPrintable(QString::number(back)));
        QCOMPARE(mWindow->viewport()->trees().size(), trees);
    }

    /// Delete and Ctrl+D on the selection, by keys, each one undo step.
    void deleteAndDuplicateByKeys() {
        clickTreeInOutliner(0);
        const doc::TreeId id = document().treeIds()[0];
        QCOMPARE(document().selectedTrees(), QList<doc::TreeId>{id});
        QTest::keyClick(mWindow->outliner(), Qt::Key_Delete);
        QCOMPARE(document().treeIds().size(), std::size_t(0));
        QCOMPARE(document().undoStack()->undoText(), QStringLiteral("Remove tree"));
        QTest::keyClick(mWindow.get(), Qt::Key_Z, Qt::ControlModifier);
        QCOMPARE(document().treeIds().size(), std::size_t(1));
        document().selectTrees({id});
        QTest::keyClick(mWindow.get(), Qt::Key_D, Qt::ControlModifier);
        QCOMPARE(document().treeIds().size(), std::size_t(2));
        QCOMPARE(document().undoStack()->undoText(), QStringLiteral("Duplicate tree"));
        QCOMPARE(document().selectedTrees(), QList<doc::TreeId>{document().treeIds()[1]});
        QTest::keyClick(mWindow.get(), Qt::Key_Z, Qt::ControlModifier);
        QCOMPARE(document().treeIds().size(), std::size_t(1));
        QVERIFY(!mWindow->isWindowModified());
        settle();
    }

    /// A regrowth after a one-tree edit uploads that tree's mesh only.
    void unchangedTreesAreNotUploadedAgain() {
        settle();
        const std::size_t before = mWindow->viewport()->uploads();
        doc::ProjectInstance t = document().tree(1);
        t.rotation += 30;
        document().setTree(1, t);
        settle();
        QCOMPARE(mWindow->generator().result().stats.at("regrown"), 1.0);
        // The upload happens at the next paint, which a loaded machine may delay.
        QTRY_COMPARE_WITH_TIMEOUT(mWindow->viewport()->uploads(), before + 1, 10000);
        QTest::qWait(200);
        QCOMPARE(mWindow->viewport()->uploads(), before + 1); // and no more
        QVERIFY(mWindow->lastEditToScreenMs() > 0.0);
        document().undoStack()->undo();
        settle();
    }

    /// Save As into another folder keeps every tree (the species and meshes are the same files,
    /// named by other relative paths): nothing regrows.
    void saveAsElsewhereKeepsTheTrees() {
        settle();
        QVERIFY(QDir().mkpath(mDir.filePath(QStringLiteral("elsewhere"))));
        for (const QString& path :
             {mDir.filePath(QStringLiteral("elsewhere/moved.sylva")), mProject}) {
            QSignalSpy generated(mWindow.get(), &MainWindow::generationFinished);
            QVERIFY(mWindow->saveAs(path));
            QTRY_VERIFY_WITH_TIMEOUT(generated.count() >= 1, 20000);
            settle();
            QCOMPARE(mWindow->generator().result().stats.at("regrown"), 0.0);
            QCOMPARE(mWindow->viewport()->trees().size(), std::size_t(42));
        }
    }

    /// A corrupt file says where it is broken and keeps the open document.
    void corruptFileKeepsTheDocument() {
        const QByteArray before = document().serialized();
        const QString broken = mDir.filePath(QStringLiteral("broken.sylva"));
        QFile f(broken);
        QVERIFY(f.open(QIODevice::WriteOnly));
        f.write(
            "{\n  \"format\": \"sylva-project\",\n  \"format_version\": 1,\n  \"seed\": 02\n}\n");
        f.close();
        QVERIFY(!mWindow->openProject(broken));
        QCOMPARE(document().serialized(), before);
        QCOMPARE(document().path(), mProject);
        MessagesPanel* messages = mWindow->messages();
        const QString last = messages->message(messages->count() - 1);
        QVERIFY2(last.contains(QStringLiteral("broken.sylva:4:")), qPrintable(last));
    }

    /// Unsaved edits are never lost without a question: opening another file, closing, and a
    /// change of the file on disk.
    void unsavedEditsAsk() {
        document().setSeed(document().project().seed + 1);
        QVERIFY(document().isModified());
        const QByteArray edited = document().serialized();
        mQuestions = 0;
        mAnswer = MainWindow::Answer::Cancel;
        QVERIFY(!mWindow->openProject(mProject));
        QCOMPARE(mQuestions, 1);
        QCOMPARE(document().serialized(), edited);
        QVERIFY(!mWindow->close()); // Cancel: the window stays
        QCOMPARE(mQuestions, 2);
        QVERIFY(mWindow->isVisible());

        // The project file changes on disk while edits are pending: asked, No keeps them.
        mAnswer = MainWindow::Answer::No;
        QByteArray onDisk = readFile(mProject);
        onDisk.replace("\"seed\": 7", "\"seed\": 9");
        QFile f(mProject);
        QVERIFY(f.open(QIODevice::WriteOnly | QIODevice::Truncate));
        f.write(onDisk);
        f.close();
        QTRY_COMPARE_WITH_TIMEOUT(mQuestions, 3, 15000);
        QVERIFY2(mLastQuestion.contains(QStringLiteral("changed on disk")),
                 qPrintable(mLastQuestion));
        QCOMPARE(document().serialized(), edited);

        // Discard: the other file opens.
        mAnswer = MainWindow::Answer::Discard;
        QVERIFY(mWindow->openProject(mProject));
        QCOMPARE(document().project().seed, std::uint64_t(9));
        QVERIFY(!document().isModified());
        settle();
    }

    /// A save replaces the project file by a rename; when the old file is deleted only after
    /// the reload timer looked (something still had it open), its watch went with it, and an
    /// edit made in place afterwards went unseen until the next regrowth renewed the watches.
    void editOnDiskAfterASaveIsSeen() {
        QVERIFY(mWindow->openProject(mProject));
        settle();
        QFile held(mProject);
        QVERIFY(held.open(QIODevice::ReadOnly)); // keeps the old file alive past the rename
        QVERIFY(mWindow->save());
        QTest::qWait(600); // the reload timer (250 ms) fires while the old file lives
        held.close();      // now it is deleted, and its watch removed
        QTest::qWait(300);
        QVERIFY(!document().isModified()); // no edits pending: the change reloads at once
        QByteArray onDisk = readFile(mProject);
        const QByteArray seed = "\"seed\": " + QByteArray::number(document().project().seed);
        QVERIFY2(onDisk.contains(seed), onDisk.constData());
        onDisk.replace(seed, "\"seed\": 4242");
        QFile f(mProject);
        QVERIFY(f.open(QIODevice::ReadWrite)); // in place: the folder does not change
        f.write(onDisk);
        f.resize(onDisk.size());
        f.close();
        QTRY_COMPARE_WITH_TIMEOUT(document().project().seed, std::uint64_t(4242), 15000);
        settle();
    }

    /// The Python console evaluates, edits the document through its commands, runs
    /// multi-line statements and shows tracebacks.
    void consoleEvaluatesAndShowsTracebacks() {
        PythonConsole* console = mWindow->console();
        mWindow->findChild<QDockWidget*>(QStringLiteral("consoleDock"))->raise();
        QLineEdit* input = console->input();
        input->setFocus();
        QTest::keyClicks(input, QStringLiteral("tid = doc.add_tree('alder', (1, 0, 1), seed=9)"));
        QTest::keyClick(input, Qt::Key_Return);
        QCOMPARE(document().treeIds().size(), std::size_t(2));
        QCOMPARE(document().undoStack()->undoText(), QStringLiteral("Add tree"));
        console->submit(QStringLiteral("for i in range(3):"));
        console->submit(QStringLiteral("    print('line', i * i)"));
        console->submit(QString());
        QVERIFY2(console->transcript().contains(QStringLiteral("line 4")),
                 qPrintable(console->transcript()));
        console->submit(QStringLiteral("1 / 0"));
        QVERIFY(console->transcript().contains(QStringLiteral("Traceback")));
        QVERIFY(console->transcript().contains(QStringLiteral("ZeroDivisionError")));
        // K of a species, one step, its range checked (the Properties panel's Variants).
        console->submit(QStringLiteral("doc.set_variants('alder', 300)"));
        QVERIFY2(console->transcript().contains(QStringLiteral("must be 0 to 256")),
                 qPrintable(console->transcript()));
        console->submit(QStringLiteral("doc.set_variants('alder', 2)"));
        QCOMPARE(
            document().project().species[std::size_t(document().speciesIndex("alder"))].variants,
            2);
        QCOMPARE(document().undoStack()->undoText(), QStringLiteral("Change variants"));
        document().undoStack()->undo();
        console->submit(QStringLiteral("doc.set_tree(tid, scale=0)"));
        QVERIFY2(console->transcript().contains(QStringLiteral("ValueError: tree scale")),
                 qPrintable(console->transcript()));
        // History: Up brings back the last line.
        QTest::keyClick(input, Qt::Key_Up);
        QCOMPARE(input->text(), QStringLiteral("doc.set_tree(tid, scale=0)"));
        input->clear();
        document().undoStack()->undo();
        settle();
    }

    /// Cancel in the status bar stops a regrowth; the document and the shown result stay.
    void cancelKeepsTheDocument() {
        settle();
        const QByteArray before = document().serialized();
        const std::size_t trees = mWindow->generator().result().trees.size();
        QSignalSpy cancelled(&mWindow->generator(), &DocumentGenerator::cancelled);
        mWindow->generator().regenerateAll();
        QVERIFY(mWindow->isGenerating());
        auto* cancel = mWindow->findChild<QToolButton*>(QStringLiteral("cancelButton"));
        QVERIFY(cancel && cancel->isVisible());
        QTest::mouseClick(cancel, Qt::LeftButton);
        QVERIFY(cancelled.wait(kTimeoutMs) || cancelled.count() == 1);
        QCOMPARE(document().serialized(), before);
        QCOMPARE(mWindow->generator().result().trees.size(), trees);
        QVERIFY(!cancel->isVisible());
        mWindow->reload();
        settle();
    }

    /// File > Open and File > Save As through their dialogs, and Edit > Preferences.
    void menuActionsOpenSaveAsAndPreferences() {
        mAnswer = MainWindow::Answer::Discard;
        QAction* open = mWindow->findChild<QAction*>(QStringLiteral("actionOpen"));
        QVERIFY(open);
        answerNextDialog(mProject);
        open->trigger();
        settle();
        QCOMPARE(document().path(), mProject);
        document().setSeed(123);
        const QString copy = mDir.filePath(QStringLiteral("sub/copy.sylva"));
        QVERIFY(QDir().mkpath(mDir.filePath(QStringLiteral("sub"))));
        answerNextDialog(copy);
        mWindow->findChild<QAction*>(QStringLiteral("actionSaveAs"))->trigger();
        QCOMPARE(document().path(), copy);
        QVERIFY(!document().isModified());
        QVERIFY(mWindow->windowTitle().contains(QStringLiteral("copy.sylva")));
        QCOMPARE(readFile(copy), document().serialized());
        // The copy in another folder still finds the species and meshes.
        doc::Document reopened;
        reopened.open(copy);
        QVERIFY(QFileInfo::exists(
            reopened.project().resolve(reopened.project().obstacles.front().file)));

        answerNextDialog({}, [](QDialog* d) {
            auto* minutes = d->findChild<QSpinBox*>(QStringLiteral("autosaveMinutes"));
            QVERIFY(minutes);
            minutes->setValue(5);
            d->accept();
        });
        mWindow->findChild<QAction*>(QStringLiteral("actionPreferences"))->trigger();
        QCOMPARE(mWindow->autosave().interval(), 5 * 60 * 1000);
        mWindow->setAutosaveInterval(120);
        settle();
    }

    /// The whole window with every dock, for a person to look at.
    void windowScreenshotWithEveryDock() {
        mWindow->editSpecies(QStringLiteral("alder")); // the species editor's docks too
        for (QDockWidget* dock : mWindow->findChildren<QDockWidget*>())
            // Open (a tab behind another counts: the species editor shares the bottom).
            QVERIFY2(dock->toggleViewAction()->isChecked() ||
                         dock->objectName() == QStringLiteral("consoleDock"),
                     qPrintable(dock->objectName()));
        document().selectTrees({document().treeIds()[0]});
        mWindow->console()->submit(QStringLiteral("print(len(doc.trees()), 'tree(s) placed')"));
        settle();
        const QString path = outputPath(QStringLiteral("ui_editor_window.png"));
        // A short dock scrolls its properties instead of squeezing the rows (the selected
        // tree's rows were once squeezed into the height of the project's page).
        auto* properties = qobject_cast<QScrollArea*>(
            mWindow->findChild<QDockWidget*>(QStringLiteral("propertiesDock"))->widget());
        QVERIFY(properties);
        QVERIFY(properties->widget()->height() >= properties->widget()->minimumSizeHint().height());
        QVERIFY(mWindow->saveWindowScreenshot(path));
        const QImage image(path);
        QCOMPARE(image.size(), mWindow->size() * mWindow->devicePixelRatio());
        // The 3D views draw into native windows, which a widget grab leaves blank: the
        // screenshot holds what each view draws.
        for (Viewport* view : {mWindow->viewport(), mWindow->workbench()->previewViewport()}) {
            const QImage drawn = view->grabSharp().convertToFormat(QImage::Format_RGB32);
            QVERIFY(!drawn.isNull());
            const QRect where(view->mapTo(mWindow.get(), QPoint(0, 0)) * image.devicePixelRatio(),
                              drawn.size());
            const QImage shot = image.copy(where).convertToFormat(QImage::Format_RGB32);
            int differ = 0;
            for (int y = 0; y < drawn.height(); y += 4)
                for (int x = 0; x < drawn.width(); x += 4)
                    differ += qAbs(qGray(shot.pixel(x, y)) - qGray(drawn.pixel(x, y))) > 24;
            QVERIFY2(differ * 16 < drawn.width() * drawn.height() / 50,
                     qPrintable(view->objectName()));
        }
    }
};

QTEST_MAIN(TestEditor)

#include "test_editor.moc"
