#pragma once

#include <QPoint>

#include "ui/viewport/tools/scenetool.h"

namespace sylva::ui {

/// Select: a click picks the tree under the cursor (its own triangles, so a click through a gap
/// in a crown picks what is behind); Shift adds, Ctrl toggles; Ctrl+drag draws a rubber band
/// and adds the hand-placed trees inside it; a domain's tree selects its domain, an obstacle
/// the obstacle.
class SelectTool : public SceneTool {
public:
    using SceneTool::SceneTool;

    bool press(QMouseEvent* event) override;
    void move(QMouseEvent* event) override;
    void release(QMouseEvent* event) override;
    void click(QMouseEvent* event) override;

    /// Selects what is drawn at \p pos as a click with \p modifiers does (the Move tool's
    /// click too).
    void selectAt(const QPoint& pos, Qt::KeyboardModifiers modifiers);
    /// Selects the previous (\p step -1) or next (+1) hand-placed tree in document order.
    void stepSelection(int step);

private:
    void finishRubberBand();

    QPoint mPress, mLast;
};

} // namespace sylva::ui
