#include "ui/viewport/drawlist.h"

#include <algorithm>
#include <cmath>

#include "ui/viewport/viewlod.h"

namespace sylva::ui {

std::array<glm::vec4, 6> frustumPlanes(const glm::mat4& viewProj) {
    std::array<glm::vec4, 6> planes;
    const glm::mat4 m = glm::transpose(viewProj);
    for (int k = 0; k < 3; ++k) {
        planes[std::size_t(2 * k)] = m[3] + m[k];
        planes[std::size_t(2 * k + 1)] = m[3] - m[k];
    }
    return planes;
}

bool intersectsFrustum(const std::array<glm::vec4, 6>& planes, const Bounds& b) {
    if (b.empty()) return false;
    for (const glm::vec4& p : planes) {
        // The box's corner farthest along the plane's normal.
        const glm::vec3 far(p.x >= 0 ? b.hi.x : b.lo.x, p.y >= 0 ? b.hi.y : b.lo.y,
                            p.z >= 0 ? b.hi.z : b.lo.z);
        if (glm::dot(glm::vec3(p), far) + p.w < 0.0f) return false;
    }
    return true;
}

std::size_t variantLevelFor(const ViewVariant& variant, double distance, double scale, double fovY,
                            double viewportHeightPx, double factor) {
    if (variant.levels.size() <= 1 || viewportHeightPx <= 0.0 || scale <= 1e-6) return 0;
    const double refFov = variant.referenceFovYDegrees * 3.14159265358979323846 / 180.0;
    // The same projected height at the reference view: d' = d · (ref / viewport) ·
    // tan(fov/2) / tan(ref/2), in the variant's own frame (scale 1).
    const double d = distance / scale * (variant.referenceHeightPx / viewportHeightPx) *
                     (std::tan(0.5 * fovY) / std::tan(0.5 * refFov)) * factor;
    return mesh::levelFor(variant.levels, d);
}

std::vector<TreeDraw> buildDrawList(const DrawListView& view, const std::vector<bool>& drawn,
                                    const std::vector<Bounds>& bounds,
                                    const std::vector<InstanceOf>& instances,
                                    const std::vector<double>& impostorPx) {
    // Frustum culling: a tree whose world box lies outside one of the six planes is not drawn
    // (a forest seen from inside draws only what is in front of the camera).
    const std::array<glm::vec4, 6> planes = frustumPlanes(view.viewProj);
    const double heightPx = view.viewportHeightPx / std::max(view.motionBias, 1e-6);
    std::vector<TreeDraw> order;
    order.reserve(drawn.size());
    for (std::size_t i = 0; i < drawn.size(); ++i) {
        if (!drawn[i]) continue;
        TreeDraw d;
        d.index = i;
        if (i < bounds.size()) {
            const Bounds& b = bounds[i];
            if (!intersectsFrustum(planes, b)) continue;
            d.distance = glm::length(0.5f * (b.lo + b.hi) - view.eye);
            // The level of detail follows the tree's height on screen (ui/viewport/viewlod.h).
            if (view.levels) {
                const double worldHeight = double(b.hi.y - b.lo.y);
                d.level = ViewLod::levelFor(ViewLod::equivalentHeights(
                    double(d.distance), worldHeight, double(view.fovY), heightPx));
                if (d.level == ViewLod::kImpostorLevel && view.maxImpostorPx > 0.0 &&
                    ViewLod::heightOnScreenPx(double(d.distance), worldHeight, double(view.fovY),
                                              view.viewportHeightPx) > view.maxImpostorPx)
                    d.level = ViewLod::kImpostorLevel - 1;
                // Its impostor matches it only from a smaller size on (issue 40).
                if (d.level == ViewLod::kImpostorLevel && i < impostorPx.size() &&
                    impostorPx[i] > 0.0 &&
                    ViewLod::heightOnScreenPx(double(d.distance), worldHeight, double(view.fovY),
                                              heightPx) > impostorPx[i])
                    d.level = ViewLod::kImpostorLevel - 1;
            }
            if (i < instances.size() && instances[i].variant &&
                d.level != ViewLod::kImpostorLevel) {
                const InstanceOf& of = instances[i];
                const auto levelAt = [&](double factor) {
                    return int(variantLevelFor(*of.variant, double(d.distance), double(of.scale),
                                               double(view.fovY), heightPx, factor));
                };
                d.variantLevel = levelAt(view.levels ? view.variantFactor : 0.0);
                d.motion = view.levels && view.variantFactor > 1.0 && d.variantLevel > levelAt(1.0);
            }
        }
        order.push_back(d);
    }
    std::sort(order.begin(), order.end(), [](const TreeDraw& a, const TreeDraw& b) {
        return a.distance < b.distance || (a.distance == b.distance && a.index < b.index);
    });
    return order;
}

} // namespace sylva::ui
