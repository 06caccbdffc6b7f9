#pragma once

#include <functional>

#include <QObject>
#include <glm/vec3.hpp>

class QAction;
class QWidget;

namespace sylva::doc {
class Document;
}

namespace sylva::ui {

struct GenerationResult;

/// The Edit and Scene menus' actions on the document's contents and selection, kept out of the
/// window as Tiled keeps its `MapDocumentActionHandler`: delete, duplicate, select all trees,
/// add a tree, add a domain, add a species from a file, import an obstacle. Each is a Document
/// call (one undo step); a refused edit comes out as failed(), never as an exception.
class DocumentActions : public QObject {
    Q_OBJECT

public:
    /// \param target where Add tree plants (the viewport camera's target, on the ground)
    /// \param dialogParent the window the file dialogs belong to
    DocumentActions(doc::Document& document, std::function<glm::vec3()> target,
                    QWidget* dialogParent);

    /// The shown generation: Delete with a branch selected prunes it with its anchor.
    void setResult(std::function<const GenerationResult&()> result) { mResult = std::move(result); }

    QAction* deleteAction() const { return mDelete; }
    QAction* duplicateAction() const { return mDuplicate; }
    QAction* selectAllAction() const { return mSelectAll; }
    QAction* addSpeciesAction() const { return mAddSpecies; }
    QAction* addTreeAction() const { return mAddTree; }
    QAction* importObstacleAction() const { return mImportObstacle; }
    QAction* addDomainAction() const { return mAddDomain; }

    /// Prunes the Branch tool's selected branch; else removes the selected trees, or else the
    /// first selected obstacle, domain or species.
    void deleteSelection();
    /// Copies the selected trees beside them and selects the copies.
    void duplicateSelection();
    void selectAllTrees();
    /// A tree of the project's first species at the target, on the ground, selected.
    void addTreeAtTarget();
    /// A 40 m square domain around the origin.
    void addDomain();

Q_SIGNALS:
    /// An edit the document refused; the message says why.
    void failed(const QString& message);

private:
    void showAddSpeciesDialog();
    void showImportObstacleDialog();
    void reportCurrentError();

    doc::Document& mDocument;
    std::function<glm::vec3()> mTarget;
    QWidget* mDialogParent;
    QAction* mDelete = nullptr;
    QAction* mDuplicate = nullptr;
    QAction* mSelectAll = nullptr;
    QAction* mAddSpecies = nullptr;
    QAction* mAddTree = nullptr;
    QAction* mImportObstacle = nullptr;
    QAction* mAddDomain = nullptr;
    std::function<const GenerationResult&()> mResult;
};

} // namespace sylva::ui
