#pragma once

#include <optional>
#include <string>
#include <vector>

#include "document/document.h"
#include "engine/skeleton/branches.h"
#include "ui/generation/treegenerator.h"

namespace sylva::ui {

/// A tree's edits in its own frame: the document keeps bends as world directions.
std::vector<skel::BranchEdit> localEdits(const DrawnTree& drawn,
                                         const std::vector<skel::BranchEdit>& edits);

/// The branches of a shown tree as \p edits (world bends) leave them, with the ids of the
/// grown tree (skel::editedBranches); with \p edited, the edited skeleton their nodes index, in
/// the tree's own frame.
std::vector<skel::Branch> editedBranchesOf(const DrawnTree& drawn,
                                           const std::vector<skel::BranchEdit>& edits,
                                           skel::Skeleton* edited = nullptr);

/// The shown tree of the document's tree \p id in \p result (its grown skeleton kept), or null.
const DrawnTree* shownTree(const GenerationResult& result, doc::TreeId id);

/// Sets \p edit on tree \p id through the document, one undo step; with \p drawn, an edit
/// without an anchor gets its branch's (skel::BranchAnchor). An edit that locks without
/// kept geometry gets it first from \p drawn (skel::lockBranch: the branch as the tree shows
/// it, the tree's other edits applied), so that the lock keeps the geometry, not only a flag.
/// \throw InvalidInput as Document::editBranch, or when the tree is not shown to lock from.
void applyBranchEdit(doc::Document& document, const DrawnTree* drawn, doc::TreeId id,
                     const skel::BranchEdit& edit);

/// The tree's present edit of \p branch, or a new empty one.
skel::BranchEdit branchEditOf(const doc::Document& document, doc::TreeId id,
                              const std::string& branch);

/// Prunes the document's selected branch (Delete with a branch selected, in the Branch tool or
/// from Edit ▸ Delete): one undo step, then the branch is let go (its tree stays selected).
/// \throw InvalidInput for a locked branch or a trunk; nothing without a selected branch.
/// \p drawn: the selected branch's tree as shown (the edit's anchor), or null.
void pruneSelectedBranch(doc::Document& document, const DrawnTree* drawn = nullptr);

} // namespace sylva::ui
