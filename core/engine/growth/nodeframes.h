#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include <glm/glm.hpp>
#include <glm/gtc/quaternion.hpp>

namespace sylva::growth {

/// The frame of a node grown from a node with frame \p parent in direction \p dir (unit): the
/// parent's frame turned by the shortest rotation from its heading onto \p dir, normalised
/// (glm::normalize(glm::rotation(headingOf(parent), dir) * parent)).
glm::quat transportFrame(const glm::quat& parent, const glm::vec3& dir);

/// out[k] = transportFrame(frames[nodes[k]], dirs[k]) for every k, bit for bit: sixteen at a
/// time where the processor has AVX-512 (each lane glm's float operations in order, none fused;
/// a lane whose direction is (nearly) opposite its heading, or whose product has no length,
/// takes transportFrame), one at a time elsewhere or with SYLVA_NO_AVX512 / SYLVA_NO_AVX set.
void transportFrames(std::span<const glm::quat> frames, std::span<const std::uint32_t> nodes,
                     std::span<const glm::vec3> dirs, std::vector<glm::quat>& out);

/// Whether transportFrames takes its sixteen-lane path here.
bool transportFramesAvx512();

} // namespace sylva::growth
