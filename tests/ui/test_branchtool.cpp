// Issue #43: the Branch tool with simulated mouse and keys in the real window. A click selects
// the branch drawn under the cursor (the document's selected branch, its id in Properties, the
// highlight over the scene); a drag bends it about its base as one undo step; Delete prunes it;
// Properties' radius and lock are one step each, the lock keeping the branch's geometry; the
// Outliner lists the tree's edits with orphans marked, and Messages says so; undo gives back
// the opened bytes. The edit-to-screen time of a bend is printed (not asserted: ctest -L perf).
#include <memory>

#include <QAbstractItemModel>
#include <QApplication>
#include <QCheckBox>
#include <QDir>
#include <QDoubleSpinBox>
#include <QFile>
#include <QGroupBox>
#include <QProcess>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QTest>

#include "demowindow.h"
#include "document/document.h"
#include "engine/export/lodchainexport.h"
#include "limbonscreen.h"
#include "ui/document/messagespanel.h"
#include "ui/document/outlinermodel.h"
#include "ui/generation/documentgenerator.h"
#include "ui/generation/exportlodchain.h"
#include "ui/generation/exportshown.h"
#include "ui/generation/treebranches.h"
#include "ui/mainwindow.h"
#include "ui/viewport/toolcontroller.h"
#include "ui/viewport/tools/branchtool.h"
#include "ui/viewport/viewport.h"
#include "uitest.h"

using namespace sylva;
using namespace sylva::ui;

namespace {
constexpr int kTimeoutMs = 120000;

QByteArray readAll(const QString& path) {
    QFile file(path);
    return file.open(QIODevice::ReadOnly) ? file.readAll() : QByteArray();
}
} // namespace

class TestBranchTool : public QObject {
    Q_OBJECT

private:
    std::unique_ptr<MainWindow> mWindow;
    QTemporaryDir mDir;
    doc::TreeId mTree = 0;
    QString mOriginal;

    doc::Document& document() { return mWindow->document(); }
    Viewport* viewport() { return mWindow->viewport(); }
    BranchTool& tool() { return mWindow->tools().branchTool(); }

    void settle() {
        QVERIFY(mWindow->waitForGeneration(kTimeoutMs));
        QTest::qWait(50);
    }

    const DrawnTree* drawn() { return shownTree(mWindow->generator().result(), mTree); }

    /// A pixel where a limb (order 1) of the tree is drawn and picked, and that limb's id.
    std::pair<QPoint, std::string> limbOnScreen() {
        const DrawnTree* t = drawn();
        if (!t) return {};
        return test::limbOnScreen(*viewport(), tool(), *t, mTree, document().branchEdits(mTree));
    }

    /// The radius of a branch's first node as grown.
    float grownRadius(const std::string& branch) {
        for (const skel::Branch& b : skel::branchesOf(*drawn()->grown))
            if (b.id == branch) return b.baseRadius;
        return -1.0f;
    }

private Q_SLOTS:
    void initTestCase() {
        QStandardPaths::setTestModeEnabled(true);
        QVERIFY(mDir.isValid());
        mWindow = test::openDemoWindow(mDir, {1400, 900});
        QVERIFY(mWindow);
        settle();
        QVERIFY(!document().treeIds().empty());
        mTree = document().treeIds().front();
        mOriginal = document().serialized();
        mWindow->tools().setTool(ToolController::Tool::Branch);
    }
    void cleanupTestCase() { mWindow.reset(); }

