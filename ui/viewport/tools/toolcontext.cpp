#include "ui/viewport/tools/toolcontext.h"

#include <algorithm>

#include <QCoreApplication>

#include "engine/environment/obstaclescene.h"
#include "ui/generation/treegenerator.h"
#include "ui/viewport/viewport.h"

namespace sylva::ui {

std::optional<glm::vec3> ToolContext::groundAt(const QPoint& pos) const {
    const Ray ray = viewport.rayAt(pos);
    if (const auto& ground = result().ground; ground && !ground->empty()) {
        // The terrain under the cursor, where trees stand in a terrain project.
        const float reach = 10.0f * viewport.camera().farPlane();
        const env::SegmentHit hit =
            ground->intersect({ray.origin, ray.origin + reach * ray.direction});
        if (hit.hit) return hit.point;
        return std::nullopt;
    }
    // Past the far plane the plane's hit is the horizon, not ground anyone can see.
    const auto hit = hitPlane(ray, 0.0f);
    if (hit && glm::length(*hit - ray.origin) > viewport.camera().farPlane()) return std::nullopt;
    return hit;
}

float ToolContext::groundHeight(float x, float z) const {
    const auto& ground = result().ground;
    if (!ground || ground->empty()) return 0.0f;
    const env::SegmentHit h =
        ground->intersect({{x, ground->hi().y + 1.0f, z}, {x, ground->lo().y - 1.0f, z}});
    return h.hit ? h.point.y : 0.0f;
}

void ToolContext::noGroundUnderCursor() const {
    if (message)
        message(QCoreApplication::translate("sylva::ui::ToolController",
                                            "No ground under the cursor: nothing planted; click "
                                            "where the ground is drawn"));
}

float ToolContext::surfaceHeight(float x, float z) const {
    float height = groundHeight(x, z);
    const auto& obstacles = result().obstacles;
    if (obstacles && !obstacles->empty()) {
        const env::SegmentHit h = obstacles->intersect(
            {{x, obstacles->hi().y + 1.0f, z}, {x, obstacles->lo().y - 1.0f, z}});
        if (h.hit) height = std::max(height, h.point.y);
    }
    return height;
}

bool ToolContext::inObstacleFootprint(const glm::vec3& p) const {
    const auto& obstacles = result().obstacles;
    if (!obstacles || obstacles->empty()) return false;
    // As placement refuses: a vertical line through the trunk meets an obstacle.
    const env::Segment vertical{{p.x, obstacles->lo().y - 1.0f, p.z},
                                {p.x, obstacles->hi().y + 1.0f, p.z}};
    return obstacles->occluded(vertical);
}

float ToolContext::crownRadius(std::uint32_t species) const {
    std::vector<double> radii;
    for (const DrawnTree& t : result().trees)
        if (t.species == species && t.metrics.crownWidthM > 0)
            radii.push_back(0.5 * t.metrics.crownWidthM);
    if (radii.empty()) return kDefaultCrownRadius;
    std::nth_element(radii.begin(), radii.begin() + std::ptrdiff_t(radii.size() / 2), radii.end());
    return float(radii[radii.size() / 2]);
}

} // namespace sylva::ui
