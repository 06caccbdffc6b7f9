#include <gtest/gtest.h>

#include <cstdint>
#include <numeric>
#include <vector>

#include <glm/gtc/quaternion.hpp>

#include "engine/mesh/cardfit.h"
#include "engine/util/random.h"

using namespace sylva;

namespace {

std::vector<skel::Leaf> randomLeaves(Rng& rng, int count) {
    std::vector<skel::Leaf> leaves(static_cast<std::size_t>(count));
    for (skel::Leaf& leaf : leaves) {
        leaf.position = glm::vec3(rng.uniformf(-3, 3), rng.uniformf(2, 9), rng.uniformf(-3, 3));
        leaf.orientation = glm::normalize(glm::quat(rng.uniformf(-1, 1), rng.uniformf(-1, 1),
                                                    rng.uniformf(-1, 1), rng.uniformf(-1, 1)));
        leaf.size = rng.uniformf(0.03f, 0.2f);
    }
    return leaves;
}

} // namespace

// A card's corners, mean and covariance are the leaves' corners as appendLeafCards makes them
// (four a leaf, in order), and the SSE2 extent is the straightforward one bit for bit, for
// groups of every size and every direction.
TEST(CardFit, ExtentMatchesTheStraightforwardOne) {
    Rng rng(12);
    const std::vector<skel::Leaf> leaves = randomLeaves(rng, 400);
    mesh::CardFitInput in;
    for (std::uint32_t first = 0, size = 1; first + size <= leaves.size(); first += size++) {
        std::vector<std::uint32_t> group(size);
        std::iota(group.begin(), group.end(), first);
        mesh::prepareCardFit(leaves, group, 0.5f, 1.3f, in);
        ASSERT_EQ(in.corners.size(), 4 * group.size());
        glm::dvec3 sum(0.0);
        for (std::size_t k = 0; k < group.size(); ++k) {
            glm::vec3 c[4];
            mesh::leafCorners(leaves[group[k]], 0.5f, 1.3f, c);
            for (int j = 0; j < 4; ++j) {
                EXPECT_EQ(in.corners[4 * k + j], c[j]);
                sum += glm::dvec3(c[j]);
            }
        }
        EXPECT_EQ(in.m, sum / static_cast<double>(in.corners.size()));
        EXPECT_EQ(in.cov, glm::transpose(in.cov));
        for (int trial = 0; trial < 4; ++trial) {
            const glm::dvec3 along = glm::normalize(
                glm::dvec3(rng.uniform(-1, 1), rng.uniform(-1, 1), rng.uniform(-1, 1)));
            const glm::dvec3 across = glm::normalize(glm::cross(along, glm::dvec3(0.2, 1, 0.3)));
            double f[4], p[4];
            mesh::cardExtent(in, along, across, f[0], f[1], f[2], f[3]);
            mesh::cardExtentPlain(in, along, across, p[0], p[1], p[2], p[3]);
            for (int j = 0; j < 4; ++j)
                EXPECT_EQ(f[j], p[j]) << size << " " << j;
            EXPECT_LE(f[0], f[1]);
            EXPECT_LE(f[2], f[3]);
        }
    }
}
