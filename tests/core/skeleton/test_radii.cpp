// skel::shapeRadii, the final radius pass of every generator (issue #44: one continuous tree).

#include <gtest/gtest.h>

#include "engine/skeleton/radii.h"
#include "engine/util/error.h"

using namespace sylva;

namespace {

const glm::quat kUp(1, 0, 0, 0);

// A vertical chain of \p n segments of \p step metres, every node of radius \p r.
skel::Skeleton column(int n, float step, float r) {
    skel::Skeleton s;
    s.addNode(glm::vec3(0.0f), -1, r, 0, kUp);
    for (int i = 1; i <= n; ++i)
        s.addNode(glm::vec3(0, step * static_cast<float>(i), 0), i - 1, r, 0, kUp);
    s.finalize();
    return s;
}

} // namespace

TEST(ShapeRadii, AClearTrunkTapers) {
    // The pipe model leaves a stretch without branches a cylinder.
    skel::Skeleton s = column(10, 0.5f, 0.1f);
    skel::shapeRadii(s, {0.1f, 0.08f});
    EXPECT_FLOAT_EQ(s.radius[10], 0.1f); // the tip keeps its radius
    for (std::size_t i = 0; i < 10; ++i)
        EXPECT_NEAR(s.radius[i], s.radius[i + 1] * 1.05f, 1e-6f) << i;
    // Radius 1 m below the top over radius at the top: 1 / 1.05² < 0.92.
    EXPECT_LT(s.radius[10] / s.radius[8], 0.92f);
}

TEST(ShapeRadii, NoChildThickerThanItsParent) {
    // A Scots pine's tier: a branch set wider than the leader it leaves.
    skel::Skeleton s = column(2, 1.0f, 0.05f);
    const auto b = s.addNode(glm::vec3(0.7f, 1.7f, 0), 1, 0.075f, 1, kUp);
    s.addNode(glm::vec3(1.4f, 2.4f, 0), b, 0.07f, 1, kUp);
    s.finalize();
    skel::shapeRadii(s, {0.0f, 0.0f});
    for (std::size_t i = 1; i < s.size(); ++i)
        EXPECT_LE(s.radius[i], s.radius[static_cast<std::size_t>(s.parent[i])]) << i;
    EXPECT_FLOAT_EQ(s.radius[3], 0.05f);
    EXPECT_FLOAT_EQ(s.radius[4], 0.05f);
}

TEST(ShapeRadii, AnAxisEndingAtAForkGoesOnInItsThickestChild) {
    // A trunk that ends where three limbs leave it (all a bracket deeper, as a grammar writes
    // them): the thickest goes on as the trunk, with its own axis.
    skel::Skeleton s = column(1, 2.0f, 0.3f);
    const auto a = s.addNode(glm::vec3(-0.5f, 2.8f, 0), 1, 0.12f, 1, kUp);
    const auto b = s.addNode(glm::vec3(0.1f, 3.0f, 0), 1, 0.16f, 1, kUp);
    const auto c = s.addNode(glm::vec3(0.5f, 2.8f, 0), 1, 0.12f, 1, kUp);
    const auto bb = s.addNode(glm::vec3(0.2f, 4.0f, 0), b, 0.1f, 1, kUp);
    const auto bl = s.addNode(glm::vec3(0.8f, 3.6f, 0), b, 0.05f, 2, kUp);
    s.finalize();
    skel::shapeRadii(s, {0.0f, 0.0f});
    EXPECT_EQ(s.order[static_cast<std::size_t>(b)], 0);
    EXPECT_EQ(s.order[static_cast<std::size_t>(bb)], 0);
    EXPECT_EQ(s.order[static_cast<std::size_t>(bl)], 1);
    EXPECT_EQ(s.order[static_cast<std::size_t>(a)], 1);
    EXPECT_EQ(s.order[static_cast<std::size_t>(c)], 1);
}

TEST(ShapeRadii, NoStepAboveAFork) {
    // A trunk of 0.2 whose continuation the pipe model makes 0.12 a segment of 0.2 m later:
    // the axis thins at most junctionSlope a metre.
    skel::Skeleton s = column(4, 0.2f, 0.12f);
    s.radius[0] = s.radius[1] = 0.2f;
    s.addNode(glm::vec3(0.3f, 0.4f, 0), 1, 0.15f, 1, kUp);
    s.finalize();
    skel::shapeRadii(s, {0.0f, 0.1f});
    EXPECT_NEAR(s.radius[2], 0.2f - 0.1f * 0.2f, 1e-6f);
    EXPECT_NEAR(s.radius[3], 0.2f - 0.1f * 0.4f, 1e-6f);
    EXPECT_NEAR(s.radius[4], 0.2f - 0.1f * 0.6f, 1e-6f);
    EXPECT_FLOAT_EQ(s.radius[5], 0.15f); // the lateral keeps its own
    // Off, the pipe model's step stays.
    skel::Skeleton off = column(4, 0.2f, 0.12f);
    off.radius[0] = off.radius[1] = 0.2f;
    skel::shapeRadii(off, {0.0f, 0.0f});
    EXPECT_FLOAT_EQ(off.radius[2], 0.12f);
}

TEST(ShapeRadii, HiddenNodesAndRanges) {
    skel::Skeleton s = column(2, 1.0f, 0.1f);
    s.radius[2] = 0.5f;
    s.flags[2] |= skel::kHidden;
    skel::shapeRadii(s);
    EXPECT_FLOAT_EQ(s.radius[2], 0.5f); // kept for a later restore
    EXPECT_FLOAT_EQ(s.radius[1], 0.1f); // and fed nothing
    EXPECT_THROW(skel::shapeRadii(s, {1.5f, 0.08f}), InvalidInput);
    EXPECT_THROW(skel::shapeRadii(s, {0.1f, -1.0f}), InvalidInput);
}