    void clickSelectsTheBranchUnderTheCursor() {
        const auto [at, branch] = limbOnScreen();
        QVERIFY2(!branch.empty(), "no limb of the demo tree is drawn where it projects");
        QTest::mouseClick(viewport(), Qt::LeftButton, {}, at);
        QVERIFY(document().selectedBranch());
        QCOMPARE(document().selectedBranch()->branch, branch);
        QCOMPARE(document().selectedTrees(), QList<doc::TreeId>{mTree});
        QCOMPARE(document().serialized(), mOriginal); // selecting is no edit
        // Highlighted: overlay lines along the branch; its id in Properties.
        QVERIFY(!mWindow->tools().handleLines().empty());
        auto* box = mWindow->findChild<QGroupBox*>(QStringLiteral("branchProperties"));
        QVERIFY(box);
        QVERIFY(box->title().contains(QString::fromStdString(branch)));
        // The branch's rows make Properties scroll: its editors still fit beside the
        // scroll bar (the position's third field was cut off).
        QApplication::processEvents();
        auto* panel = mWindow->findChild<QWidget*>(QStringLiteral("propertiesPanel"));
        QVERIFY(panel && panel->parentWidget());
        const QWidget* view = panel->parentWidget(); // the scroll area's viewport
        for (const QDoubleSpinBox* spin : panel->findChildren<QDoubleSpinBox*>()) {
            if (!spin->isVisibleTo(panel)) continue;
            const int right = spin->mapTo(view, QPoint(spin->width(), 0)).x();
            QVERIFY2(right <= view->width(), qPrintable(QStringLiteral("%1 ends at %2 of %3")
                                                            .arg(spin->objectName())
                                                            .arg(right)
                                                            .arg(view->width())));
        }
        QVERIFY(viewport()->grabFramebuffer().save(test::outputPath("branch_selected.png")));
        // A click on the sky lets it go.
        QTest::mouseClick(viewport(), Qt::LeftButton, {}, QPoint(5, 5));
        QVERIFY(!document().selectedBranch());
    }

    void dragBendsAsOneUndoStep() {
        const auto [at, branch] = limbOnScreen();
        QVERIFY(!branch.empty());
        const int steps = document().undoStack()->index();
        test::dragThrough(viewport(), {at, at + QPoint(40, -30), at + QPoint(90, -70)});
        QCOMPARE(document().undoStack()->index(), steps + 1);
        const auto& edits = document().branchEdits(mTree);
        QCOMPARE(edits.size(), std::size_t(1));
        QCOMPARE(edits.front().branch, branch);
        QVERIFY(edits.front().bend);
        settle();
        std::printf("bend of branch %s: %.1f ms edit to screen (%zu nodes in the tree)\n",
                    branch.c_str(), mWindow->lastEditToScreenMs(), drawn()->grown->size());
        QVERIFY(mWindow->lastEditToScreenMs() > 0.0);
        // Undo is byte-identical.
        document().undoStack()->undo();
        QCOMPARE(document().serialized(), mOriginal);
        settle();
    }

    void deletePrunesAndPropertiesEdit() {
        const auto [at, branch] = limbOnScreen();
        QVERIFY(!branch.empty());
        QTest::mouseClick(viewport(), Qt::LeftButton, {}, at);
        QVERIFY(document().selectedBranch());
        // Properties: radius x1.5 is one step, lock another that keeps the geometry.
        auto* radius = mWindow->findChild<QDoubleSpinBox*>(QStringLiteral("branchRadius"));
        QVERIFY(radius);
        const int steps = document().undoStack()->index();
        radius->setValue(1.5);
        QCOMPARE(document().undoStack()->index(), steps + 1);
        settle();
        auto* lock = mWindow->findChild<QCheckBox*>(QStringLiteral("branchLock"));
        QVERIFY(lock);
        lock->setChecked(true);
        QCOMPARE(document().undoStack()->index(), steps + 2);
        const skel::BranchEdit locked = branchEditOf(document(), mTree, branch);
        QVERIFY(locked.lock);
        QVERIFY(!locked.locked.empty()); // the geometry, not only a flag
        QCOMPARE(locked.locked.front().radius, 1.5f * grownRadius(branch)); // as shown
        // A locked branch is not pruned: the document says why, nothing changes.
        QTest::keyClick(viewport(), Qt::Key_Delete);
        QCOMPARE(document().undoStack()->index(), steps + 2);
        lock = mWindow->findChild<QCheckBox*>(QStringLiteral("branchLock"));
        lock->setChecked(false);
        QCOMPARE(document().undoStack()->index(), steps + 3);
        QVERIFY(document().selectedBranch());
        QTest::keyClick(viewport(), Qt::Key_Delete);
        QCOMPARE(document().undoStack()->index(), steps + 4);
        QVERIFY(branchEditOf(document(), mTree, branch).prune);
        QCOMPARE(document().treeIds().front(), mTree); // the tree stays
        settle();
        for (const skel::Branch& b : editedBranchesOf(*drawn(), document().branchEdits(mTree)))
            QVERIFY(b.id != branch);
        for (int k = 0; k < 4; ++k)
            document().undoStack()->undo();
        QCOMPARE(document().serialized(), mOriginal);
        settle();
    }

