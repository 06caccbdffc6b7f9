#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "engine/mesh/leafplacement.h"
#include "engine/util/error.h"

using namespace sylva;

namespace {

// A straight, thin vertical branch of \p segments one-metre segments.
skel::Skeleton twig(int segments, float radius = 0.01f) {
    skel::Skeleton s;
    s.addNode({0, 0, 0}, -1, radius, 0, glm::quat(1, 0, 0, 0));
    for (int i = 1; i <= segments; ++i)
        s.addNode({0, static_cast<float>(i), 0}, i - 1, radius, 0, glm::quat(1, 0, 0, 0));
    s.finalize();
    return s;
}

double azimuth(const skel::Leaf& l) {
    return std::atan2(l.position.x, l.position.z);
}

double angleDiff(double a, double b) {
    double d = std::fmod(a - b, 2.0 * std::numbers::pi);
    if (d < 0) d += 2.0 * std::numbers::pi;
    return d * 180.0 / std::numbers::pi;
}

mesh::LeafPlacement branchesOnly(mesh::Phyllotaxis ph) {
    mesh::LeafPlacement p;
    p.atTips = false;
    p.density = 10.0;
    p.phyllotaxis = ph;
    return p;
}

} // namespace

TEST(LeafPlacement, SpiralUsesTheGoldenAngle) {
    const auto leaves = mesh::placeLeaves(twig(2), branchesOnly(mesh::Phyllotaxis::Spiral));
    ASSERT_EQ(leaves.size(), 20u); // floor(10 * 1 + u) with u in [0, 1) per segment
    for (std::size_t i = 1; i < leaves.size(); ++i) {
        EXPECT_NEAR(angleDiff(azimuth(leaves[i]), azimuth(leaves[i - 1])), 137.5, 1e-3);
        EXPECT_GT(leaves[i].position.y, leaves[i - 1].position.y);
        EXPECT_NEAR(glm::length(glm::vec2(leaves[i].position.x, leaves[i].position.z)), 0.01f,
                    1e-6f);
    }
}

TEST(LeafPlacement, OppositeAndWhorled) {
    const auto opp = mesh::placeLeaves(twig(1), branchesOnly(mesh::Phyllotaxis::Opposite));
    ASSERT_EQ(opp.size(), 20u);
    EXPECT_NEAR(angleDiff(azimuth(opp[1]), azimuth(opp[0])), 180.0, 1e-3);
    EXPECT_NEAR(angleDiff(azimuth(opp[2]), azimuth(opp[0])), 90.0, 1e-3);
    auto p = branchesOnly(mesh::Phyllotaxis::Whorled);
    p.whorlCount = 4;
    const auto wh = mesh::placeLeaves(twig(1), p);
    ASSERT_EQ(wh.size(), 40u);
    EXPECT_NEAR(angleDiff(azimuth(wh[1]), azimuth(wh[0])), 90.0, 1e-3);
    EXPECT_NEAR(angleDiff(azimuth(wh[4]), azimuth(wh[0])), 45.0, 1e-3);
    const auto alt = mesh::placeLeaves(twig(1), branchesOnly(mesh::Phyllotaxis::Alternate));
    EXPECT_NEAR(angleDiff(azimuth(alt[1]), azimuth(alt[0])), 180.0, 1e-3);
}

TEST(LeafPlacement, ThickBranchesCarryNoLeavesTipsDo) {
    mesh::LeafPlacement p;
    p.tipCount = 5;
    const auto leaves = mesh::placeLeaves(twig(3, 0.2f), p);
    ASSERT_EQ(leaves.size(), 5u);
    for (const auto& l : leaves) {
        EXPECT_EQ(l.node, 3);
        EXPECT_EQ(l.position, glm::vec3(0, 3, 0));
    }
}

TEST(LeafPlacement, FramesSizesAndDeterminism) {
    mesh::LeafPlacement p;
    p.size = 0.2;
    p.sizeVariation = 0.5;
    p.normalWeight = 0.0;
    p.lightWeight = 0.0;
    p.upWeight = 1.0;
    p.seed = 9;
    skel::Skeleton s = twig(3);
    // Bend the twig so headings are not vertical.
    s.position[2] = {1, 1.5f, 0};
    s.position[3] = {2, 1.8f, 0.5f};
    const auto a = mesh::placeLeaves(s, p);
    const auto b = mesh::placeLeaves(s, p);
    ASSERT_FALSE(a.empty());
    bool differentSizes = false;
    for (std::size_t i = 0; i < a.size(); ++i) {
        EXPECT_EQ(a[i].position, b[i].position);
        EXPECT_EQ(a[i].size, b[i].size);
        EXPECT_GE(a[i].size, 0.1f - 1e-6f);
        EXPECT_LE(a[i].size, 0.3f + 1e-6f);
        differentSizes |= a[i].size != a[0].size;
        const glm::vec3 h = skel::headingOf(a[i].orientation), u = skel::upOf(a[i].orientation);
        EXPECT_NEAR(glm::dot(h, u), 0.0f, 1e-5f);
        EXPECT_GT(u.y, 0.0f); // facing up as asked
    }
    EXPECT_TRUE(differentSizes);
    p.seed = 10;
    const auto c = mesh::placeLeaves(s, p);
    bool changed = c.size() != a.size();
    for (std::size_t i = 0; !changed && i < a.size(); ++i)
        changed = a[i].size != c[i].size;
    EXPECT_TRUE(changed);
}

TEST(LeafPlacement, RangesAreChecked) {
    mesh::LeafPlacement p;
    p.whorlCount = 1;
    EXPECT_THROW(mesh::placeLeaves(twig(1), p), InvalidInput);
    p = {};
    p.sizeVariation = 2.0;
    EXPECT_THROW(mesh::placeLeaves(twig(1), p), InvalidInput);
}
