#include "ui/generation/treebranches.h"

#include "engine/util/error.h"

namespace sylva::ui {

std::vector<skel::BranchEdit> localEdits(const DrawnTree& drawn,
                                         const std::vector<skel::BranchEdit>& edits) {
    std::vector<skel::BranchEdit> local = edits;
    const glm::mat3 toLocal = glm::inverse(glm::mat3(drawn.transform));
    for (skel::BranchEdit& e : local)
        if (e.bend) e.bend = toLocal * *e.bend;
    return local;
}

std::vector<skel::Branch> editedBranchesOf(const DrawnTree& drawn,
                                           const std::vector<skel::BranchEdit>& edits,
                                           skel::Skeleton* edited) {
    return skel::editedBranches(*drawn.grown, localEdits(drawn, edits), edited);
}

const DrawnTree* shownTree(const GenerationResult& result, doc::TreeId id) {
    for (const DrawnTree& t : result.trees)
        if (t.docId == id && t.grown) return &t;
    return nullptr;
}

skel::BranchEdit branchEditOf(const doc::Document& document, doc::TreeId id,
                              const std::string& branch) {
    for (const skel::BranchEdit& e : document.branchEdits(id))
        if (e.branch == branch) return e;
    skel::BranchEdit e;
    e.branch = branch;
    return e;
}

void applyBranchEdit(doc::Document& document, const DrawnTree* drawn, doc::TreeId id,
                     const skel::BranchEdit& given) {
    skel::BranchEdit edit = given;
    // Where the branch is in the tree as grown: the edit finds it there again after a change
    // of topology shifts the ids (docs/branch-edits.md#anchors).
    if (!edit.anchor && drawn && drawn->grown)
        for (const skel::Branch& b : skel::branchesOf(*drawn->grown))
            if (b.id == edit.branch) edit.anchor = skel::anchorOf(b);
    if (!edit.lock || !edit.locked.empty()) {
        document.editBranch(id, edit);
        return;
    }
    if (!drawn || !drawn->grown)
        throw InvalidInput("tree " + std::to_string(id) +
                           " is not grown yet: its branch cannot be locked");
    // Locked now: its geometry as the tree shows it, the other edits applied, in the tree's
    // frame (bends are world directions in the document).
    const std::vector<skel::BranchEdit> local = localEdits(*drawn, document.branchEdits(id));
    skel::BranchEdit kept = localEdits(*drawn, {edit}).front();
    skel::lockBranch(*drawn->grown, local, kept);
    skel::BranchEdit stored = edit; // the world bend kept as given
    stored.lock = true;
    stored.lockedBase = kept.lockedBase;
    stored.locked = std::move(kept.locked);
    stored.lockedLeaves = std::move(kept.lockedLeaves);
    document.editBranch(id, stored);
}

void pruneSelectedBranch(doc::Document& document, const DrawnTree* drawn) {
    const std::optional<doc::Document::BranchRef> selected = document.selectedBranch();
    if (!selected) return;
    skel::BranchEdit edit = branchEditOf(document, selected->tree, selected->branch);
    if (edit.lock)
        throw InvalidInput("branch " + selected->branch +
                           " is locked: unlock it before pruning it");
    edit.prune = true;
    applyBranchEdit(document, drawn, selected->tree, edit);
    document.setSelectedBranch(std::nullopt);
}

} // namespace sylva::ui
