#pragma once

#include <array>
#include <cstddef>
#include <vector>

#include <glm/glm.hpp>

#include "ui/viewport/picking.h"

namespace sylva::ui {

/// A tree to draw in a frame: its index among the view's trees, its distance from the eye and
/// its level of detail (ui/viewport/viewlod.h; ViewLod::kImpostorLevel: the baked impostor).
struct TreeDraw {
    std::size_t index = 0;
    float distance = 0.0f;
    int level = 0;
};

/// The view a draw list is made for.
struct DrawListView {
    glm::mat4 viewProj{1.0f};
    glm::vec3 eye{0.0f};
    float fovY = 0.8f;             ///< vertical field of view, radians
    double viewportHeightPx = 1.0; ///< device pixels
    bool levels = true;            ///< false: every tree at level 0 (the distance LOD is off)
};

/// The six planes of the frustum of \p viewProj (left, right, bottom, top, near, far), each
/// (n, d) with n·p + d >= 0 inside.
std::array<glm::vec4, 6> frustumPlanes(const glm::mat4& viewProj);
/// Whether \p box is not entirely outside one of \p planes (false for an empty box).
bool intersectsFrustum(const std::array<glm::vec4, 6>& planes, const Bounds& box);

/// What a frame draws, nearest first (so that the depth test spares the rasteriser what is
/// hidden behind): each tree that \p drawn allows (one entry per tree: false for a tree
/// without a mesh or hidden) and whose world box (\p bounds, in the same order)
/// meets the frustum, at the level of detail its height on screen asks for. A tree with no
/// box (past the end of \p bounds) is drawn at full detail. Pure: no OpenGL.
std::vector<TreeDraw> buildDrawList(const DrawListView& view, const std::vector<bool>& drawn,
                                    const std::vector<Bounds>& bounds);

} // namespace sylva::ui
