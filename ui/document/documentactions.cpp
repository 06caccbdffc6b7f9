#include "ui/document/documentactions.h"

#include <QAction>
#include <QFileDialog>
#include <QFileInfo>
#include <QInputDialog>
#include <QKeySequence>
#include <QLineEdit>

#include "document/document.h"
#include "document/errormessage.h"
#include "document/presetlibrary.h"
#include "engine/util/error.h"
#include "ui/generation/treebranches.h"

namespace sylva::ui {

DocumentActions::DocumentActions(doc::Document& document, std::function<glm::vec3()> target,
                                 QWidget* dialogParent)
    : QObject(dialogParent), mDocument(document), mTarget(std::move(target)),
      mDialogParent(dialogParent) {
    auto action = [this](const QString& text, auto slot) {
        auto* a = new QAction(text, this);
        connect(a, &QAction::triggered, this, slot);
        return a;
    };
    mDelete = action(tr("&Delete"), &DocumentActions::deleteSelection);
    mDelete->setObjectName(QStringLiteral("actionDelete"));
    mDelete->setShortcut(QKeySequence::Delete);
    mDuplicate = action(tr("D&uplicate"), &DocumentActions::duplicateSelection);
    mDuplicate->setObjectName(QStringLiteral("actionDuplicate"));
    mDuplicate->setShortcut(QKeySequence(tr("Ctrl+D")));
    mSelectAll = action(tr("Select &all trees"), &DocumentActions::selectAllTrees);
    mSelectAll->setObjectName(QStringLiteral("actionSelectAll"));
    mSelectAll->setShortcut(QKeySequence::SelectAll);
    mAddSpecies = action(tr("Add &species from file…"), &DocumentActions::showAddSpeciesDialog);
    mAddTree = action(tr("Add &tree"), &DocumentActions::addTreeAtTarget);
    mAddTree->setObjectName(QStringLiteral("actionAddTree"));
    mAddTree->setShortcut(QKeySequence(tr("Ctrl+T")));
    mImportObstacle = action(tr("Import &obstacle…"), &DocumentActions::showImportObstacleDialog);
    mAddDomain = action(tr("Add &domain"), &DocumentActions::addDomain);
}

void DocumentActions::reportCurrentError() {
    Q_EMIT failed(QString::fromStdString(doc::currentErrorMessage()));
}

void DocumentActions::deleteSelection() {
    try {
        if (mDocument.selectedBranch()) { // the Branch tool's selection: Delete prunes it
            pruneSelectedBranch(mDocument,
                                mResult ? shownTree(mResult(), mDocument.selectedBranch()->tree)
                                        : nullptr);
            return;
        }
        const QList<doc::ItemRef> selection = mDocument.selection();
        QList<doc::TreeId> trees = mDocument.selectedTrees();
        if (!trees.isEmpty()) {
            mDocument.removeTrees(trees);
            return;
        }
        for (const doc::ItemRef& item : selection) {
            if (item.kind == doc::ItemRef::Kind::Obstacle) mDocument.removeObstacle(int(item.id));
            if (item.kind == doc::ItemRef::Kind::Domain) mDocument.removeDomain(int(item.id));
            if (item.kind == doc::ItemRef::Kind::Species)
                mDocument.removeSpecies(mDocument.project().species[item.id].name);
            return; // indices of the rest changed
        }
    } catch (...) {
        reportCurrentError();
    }
}

void DocumentActions::duplicateSelection() {
    try {
        const QList<doc::TreeId> copies = mDocument.duplicateTrees(mDocument.selectedTrees());
        if (!copies.isEmpty()) mDocument.selectTrees(copies);
    } catch (...) {
        reportCurrentError();
    }
}

void DocumentActions::selectAllTrees() {
    mDocument.selectTrees(
        QList<doc::TreeId>(mDocument.treeIds().begin(), mDocument.treeIds().end()));
}

void DocumentActions::addTreeAtTarget() {
    try {
        if (mDocument.project().species.empty())
            throw InvalidInput("add a species first (Scene ▸ Add species from file…)");
        doc::ProjectInstance t;
        t.species = mDocument.project().species.front().name;
        const glm::vec3 target = mTarget();
        t.position = {target.x, 0.0f, target.z};
        t.seed = mDocument.project().newTreeSeed(mDocument.treeIds().size());
        mDocument.selectTrees({mDocument.addTree(t)});
    } catch (...) {
        reportCurrentError();
    }
}

void DocumentActions::addDomain() {
    try {
        doc::PlacementDomain d;
        d.min = {-20.0f, -20.0f};
        d.max = {20.0f, 20.0f};
        mDocument.addDomain(d);
    } catch (...) {
        reportCurrentError();
    }
}

void DocumentActions::showAddSpeciesDialog() {
    const QString path = QFileDialog::getOpenFileName(
        mDialogParent, tr("Add species"), doc::PresetLibrary::directory(),
        tr("Species and grammars (*.json *.lsys *.txt);;All files (*)"));
    if (path.isEmpty()) return;
    bool ok = false;
    const QString name =
        QInputDialog::getText(mDialogParent, tr("Add species"), tr("Name in the project:"),
                              QLineEdit::Normal, QFileInfo(path).completeBaseName(), &ok);
    if (!ok) return;
    try {
        mDocument.addSpecies(name.trimmed().toStdString(), path);
    } catch (...) {
        reportCurrentError();
    }
}

void DocumentActions::showImportObstacleDialog() {
    const QString path = QFileDialog::getOpenFileName(
        mDialogParent, tr("Import obstacle"), QFileInfo(mDocument.path()).absolutePath(),
        tr("Meshes (*.obj *.ply *.stl *.fbx *.gltf *.glb *.dae *.3ds *.off);;All files (*)"));
    if (path.isEmpty()) return;
    try {
        doc::ProjectObstacle o;
        o.file = path.toStdString();
        mDocument.addObstacle(o);
    } catch (...) {
        reportCurrentError();
    }
}

} // namespace sylva::ui
