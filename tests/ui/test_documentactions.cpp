// DocumentActions: the Edit and Scene menus' edits, each one undo step, refusals as messages.
#include <QAction>
#include <QDir>
#include <QSignalSpy>
#include <QTest>
#include <QUndoStack>
#include <QWidget>

#include "document/document.h"
#include "ui/document/documentactions.h"

using namespace sylva;
using namespace sylva::ui;

class TestDocumentActions : public QObject {
    Q_OBJECT

private:
    QWidget mWindow;
    doc::Document mDocument;
    glm::vec3 mTarget{3.0f, 7.0f, -4.0f};
    DocumentActions* mActions = nullptr;

private Q_SLOTS:
    void init() {
        mDocument.open(QDir(QStringLiteral(SYLVA_TEST_DATA_DIR))
                           .filePath(QStringLiteral("projects/small.sylva")));
        delete mActions;
        mActions = new DocumentActions(
            mDocument, [this] { return mTarget; }, &mWindow);
    }

    void actionsHaveTheirNamesAndShortcuts() {
        QCOMPARE(mActions->deleteAction()->objectName(), QStringLiteral("actionDelete"));
        QCOMPARE(mActions->deleteAction()->shortcut(), QKeySequence(QKeySequence::Delete));
        QCOMPARE(mActions->duplicateAction()->shortcut(), QKeySequence(QStringLiteral("Ctrl+D")));
        QCOMPARE(mActions->addTreeAction()->shortcut(), QKeySequence(QStringLiteral("Ctrl+T")));
        QCOMPARE(mWindow.findChild<QAction*>(QStringLiteral("actionSelectAll")),
                 mActions->selectAllAction());
    }

    void addsATreeAtTheTargetOnTheGround() {
        const std::size_t before = mDocument.treeIds().size();
        mActions->addTreeAction()->trigger();
        QCOMPARE(mDocument.treeIds().size(), before + 1);
        const QList<doc::TreeId> selected = mDocument.selectedTrees();
        QCOMPARE(selected.size(), 1);
        const doc::ProjectInstance& t = mDocument.tree(selected.front());
        QCOMPARE(t.species, std::string("bush")); // the first species
        QCOMPARE(t.position, glm::vec3(3.0f, 0.0f, -4.0f));
    }

    void duplicatesThenDeletesTheSelection() {
        mActions->selectAllAction()->trigger();
        const int trees = int(mDocument.treeIds().size());
        QCOMPARE(mDocument.selectedTrees().size(), trees);
        mActions->duplicateAction()->trigger();
        QCOMPARE(int(mDocument.treeIds().size()), 2 * trees);
        QCOMPARE(mDocument.selectedTrees().size(), trees); // the copies
        mActions->deleteAction()->trigger();
        QCOMPARE(int(mDocument.treeIds().size()), trees);
        mDocument.undoStack()->undo();
        QCOMPARE(int(mDocument.treeIds().size()), 2 * trees);
    }

    void deletesTheFirstSelectedObstacleAndAddsADomain() {
        const std::size_t domains = mDocument.project().domains.size();
        mActions->addDomainAction()->trigger();
        QCOMPARE(mDocument.project().domains.size(), domains + 1);
        QCOMPARE(mDocument.project().domains.back().max, glm::vec2(20.0f, 20.0f));
        mDocument.setSelection({{doc::ItemRef::Kind::Obstacle, 0}});
        mActions->deleteSelection();
        QVERIFY(mDocument.project().obstacles.empty());
    }

    void aRefusedEditIsAMessage() {
        mDocument.newProject(); // no species: no tree can be added
        QSignalSpy failed(mActions, &DocumentActions::failed);
        mActions->addTreeAtTarget();
        QCOMPARE(failed.size(), 1);
        QVERIFY(failed.front().front().toString().contains(QStringLiteral("add a species")));
        QVERIFY(mDocument.treeIds().empty());
    }
};

QTEST_MAIN(TestDocumentActions)
#include "test_documentactions.moc"
