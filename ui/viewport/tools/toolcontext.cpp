#include "ui/viewport/tools/toolcontext.h"

#include <algorithm>

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
    return hitPlane(ray, 0.0f);
}

float ToolContext::groundHeight(float x, float z) const {
    const auto& ground = result().ground;
    if (!ground || ground->empty()) return 0.0f;
    const env::SegmentHit h =
        ground->intersect({{x, ground->hi().y + 1.0f, z}, {x, ground->lo().y - 1.0f, z}});
    return h.hit ? h.point.y : 0.0f;
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
