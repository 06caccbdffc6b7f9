#pragma once

#include "ui/viewport/tools/toolcontext.h"
#include "ui/viewport/viewport.h"

namespace sylva::ui {

/// One of the viewport's tools (ToolController picks the current one and hands it the
/// viewport's gestures, ViewportTool's contract). Gestures a tool does not use do nothing.
/// The tools' strings keep ToolController's translation context, where they were written
/// first (QCoreApplication::translate("sylva::ui::ToolController", …), which lupdate reads).
class SceneTool : public ViewportTool {
public:
    explicit SceneTool(ToolContext& context) : mContext(context) {}

    bool press(QMouseEvent*) override { return false; }
    void move(QMouseEvent*) override {}
    void release(QMouseEvent*) override {}
    void click(QMouseEvent*) override {}
    /// The keys every tool shares are ToolController's; none is a tool's own yet.
    bool key(QKeyEvent*) override { return false; }

protected:
    ToolContext& mContext;
};

} // namespace sylva::ui
