#pragma once

#include <memory>
#include <optional>

#include <QObject>

#include "document/document.h"
#include "ui/viewport/tools/toolcontext.h"

namespace sylva::ui {

class BranchTool;
class DocumentGenerator;
class SpeciesWorkbench;
class ToolController;

/// The Branch tool in the Species Editor's preview (docs/editor.md#the-branch-tool). Branch
/// edits belong to a hand-placed tree of the project, not to a species, so while the window's
/// tool is Branch the preview shows that tree as the scene draws it, edits and all, in place of
/// the species' own preview: the tree of the selected branch, else the first selected
/// hand-placed tree, else the one it showed last while it is still in the project. There a
/// click selects a branch, a drag bends it and Delete prunes it, each one undo step of the
/// document, exactly as in the 3D view (the same BranchTool over the preview's viewport).
/// Another tool, or no such tree, gives the preview back to the species.
class SpeciesBranchEditing : public QObject {
    Q_OBJECT

public:
    SpeciesBranchEditing(doc::Document& document, SpeciesWorkbench& workbench,
                         ToolController& tools, DocumentGenerator& generator);
    ~SpeciesBranchEditing() override;

    /// The tree the preview shows for branch editing, or none (the species' preview).
    std::optional<doc::TreeId> tree() const { return mTree; }
    BranchTool& tool() { return *mTool; }

private:
    /// Picks the tree to show (or none) and shows it; \p regrown: a new generation arrived.
    void update(bool regrown);

    doc::Document& mDocument;
    SpeciesWorkbench& mWorkbench;
    ToolController& mTools;
    DocumentGenerator& mGenerator;
    ToolContext mContext;
    std::unique_ptr<BranchTool> mTool;
    std::optional<doc::TreeId> mTree;
};

} // namespace sylva::ui
