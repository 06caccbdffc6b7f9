#pragma once

#include <optional>
#include <vector>

#include <QPoint>

#include "document/document.h"
#include "ui/viewport/tools/scenetool.h"

namespace sylva::ui {

class SelectTool;

/// Move: drag a selected tree (all selected trees move together) along the ground with a live
/// preview; the ring drawn on the ground around the selection turns each tree about its trunk
/// when dragged along, the box above it scales them when dragged up or down (Ctrl+drag and
/// Shift+drag on a tree do the same). The release is one undo step; a tree dropped into an
/// obstacle's footprint is refused with a message and goes back. A click selects as the
/// Select tool's does.
class MoveTool : public SceneTool {
public:
    /// The handles for the selected hand-placed trees: a ring on the ground around them and a
    /// box above the tallest.
    struct Handles {
        glm::vec3 centre{0.0f};      ///< the selected trunks' mean position
        float radius = 1.0f;         ///< the ring's, metres
        glm::vec3 scaleHandle{0.0f}; ///< the box's centre, above the crowns
    };
    enum class Handle { None, Ring, Scale };

    MoveTool(ToolContext& context, SelectTool& select) : SceneTool(context), mSelect(select) {}

    bool press(QMouseEvent* event) override;
    void move(QMouseEvent* event) override;
    void release(QMouseEvent* event) override;
    void click(QMouseEvent* event) override;

    /// The handles of the selection; none without selected hand-placed trees drawn.
    std::optional<Handles> handles() const;
    /// The handle drawn within a few pixels of \p pos (widget pixels).
    Handle handleAt(const QPoint& pos) const;
    /// The handles as lines for the viewport to draw over the scene.
    std::vector<OverlayLine> handleLines() const;
    /// Moves the selected trees by (dx, 0, dz) metres as one undo step (the arrow keys, in
    /// every tool); refused with a message when one would stand in an obstacle's footprint.
    void nudge(float dx, float dz);

private:
    struct Dragged {
        doc::TreeId id = 0;
        std::size_t viewIndex = 0;
        doc::ProjectInstance start;
        glm::mat4 startTransform{1.0f};
    };
    enum class DragMode { Move, Rotate, Scale };
    void dragTo(const QPoint& pos, Qt::KeyboardModifiers modifiers);
    bool startDrag(doc::TreeId hit);
    /// The angle (radians, about +y as glm::rotate turns) of the ground under \p pos around
    /// the ring's centre, or none when the ray misses the ground plane.
    std::optional<double> ringAngle(const QPoint& pos) const;
    doc::ProjectInstance draggedInstance(const Dragged& d) const;

    SelectTool& mSelect;
    QPoint mPress, mLast;
    std::vector<Dragged> mDragged;
    glm::vec3 mDragStart{0.0f};
    float mDragHeight = 0.0f;
    glm::vec3 mDragMove{0.0f}; ///< the drag so far: a move, or a rotation, or a scale
    double mDragDegrees = 0.0;
    double mDragScale = 1.0;
    DragMode mDragMode = DragMode::Move;
    Handle mDragHandle = Handle::None; ///< the handle being dragged
    Handles mDragHandles;              ///< the handles as they were when the drag began
    double mRingLast = 0.0, mRingTotal = 0.0;
};

} // namespace sylva::ui
