// transportFrames: the new nodes' frames, sixteen at a time where the processor has AVX-512,
// against glm's expression node by node, bit for bit.
#include <gtest/gtest.h>

#include <cstdint>
#include <cstring>
#include <vector>

#include <glm/gtx/quaternion.hpp>

#include "engine/growth/nodeframes.h"
#include "engine/skeleton/skeleton.h"
#include "engine/util/random.h"

using namespace sylva;
using namespace sylva::growth;

namespace {

glm::quat straightforward(const glm::quat& parent, const glm::vec3& dir) {
    return glm::normalize(glm::rotation(skel::headingOf(parent), dir) * parent);
}

glm::vec3 unit(Rng& rng) {
    for (;;) {
        const glm::vec3 v(rng.uniformf(-1, 1), rng.uniformf(-1, 1), rng.uniformf(-1, 1));
        const float l = glm::length(v);
        if (l > 0.1f && l <= 1.0f) return v / l;
    }
}

} // namespace

TEST(NodeFrames, SameBitsAsGlmNodeByNode) {
    Rng rng(41);
    int special = 0, compared = 0;
    for (int trial = 0; trial < 400; ++trial) {
        // Frames: random unit quaternions, some slightly off unit length (as normalised floats
        // are), the identity and its negation.
        const std::size_t frameCount = 1 + rng.below(60);
        std::vector<glm::quat> frames(frameCount);
        for (glm::quat& q : frames) {
            const std::uint64_t kind = rng.below(10);
            if (kind == 0) {
                q = glm::quat(1, 0, 0, 0);
            } else if (kind == 1) {
                q = glm::quat(-1, 0, 0, 0);
            } else {
                q = glm::normalize(glm::quat(rng.uniformf(-1, 1), rng.uniformf(-1, 1),
                                             rng.uniformf(-1, 1), rng.uniformf(-1, 1)));
                if (kind == 2) q = q * 1.0001f;
            }
        }
        // 1-70 nodes (sixteen-lane blocks and every tail), directions: random, the heading
        // itself (the identity rotation), its opposite (the scalar lanes), nearly either.
        const std::size_t n = 1 + rng.below(70);
        std::vector<std::uint32_t> nodes(n);
        std::vector<glm::vec3> dirs(n);
        for (std::size_t k = 0; k < n; ++k) {
            nodes[k] = static_cast<std::uint32_t>(rng.below(frameCount));
            const glm::vec3 h = skel::headingOf(frames[nodes[k]]);
            const std::uint64_t kind = rng.below(8);
            if (kind == 0) {
                dirs[k] = h;
            } else if (kind == 1) {
                dirs[k] = -h;
            } else if (kind == 2) {
                dirs[k] = glm::normalize(h + 1e-4f * unit(rng));
            } else if (kind == 3) {
                dirs[k] = glm::normalize(-h + 1e-4f * unit(rng));
            } else {
                dirs[k] = unit(rng);
            }
            const float c = glm::dot(h, dirs[k]);
            special += c >= 1.0f - 1.2e-7f || c < -1.0f + 1.2e-7f ? 1 : 0;
        }
        std::vector<glm::quat> got;
        transportFrames(frames, nodes, dirs, got);
        ASSERT_EQ(got.size(), n);
        for (std::size_t k = 0; k < n; ++k) {
            const glm::quat want = straightforward(frames[nodes[k]], dirs[k]);
            ASSERT_EQ(std::memcmp(&got[k], &want, sizeof want), 0)
                << "trial " << trial << " node " << k << " of " << n << ": (" << got[k].w << ", "
                << got[k].x << ", " << got[k].y << ", " << got[k].z << ") vs (" << want.w << ", "
                << want.x << ", " << want.y << ", " << want.z << ")";
            ++compared;
        }
    }
    EXPECT_GT(compared, 10000);
    EXPECT_GT(special, 1000); // the identity and opposite lanes were met
}
