#pragma once

#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "document/document.h"
#include "ui/viewport/tools/scenetool.h"

namespace sylva::ui {

/// Brush: paints trees of a species mix (weights) with a radius and a density
/// (ToolContext::brush), keeping reference 000's rules: no two trunks closer than their crowns'
/// cores, no trunk in an obstacle's footprint, random rotation and ±5 % scale. The stroke is
/// previewed in the viewport; it is one undo step and the forest regrows once, when it ends.
class BrushTool : public SceneTool {
public:
    using SceneTool::SceneTool;

    bool press(QMouseEvent* event) override;
    void move(QMouseEvent* event) override;
    void release(QMouseEvent* event) override;

private:
    /// Adds the trees of one dab around \p centre to the stroke and shows them.
    void dab(const glm::vec3& centre);

    std::vector<doc::ProjectInstance> mStroke; ///< the stroke's trees, added on release
    glm::vec3 mLastDab{1e30f};
    std::uint64_t mStrokes = 0;
};

} // namespace sylva::ui
