#pragma once

#include <array>
#include <cstddef>
#include <vector>

#include <glm/glm.hpp>

#include "ui/generation/treelodsource.h"
#include "ui/viewport/picking.h"

namespace sylva::ui {

/// A tree to draw in a frame: its index among the view's trees, its distance from the eye and
/// its level of detail (ui/viewport/viewlod.h; ViewLod::kImpostorLevel: the baked impostor).
struct TreeDraw {
    std::size_t index = 0;
    float distance = 0.0f;
    int level = 0;
    /// An instance of a variant below the impostor level: the index of the variant's level it
    /// draws (ViewVariant::levels); -1 otherwise.
    int variantLevel = -1;
    /// The variant level is coarser than at rest because the view moves (variantFactor).
    bool motion = false;
};

/// A tree that is an instance of a variant (TreeLodSource::instance): the variant and the
/// instance's scale (its transform's), so that its level follows its size on screen.
struct InstanceOf {
    const ViewVariant* variant = nullptr;
    float scale = 1.0f;
};

/// The level of \p variant an instance at scale \p scale drawn \p distance metres from the eye
/// needs: the variant's levels keep the silhouette from their distance on at the variant's
/// reference view, so the camera's distance is turned into the reference view's for the same
/// size on screen (\p fovY radians, \p viewportHeightPx device pixels) and multiplied by
/// \p factor (> 1: coarser, while the view moves).
std::size_t variantLevelFor(const ViewVariant& variant, double distance, double scale, double fovY,
                            double viewportHeightPx, double factor = 1.0);

/// The view a draw list is made for.
struct DrawListView {
    glm::mat4 viewProj{1.0f};
    glm::vec3 eye{0.0f};
    float fovY = 0.8f;             ///< vertical field of view, radians
    double viewportHeightPx = 1.0; ///< device pixels
    /// Every tree's level, the impostor's switch and the instances' variant levels as if the
    /// viewport were this many times smaller (Viewport::kMotionLodBias while the view moves
    /// under a software renderer, 1 at rest).
    double motionBias = 1.0;
    /// A tree higher than this on the target (device pixels, before motionBias; 0: no limit)
    /// is never an impostor but the coarsest mesh: Viewport::kMaxMovingImpostorPx while the
    /// view moves, so that no atlas cell is magnified into blocks (at rest the switch size
    /// keeps it so), and the rest switch's height with View ▸ Wind on (impostors do not sway).
    double maxImpostorPx = 0.0;
    bool levels = true; ///< false: every tree at level 0 (the distance LOD is off)
    /// Instances pick their variant's level this much farther (ViewLod::kMotionFactor while
    /// the view moves under a software renderer, 1 at rest).
    double variantFactor = 1.0;
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
/// box (past the end of \p bounds) is drawn at full detail. Trees that \p instances (in the
/// same order, may be shorter) names an instance of a variant get their variant level below
/// the impostor (variantLevelFor). Pure: no OpenGL.
/// \p impostorPx (in the same order, may be shorter; <= 0: the default switch) holds, per tree,
/// the height on screen under which its impostor matches it (Impostors::switchHeightPx()):
/// a tree higher than that is drawn as its coarsest mesh instead.
std::vector<TreeDraw> buildDrawList(const DrawListView& view, const std::vector<bool>& drawn,
                                    const std::vector<Bounds>& bounds,
                                    const std::vector<InstanceOf>& instances = {},
                                    const std::vector<double>& impostorPx = {});

} // namespace sylva::ui
