// Issue #43: the Branch tool in the Species Editor's preview, with simulated mouse and keys in
// the real window. With the Branch tool on and a hand-placed tree selected, the preview shows
// that tree as the scene draws it (its edits applied); a click there selects the branch under
// the cursor, a drag bends it (one undo step), Delete prunes it (one step), the preview shows
// each result, and undo gives back the opened bytes. Another tool gives the preview back to
// the species.
#include <memory>

#include <QStandardPaths>
#include <QTemporaryDir>
#include <QTest>

#include "demowindow.h"
#include "document/document.h"
#include "limbonscreen.h"
#include "ui/generation/documentgenerator.h"
#include "ui/generation/treebranches.h"
#include "ui/mainwindow.h"
#include "ui/speciesbranchediting.h"
#include "ui/speciesworkbench.h"
#include "ui/viewport/toolcontroller.h"
#include "ui/viewport/tools/branchtool.h"
#include "ui/viewport/viewport.h"
#include "uitest.h"

using namespace sylva;
using namespace sylva::ui;

namespace {
constexpr int kTimeoutMs = 120000;
} // namespace

class TestSpeciesBranchEdit : public QObject {
    Q_OBJECT

private:
    std::unique_ptr<MainWindow> mWindow;
    QTemporaryDir mDir;
    doc::TreeId mTree = 0;
    QString mOriginal;

    doc::Document& document() { return mWindow->document(); }
    SpeciesWorkbench* workbench() {
        return mWindow->findChild<SpeciesWorkbench*>(QStringLiteral("speciesWorkbench"));
    }
    Viewport* preview() { return workbench()->previewViewport(); }
    BranchTool& tool() { return workbench()->branchEditing()->tool(); }
    const DrawnTree* drawn() { return shownTree(mWindow->generator().result(), mTree); }

    void settle() {
        QVERIFY(mWindow->waitForGeneration(kTimeoutMs));
        QTest::qWait(100);
    }

    /// A pixel of the preview where a limb (order 1) of the tree is drawn and picked.
    std::pair<QPoint, std::string> limbInPreview() {
        const DrawnTree* t = drawn();
        if (!t) return {};
        return test::limbOnScreen(*preview(), tool(), *t, mTree, document().branchEdits(mTree));
    }

private Q_SLOTS:
    void initTestCase() {
        QStandardPaths::setTestModeEnabled(true);
        QVERIFY(mDir.isValid());
        mWindow = test::openDemoWindow(mDir, {1400, 1000});
        QVERIFY(mWindow);
        settle();
        QVERIFY(!document().treeIds().empty());
        mTree = document().treeIds().front();
        mOriginal = document().serialized();
        const std::string species = document().tree(mTree).species;
        mWindow->editSpecies(QString::fromStdString(species));
        QVERIFY(workbench() && workbench()->branchEditing());
        QTest::qWait(300);
    }
    void cleanupTestCase() { mWindow.reset(); }

    void previewShowsTheSelectedTreeWithTheBranchTool() {
        document().selectTrees({mTree});
        QVERIFY(!workbench()->showsTree()); // the Select tool: the species' own preview
        mWindow->tools().setTool(ToolController::Tool::Branch);
        QVERIFY(workbench()->showsTree());
        QCOMPARE(workbench()->branchEditing()->tree(), std::optional<doc::TreeId>(mTree));
        QCOMPARE(preview()->trees().size(), std::size_t(1));
        QCOMPARE(preview()->trees().front().mesh, drawn()->mesh); // the scene's tree as drawn
        QTest::qWait(200);
        QVERIFY(preview()->grabFramebuffer().save(test::outputPath("preview_branch_tree.png")));
    }

    void clickSelectsDragBendsDeletePrunes() {
        auto [at, branch] = limbInPreview();
        QVERIFY2(!branch.empty(), "no limb of the tree is drawn where it projects in the preview");
        QTest::mouseClick(preview(), Qt::LeftButton, {}, at);
        QVERIFY(document().selectedBranch());
        QCOMPARE(document().selectedBranch()->branch, branch);
        QCOMPARE(document().serialized(), mOriginal); // selecting is no edit
        QVERIFY(!tool().lines().empty());             // highlighted in the preview

        // A drag bends it: one undo step, and the preview shows the bent tree.
        const int steps = document().undoStack()->index();
        test::dragThrough(preview(), {at, at + QPoint(30, -25), at + QPoint(60, -50)});
        QCOMPARE(document().undoStack()->index(), steps + 1);
        const auto& edits = document().branchEdits(mTree);
        QCOMPARE(edits.size(), std::size_t(1));
        QCOMPARE(edits.front().branch, branch);
        QVERIFY(edits.front().bend);
        settle();
        QVERIFY(workbench()->showsTree());
        QCOMPARE(preview()->trees().front().mesh, drawn()->mesh);
        const std::size_t bentVertices = drawn()->mesh->vertexCount();

        // Delete (the key in the preview) prunes the selected branch: one more step.
        document().setSelectedBranch(doc::Document::BranchRef{mTree, branch});
        preview()->setFocus();
        QTest::keyClick(preview(), Qt::Key_Delete);
        QCOMPARE(document().undoStack()->index(), steps + 2);
        QVERIFY(document().branchEdits(mTree).front().prune);
        settle();
        QCOMPARE(preview()->trees().front().mesh, drawn()->mesh);
        QVERIFY2(drawn()->mesh->vertexCount() < bentVertices, "the pruned limb is still drawn");
        QVERIFY(preview()->grabFramebuffer().save(test::outputPath("preview_branch_pruned.png")));

        // Undo back to the opened bytes.
        document().undoStack()->undo();
        document().undoStack()->undo();
        QCOMPARE(document().serialized(), mOriginal);
        settle();
    }

    void anotherToolGivesThePreviewBack() {
        mWindow->tools().setTool(ToolController::Tool::Select);
        QVERIFY(!workbench()->showsTree());
        QVERIFY(preview()->trees().empty());
        QVERIFY(!workbench()->branchEditing()->tree());
    }
};

QTEST_MAIN(TestSpeciesBranchEdit)
#include "test_speciesbranchedit.moc"
