#include "ui/viewport/tools/erasetool.h"

#include <QMouseEvent>
#include <QSet>

namespace sylva::ui {

bool EraseTool::press(QMouseEvent* event) {
    const auto g = mContext.groundAt(event->position().toPoint());
    if (!g) return false;
    mErased.clear();
    erase(*g);
    return true;
}

void EraseTool::move(QMouseEvent* event) {
    if (const auto g = mContext.groundAt(event->position().toPoint())) erase(*g);
}

void EraseTool::release(QMouseEvent*) {
    const QList<doc::TreeId> erased = mErased;
    mErased.clear();
    mContext.viewport.setHiddenTrees({});
    if (!erased.isEmpty()) mContext.document.removeTrees(erased);
}

void EraseTool::erase(const glm::vec3& centre) {
    bool changed = false;
    for (const ViewTree& t : mContext.viewport.trees()) {
        if (t.id == 0 || mErased.contains(t.id)) continue;
        const glm::vec3 p = positionOf(t.transform);
        if (glm::length(glm::vec2(p.x - centre.x, p.z - centre.z)) <= mContext.brush.radius) {
            mErased << t.id;
            changed = true;
        }
    }
    if (changed) {
        QSet<std::uint32_t> hidden(mErased.begin(), mErased.end());
        mContext.viewport.setHiddenTrees(hidden); // the preview: they vanish as the brush passes
    }
}

} // namespace sylva::ui
