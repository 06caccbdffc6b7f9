#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include <glm/glm.hpp>
#include <glm/gtc/quaternion.hpp>

#include "engine/mesh/mesh.h"
#include "engine/skeleton/skeleton.h"
#include "engine/wind/windelements.h"
#include "engine/wind/windmodel.h"

namespace sylva::wind {

/// How a tree's low-bone rig and its clip are made.
struct RigSettings {
    int maxBones = 64; ///< 2 .. 1024; at least two per trunk
    float fps = 30.0f; ///< clip frames per second, 1 .. 240 (the clip lasts WindSettings::period)
};
void validate(const RigSettings& settings);

/// A joint samples the wind model at one point of a sway element.
struct RigJoint {
    std::string name;
    std::int32_t parent = -1; ///< joint index, parents first; -1 for a trunk's base
    std::int32_t element = -1;
    float u = 0.0f;       ///< bend fraction on the element
    glm::vec3 rest{0.0f}; ///< bind position (mesh frame); the bind pose has no rotation
};

/// Low-bone rig of one tree: a chain along each trunk (joints at u = k/n, k = 0..n) and, as the
/// budget allows, two joints (u = ½, 1) on the largest main limbs and one (u = 1) on the largest
/// level-2 branches. An element without joints moves with its parent's joints where it hangs.
struct Rig {
    std::vector<RigJoint> joints;
    /// Per element: first joint and count (0: not rigged).
    std::vector<std::int32_t> elementFirstJoint;
    std::vector<std::int32_t> elementJointCount;
};

/// \throw LimitExceeded when the budget is below two joints per trunk; InvalidInput for
/// settings out of range.
Rig buildRig(const WindElements& elements, const skel::Skeleton& skeleton,
             const RigSettings& settings);

/// Skin weights, ≤ 4 influences per vertex, each vertex's weights summing to 1 (unused slots:
/// joint 0, weight 0; influences sorted by weight, largest first).
struct SkinWeights {
    std::vector<glm::u16vec4> joints;
    std::vector<glm::vec4> weights;
};

/// Weights of every vertex of \p mesh (which needs Mesh::node): a vertex is blended between the
/// joints on either side of its node's fraction on the nearest rigged element of its ancestry,
/// the same for every vertex of a node, so a ring at a fork moves with its parent and a leaf
/// with its twig. Vertices without a node follow the first trunk's base.
SkinWeights skinWeights(const Rig& rig, const WindElements& elements, const mesh::Mesh& mesh);

/// The joints and weights (summing to 1, unsorted, at most 4) that carry a point at fraction
/// \p u of \p element: what skinWeights gives that point's vertices.
std::vector<std::pair<std::int32_t, float>>
jointWeights(const Rig& rig, const WindElements& elements, std::int32_t element, float u);

/// Rigid transform x ↦ rotation·x + translation.
struct RigidPose {
    glm::quat rotation{1, 0, 0, 0};
    glm::vec3 translation{0.0f};
};

/// The model's rigid motion of a point at fraction \p u on \p element at \p frame (the element's
/// bend composed with its ancestors'; leaf flutter and the ground clamp are left out).
RigidPose elementPose(const WindElements& elements, std::int32_t element, float u,
                      const WindFrame& frame);

/// A looping clip: per frame and joint the joint's local transform (relative to its parent
/// joint, or to the tree for a base). frames = round(period · fps) + 1; the last frame is the
/// first one again, exactly.
struct WindClip {
    std::vector<float> times; ///< seconds, 0 .. period
    std::size_t jointCount = 0;
    std::vector<glm::vec3> translation; ///< [frame · jointCount + joint]
    std::vector<glm::quat> rotation;    ///< [frame · jointCount + joint], w ≥ 0
    std::size_t frameCount() const { return times.size(); }
};

WindClip bakeClip(const Rig& rig, const WindElements& elements, const WindSettings& wind,
                  const RigSettings& settings);

} // namespace sylva::wind
