#include "document/commands/treecommands.h"

#include <algorithm>

namespace sylva::doc::cmd {

AddTree::AddTree(Document& doc, int index, TreeId id, ProjectInstance tree, QUndoCommand* parent)
    : QUndoCommand(QCoreApplication::translate("Commands", "Add tree"), parent), mDoc(doc),
      mIndex(index), mId(id), mTree(std::move(tree)) {}

void AddTree::undo() {
    mDoc.rawRemoveTree(mId);
    mDoc.rawSetNextTreeId(mNextBefore);
}

void AddTree::redo() {
    mNextBefore = mDoc.project().nextTreeId;
    mDoc.rawInsertTree(mIndex, mId, mTree);
}

RemoveTree::RemoveTree(Document& doc, TreeId id, QUndoCommand* parent)
    : QUndoCommand(QCoreApplication::translate("Commands", "Remove tree"), parent), mDoc(doc),
      mId(id), mIndex(doc.treeIndex(id)), mTree(doc.tree(id)) {}

void RemoveTree::undo() {
    mDoc.rawInsertTree(mIndex, mId, mTree);
}

void RemoveTree::redo() {
    mDoc.rawRemoveTree(mId);
}

QUndoCommand* changeTree(Document& doc, TreeId id, const ProjectInstance& newTree, bool commit) {
    const ProjectInstance& old = doc.tree(id);
    QString label = QCoreApplication::translate("Commands", "Edit tree");
    int changes = 0;
    auto note = [&](bool differs, const char* what) {
        if (!differs) return;
        ++changes;
        label = QCoreApplication::translate("Commands", what);
    };
    note(old.position != newTree.position, QT_TRANSLATE_NOOP("Commands", "Move tree"));
    note(old.rotation != newTree.rotation, QT_TRANSLATE_NOOP("Commands", "Rotate tree"));
    note(old.scale != newTree.scale, QT_TRANSLATE_NOOP("Commands", "Scale tree"));
    note(old.seed != newTree.seed, QT_TRANSLATE_NOOP("Commands", "Change tree seed"));
    note(old.species != newTree.species, QT_TRANSLATE_NOOP("Commands", "Change tree species"));
    note(old.growth != newTree.growth, QT_TRANSLATE_NOOP("Commands", "Change tree growth"));
    note(old.season != newTree.season, QT_TRANSLATE_NOOP("Commands", "Change tree season"));
    if (changes > 1) label = QCoreApplication::translate("Commands", "Edit tree");
    return new ChangeValue<TreeId, ProjectInstance>(
        doc, kMergeTree, id, old, newTree, commit,
        [](Document& d, const TreeId& key, const ProjectInstance& v) { d.rawSetTree(key, v); },
        label);
}

QUndoCommand* changeBranchEdits(Document& doc, TreeId id,
                                const std::vector<skel::BranchEdit>& newEdits) {
    const std::vector<skel::BranchEdit>& old = doc.tree(id).branchEdits;
    QString label = QCoreApplication::translate("Commands", "Edit branch");
    if (newEdits.empty() && !old.empty())
        label = QCoreApplication::translate("Commands", "Clear branch edits");
    else {
        // A branch newly pruned (a new edit, or an edit that bent or scaled it before).
        bool pruned = false;
        for (const skel::BranchEdit& e : newEdits) {
            if (!e.prune) continue;
            const auto before =
                std::find_if(old.begin(), old.end(),
                             [&e](const skel::BranchEdit& o) { return o.branch == e.branch; });
            pruned = pruned || before == old.end() || !before->prune;
        }
        if (pruned) label = QCoreApplication::translate("Commands", "Prune branch");
    }
    return new ChangeValue<TreeId, std::vector<skel::BranchEdit>>(
        doc, kMergeBranchEdits, id, old, newEdits, true,
        [](Document& d, const TreeId& key, const std::vector<skel::BranchEdit>& v) {
            d.rawSetBranchEdits(key, v);
        },
        label);
}

} // namespace sylva::doc::cmd
