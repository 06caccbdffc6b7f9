#pragma once

#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <QObject>
#include <QPoint>

#include "document/document.h"
#include "ui/viewport/tools/movetool.h"
#include "ui/viewport/tools/toolcontext.h"
#include "ui/viewport/viewport.h"

namespace sylva::ui {

struct GenerationResult;
class SceneTool;
class SelectTool;
class PlaceTool;
class BrushTool;
class EraseTool;
class BranchTool;

/// The viewport's tools (a toolbar and shortcuts, docs/editor.md). Each gesture becomes document
/// edits (one undo step per gesture); the camera keeps working with every tool (left drag
/// orbits where a tool does not take it, right or middle drag pans, the wheel zooms, WASD flies).
///
/// - Select: click picks the tree under the cursor (its own triangles, so a click through a gap
///   in a crown picks what is behind); Shift adds, Ctrl toggles; Ctrl+drag draws a rubber band
///   and adds the hand-placed trees inside it; a domain's tree selects its domain, an obstacle
///   the obstacle; `[` and `]` step through the trees.
/// - Move: drag a selected tree (all selected trees move together) along the ground with a live
///   preview; the ring drawn on the ground around the selection turns each tree about its
///   trunk when dragged along, the box above it scales them when dragged up or down (Ctrl+drag
///   and Shift+drag on a tree do the same); arrow keys nudge 10 cm (Shift: 1 m). The
///   release is one undo step, after which the document regrows and re-adapts the moved trees
///   and the neighbours whose crowns they now touch. A tree dropped into an obstacle's
///   footprint is refused with a message and goes back.
/// - Place: a click drops a tree of the chosen species on the ground, with a fresh seed and a
///   random rotation.
/// - Brush: paints trees of a species mix (weights) with a radius and a density, keeping
///   reference 000's rules: no two trunks closer than their crowns' cores, no trunk in an
///   obstacle's footprint, random rotation and ±5 % scale. One stroke is one undo step and the
///   forest regrows once, when the stroke ends.
/// - Erase: removes the hand-placed trees the brush passes over; one stroke, one step.
/// - Branch: click selects the branch under the cursor, drag bends it, Delete prunes it
///   (BranchTool; docs/editor.md#the-branch-tool).
///
/// Each tool is its own class (ui/viewport/tools/: SelectTool, MoveTool, PlaceTool, BrushTool,
/// EraseTool, over a ToolContext they share); this class keeps the current one, hands it the
/// viewport's gestures and handles the keys every tool shares.
class ToolController : public QObject, public ViewportTool {
    Q_OBJECT

public:
    enum class Tool { Select, Move, Place, Brush, Erase, Branch };
    static QString name(Tool tool);
    /// "select", "move", "place", "brush", "erase", "branch" (the script names); false for
    /// another.
    static bool fromName(const QString& name, Tool& tool);

    using Brush = BrushSettings;

    ToolController(doc::Document& document, Viewport& viewport,
                   std::function<const GenerationResult&()> result, QObject* parent = nullptr);
    ~ToolController() override;

    Tool tool() const { return mTool; }
    void setTool(Tool tool);
    /// The species the Place tool drops (the first species when empty or unknown).
    void setPlaceSpecies(const std::string& species);
    std::string placeSpecies() const;
    void setBrush(const Brush& brush);
    const Brush& brush() const { return mContext.brush; }

    /// The Move tool's handles for the selected hand-placed trees: a ring on the ground around
    /// them and a box above the tallest. None in other tools or without such a selection.
    using Handles = MoveTool::Handles;
    std::optional<Handles> handles() const;
    using Handle = MoveTool::Handle;
    /// The handle drawn within a few pixels of \p pos (widget pixels).
    Handle handleAt(const QPoint& pos) const;
    /// The handles as lines for the viewport to draw over the scene (the Branch tool: its
    /// selected branch).
    std::vector<OverlayLine> handleLines() const;
    /// The Branch tool (its picking, for tests and scripts).
    BranchTool& branchTool() { return *mBranch; }

    /// Selects the previous (\p step -1) or next (+1) hand-placed tree in document order.
    void stepSelection(int step);
    /// The crown radius the spacing rules use for a species: the median of its grown trees'
    /// half crown widths in the last generation (2 m when it has none yet).
    float crownRadius(std::uint32_t species) const;
    /// The highest surface at (x, z) in the last generation: terrain (or y = 0), obstacles.
    float surfaceHeight(float x, float z) const { return mContext.surfaceHeight(x, z); }

    // ViewportTool
    bool press(QMouseEvent* event) override;
    void move(QMouseEvent* event) override;
    void release(QMouseEvent* event) override;
    void click(QMouseEvent* event) override;
    bool key(QKeyEvent* event) override;

Q_SIGNALS:
    void toolChanged(sylva::ui::ToolController::Tool tool);
    /// Something the user should read (a refused drop, an empty species list).
    void message(const QString& text);
    /// A plain click (Select tool) hit hand-placed tree \p id at \p local (the tree's own
    /// coordinates, before its placement): the species editor shows the node and rule behind it.
    void treeBranchClicked(std::uint32_t id, const glm::vec3& local);

private:
    /// The current tool's class.
    SceneTool& current();

    Tool mTool = Tool::Select;
    ToolContext mContext;
    std::unique_ptr<SelectTool> mSelect;
    std::unique_ptr<MoveTool> mMove;
    std::unique_ptr<PlaceTool> mPlace;
    std::unique_ptr<BrushTool> mBrush;
    std::unique_ptr<EraseTool> mErase;
    std::unique_ptr<BranchTool> mBranch;
};

} // namespace sylva::ui