    void editedTreeExportsAsTheCliAndItsLodChainIsEdited() {
        // The editor's File > Export of the edited project writes sylva-cli's bytes (saved, so
        // the CLI reads the same project), and the LOD chain and impostor of the selected tree
        // are made from the edited tree.
        const std::size_t grownNodes = drawn()->grown->size();
        const auto [at, branch] = limbOnScreen();
        QVERIFY(!branch.empty());
        QTest::mouseClick(viewport(), Qt::LeftButton, {}, at);
        QTest::keyClick(viewport(), Qt::Key_Delete);
        QVERIFY(branchEditOf(document(), mTree, branch).prune);
        settle();
        QTemporaryDir dir;
        QVERIFY(dir.isValid());
        // Beside the opened copy, which stays: the species files are found from it.
        const QString saved = mDir.filePath(QStringLiteral("edited.sylva"));
        QVERIFY(mWindow->saveAs(saved));
        QVERIFY(QDir(dir.path()).mkpath(QStringLiteral("editor")));
        QVERIFY(QDir(dir.path()).mkpath(QStringLiteral("cli")));
        const QString ours = dir.filePath(QStringLiteral("editor/export.obj"));
        const QString theirs = dir.filePath(QStringLiteral("cli/export.obj"));
        QVERIFY2(mWindow->exportTo(ours), qPrintable(mWindow->lastError()));
        QProcess cli;
        cli.start(QStringLiteral(SYLVA_CLI_PATH),
                  {QStringLiteral("forest"), saved, QStringLiteral("-o"), theirs});
        QVERIFY(cli.waitForFinished(kTimeoutMs));
        QCOMPARE(cli.exitCode(), 0);
        const QByteArray a = readAll(ours), b = readAll(theirs);
        QVERIFY(a.size() > 1000);
        QVERIFY2(a == b, "the editor's export of the edited project differs from sylva-cli's");

        document().selectTrees({mTree});
        const ShownScene shown{mWindow->generator().result(), &document()};
        const std::optional<LodChainSource> source = lodChainSource(shown);
        QVERIFY(source && source->skeleton);
        QVERIFY(source->skeleton->size() < grownNodes); // the pruned tree, not the grown one
        const exporter::GameLodFiles files =
            exportLodChain(dir.filePath(QStringLiteral("lods")).toStdString(), *source);
        QVERIFY(files.impostor);
        QVERIFY(!files.levels.empty());
        QVERIFY(QFile::exists(QString::fromStdString(files.impostorColor.string())));
        std::printf("edited tree: %zu of %zu nodes; LOD chain of %zu levels, LOD0 %zu "
                    "triangles, impostor baked\n",
                    source->skeleton->size(), grownNodes, files.levels.size(),
                    files.levels.front().triangles);
        document().undoStack()->undo();
        settle();
    }

    void outlinerListsEditsAndOrphans() {
        const QString before = document().serialized(); // saved elsewhere by the export test
        skel::BranchEdit gone;
        gone.branch = "0.999";
        gone.prune = true;
        document().setBranchEdits(mTree, {gone});
        settle();
        auto* model = mWindow->findChild<OutlinerModel*>();
        QVERIFY(model);
        const QModelIndex tree = model->indexOf({doc::ItemRef::Kind::Tree, mTree});
        QCOMPARE(model->rowCount(tree), 1);
        std::size_t orphans = 0;
        for (const DrawnTree& t : mWindow->generator().result().trees)
            if (t.docId == mTree) orphans = t.orphanedEdits.size();
        QCOMPARE(orphans, std::size_t(1));
        const QString text = model->index(0, 0, tree).data().toString();
        QVERIFY2(text.contains(QStringLiteral("0.999")) &&
                     text.contains(QStringLiteral("orphaned")),
                 qPrintable(text));
        auto* messages = mWindow->findChild<MessagesPanel*>();
        QVERIFY(messages);
        bool said = false;
        for (int i = 0; i < messages->count(); ++i)
            said = said || messages->message(i).contains(QStringLiteral("branch 0.999"));
        QVERIFY(said);
        document().undoStack()->undo();
        QCOMPARE(document().serialized(), before);
    }
};

QTEST_MAIN(TestBranchTool)
#include "test_branchtool.moc"
