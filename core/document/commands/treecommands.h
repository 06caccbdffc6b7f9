#pragma once

#include "document/commands/command.h"

namespace sylva::doc::cmd {

/// Adds a tree at an index with an id (redo), removes it and gives the project its former
/// next tree id back (undo).
class AddTree : public QUndoCommand {
public:
    AddTree(Document& doc, int index, TreeId id, ProjectInstance tree,
            QUndoCommand* parent = nullptr);
    void undo() override;
    void redo() override;

private:
    Document& mDoc;
    int mIndex;
    TreeId mId;
    ProjectInstance mTree;
    std::uint64_t mNextBefore = 0;
};

/// Removes a tree (redo) and puts it back at its index with its id (undo).
class RemoveTree : public QUndoCommand {
public:
    RemoveTree(Document& doc, TreeId id, QUndoCommand* parent = nullptr);
    void undo() override;
    void redo() override;

private:
    Document& mDoc;
    TreeId mId;
    int mIndex;
    ProjectInstance mTree;
};

/// Moves, rotates, scales, reseeds or changes the species of a tree; merges while a drag is in
/// progress. The text names what changed ("Move tree", "Rotate tree", ...).
QUndoCommand* changeTree(Document& doc, TreeId id, const ProjectInstance& newTree, bool commit);

/// Replaces a tree's hand edits of single branches (docs/branch-edits.md): one step, obsolete
/// when nothing changes. The text names what changed ("Prune branch", "Edit branch", "Clear
/// branch edits").
QUndoCommand* changeBranchEdits(Document& doc, TreeId id,
                                const std::vector<skel::BranchEdit>& newEdits);

} // namespace sylva::doc::cmd
