#include "ui/speciesbranchediting.h"

#include "ui/generation/documentgenerator.h"
#include "ui/generation/treebranches.h"
#include "ui/speciesworkbench.h"
#include "ui/viewport/toolcontroller.h"
#include "ui/viewport/tools/branchtool.h"
#include "ui/viewport/viewport.h"

namespace sylva::ui {

SpeciesBranchEditing::SpeciesBranchEditing(doc::Document& document, SpeciesWorkbench& workbench,
                                           ToolController& tools, DocumentGenerator& generator)
    : QObject(&workbench), mDocument(document), mWorkbench(workbench), mTools(tools),
      mGenerator(generator),
      mContext(document, *workbench.previewViewport(),
               [&generator]() -> const GenerationResult& { return generator.result(); }),
      mTool(std::make_unique<BranchTool>(mContext)) {
    mContext.message = [this](const QString& text) { Q_EMIT mWorkbench.status(text, 8000); };
    connect(&mTools, &ToolController::toolChanged, this, [this] { update(false); });
    connect(&mDocument, &doc::Document::selectionChanged, this, [this] { update(false); });
    connect(&mDocument, &doc::Document::changed, this, [this](const doc::DocumentChange& c) {
        if (c.what & doc::DocumentChange::Reset) mTree.reset();
        update(false);
    });
    connect(&mGenerator, &DocumentGenerator::finished, this, [this] { update(true); });
}

// The workbench's child, as its preview view is (in a pane made before this): both go with the
// workbench, the view first, so nothing is handed back to it here.
SpeciesBranchEditing::~SpeciesBranchEditing() = default;

void SpeciesBranchEditing::update(bool regrown) {
    std::optional<doc::TreeId> tree;
    if (mTools.tool() == ToolController::Tool::Branch) {
        const GenerationResult& result = mGenerator.result();
        auto editable = [&](doc::TreeId id) {
            const DrawnTree* drawn = shownTree(result, id);
            return drawn && drawn->grown && drawn->mesh && mDocument.treeIndex(id) >= 0;
        };
        if (const auto& b = mDocument.selectedBranch(); b && editable(b->tree)) tree = b->tree;
        if (!tree)
            for (doc::TreeId id : mDocument.selectedTrees())
                if (editable(id)) {
                    tree = id;
                    break;
                }
        // A click on the sky lets the selection go: the preview keeps its tree.
        if (!tree && mTree && editable(*mTree)) tree = mTree;
    }
    Viewport* view = mWorkbench.previewViewport();
    if (!tree) {
        if (mTree) {
            mTree.reset();
            view->setTool(nullptr);
            view->setOverlay({});
            mWorkbench.showTree(nullptr, false);
        }
        return;
    }
    const bool changed = !mTree || *mTree != *tree;
    const DrawnTree* drawn = shownTree(mGenerator.result(), *tree);
    if (changed || regrown) {
        const ViewTree shown{drawn->docId, drawn->mesh, drawn->transform, drawn->lod, 0.0f};
        mWorkbench.showTree(&shown, changed);
    }
    if (changed) {
        mTree = tree;
        view->setTool(mTool.get());
        view->setOverlay([this] { return mTool->lines(); });
    }
    view->update();
}

} // namespace sylva::ui
