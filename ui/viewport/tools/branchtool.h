#pragma once

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <QPoint>

#include "document/document.h"
#include "engine/skeleton/branches.h"
#include "ui/viewport/tools/scenetool.h"

namespace sylva::ui {

struct DrawnTree;

/// Branch: hand edits of single branches of a hand-placed tree (docs/editor.md#the-branch-tool).
/// A click selects the branch under the cursor (the drawn tree's triangle hit, then the nearest
/// segment of the tree as its edits leave it), shown highlighted over the scene and in
/// Properties; dragging a branch turns it about its base (a bend, one undo step when the mouse
/// is released); Delete prunes the selected branch (Edit ▸ Delete, DocumentActions); Escape
/// lets it go.
class BranchTool : public SceneTool {
public:
    explicit BranchTool(ToolContext& context) : SceneTool(context) {}

    bool press(QMouseEvent* event) override;
    void move(QMouseEvent* event) override;
    void release(QMouseEvent* event) override;
    void click(QMouseEvent* event) override;
    bool key(QKeyEvent* event) override;

    /// The branch drawn under \p pos (widget pixels): a hand-placed tree's, or none.
    std::optional<doc::Document::BranchRef> branchAt(const QPoint& pos) const;
    /// The selected branch (yellow) and what it carries (orange), bent as the drag has it.
    std::vector<OverlayLine> lines() const;

private:
    /// A shown tree as its edits leave it: its branches, the edited skeleton their nodes
    /// index, and each node's branch; remade when the tree or its edits change.
    struct Shown {
        doc::TreeId tree = 0;
        std::shared_ptr<const skel::Skeleton> grown; ///< held: a new one is never taken for it
        std::vector<skel::BranchEdit> edits;
        std::vector<skel::Branch> branches;
        skel::Skeleton edited;
        std::vector<std::int32_t> branchOfNode;
        glm::mat4 transform{1.0f};
    };
    const Shown* shown(doc::TreeId tree) const;
    /// The selected branch's index in shown(tree)->branches, or -1.
    int selectedIndex(const Shown& s) const;

    struct Drag {
        doc::Document::BranchRef branch;
        glm::vec3 base{0.0f}, tip{0.0f};    ///< world, as the drag began
        glm::vec3 grab{0.0f};               ///< where the cursor met the drag plane
        glm::vec3 normal{0.0f};             ///< the drag plane's (the view direction)
        std::optional<glm::vec3> direction; ///< the new base -> tip direction (world)
        QPoint press;
    };
    std::optional<glm::vec3> onDragPlane(const QPoint& pos) const;

    mutable std::optional<Shown> mShown;
    std::optional<Drag> mDrag;
};

} // namespace sylva::ui
