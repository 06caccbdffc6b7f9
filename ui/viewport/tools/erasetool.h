#pragma once

#include <QList>

#include <glm/glm.hpp>

#include "document/document.h"
#include "ui/viewport/tools/scenetool.h"

namespace sylva::ui {

/// Erase: removes the hand-placed trees the brush (ToolContext::brush's radius) passes over;
/// they vanish as it passes, and the stroke is one undo step.
class EraseTool : public SceneTool {
public:
    using SceneTool::SceneTool;

    bool press(QMouseEvent* event) override;
    void move(QMouseEvent* event) override;
    void release(QMouseEvent* event) override;

private:
    void erase(const glm::vec3& centre);

    QList<doc::TreeId> mErased;
};

} // namespace sylva::ui
