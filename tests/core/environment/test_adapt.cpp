#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include <glm/gtc/constants.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <omp.h>

#include "engine/environment/adapt.h"
#include "engine/mesh/tubemesh.h"
#include "engine/util/error.h"

using namespace sylva;
using namespace sylva::env;

namespace {

/// Appends \p count segments of \p step from node \p from; returns the last node.
std::int32_t addBranch(skel::Skeleton& s, std::int32_t from, const glm::vec3& step, int count,
                       std::uint16_t order, float radius = 0.05f) {
    std::int32_t last = from;
    for (int i = 0; i < count; ++i) {
        const glm::vec3 p = s.position[static_cast<std::size_t>(last)] + step;
        last = s.addNode(p, last, radius, order, glm::quat(1, 0, 0, 0));
    }
    return last;
}

/// A vertical trunk of \p segments half-metre segments from the origin; returns the skeleton.
skel::Skeleton trunk(int segments) {
    skel::Skeleton s;
    s.addNode(glm::vec3(0.0f), -1, 0.2f, 0, glm::quat(1, 0, 0, 0));
    addBranch(s, 0, glm::vec3(0, 0.5f, 0), segments, 0, 0.15f);
    return s;
}

const std::int32_t kTop = 12; // last trunk node of trunk(12)

ObstacleScene wallAt(float x0, float x1, float height = 3.0f,
                     CollisionBackend backend = CollisionBackend::Embree) {
    return ObstacleScene({makeBoxMesh(glm::vec3(x0, 0, -3), glm::vec3(x1, height, 3), "wall")},
                         backend);
}

double restLength(const skel::Skeleton& s) {
    double sum = 0.0;
    for (std::size_t i = 0; i < s.size(); ++i)
        if (s.parent[i] >= 0)
            sum += glm::length(
                glm::dvec3(s.position[i] - s.position[static_cast<std::size_t>(s.parent[i])]));
    return sum;
}

bool hidden(const skel::Skeleton& s, std::int32_t i) {
    return (s.flags[static_cast<std::size_t>(i)] & skel::kHidden) != 0;
}

void expectSameSkeleton(const skel::Skeleton& a, const skel::Skeleton& b) {
    ASSERT_EQ(a.size(), b.size());
    for (std::size_t i = 0; i < a.size(); ++i) {
        EXPECT_EQ(a.position[i], b.position[i]) << i;
        EXPECT_EQ(a.flags[i], b.flags[i]) << i;
        EXPECT_EQ(a.orientation[i], b.orientation[i]) << i;
    }
    ASSERT_EQ(a.leaves.size(), b.leaves.size());
    for (std::size_t i = 0; i < a.leaves.size(); ++i)
        EXPECT_EQ(a.leaves[i].position, b.leaves[i].position);
}

AdaptParams noRedistribution() {
    AdaptParams p;
    p.redistribute = false;
    return p;
}

} // namespace

TEST(SegmentHitsCrown, HandComputedCases) {
    const CrownVolume c{glm::vec3(0, 0, 0), 1.0f, 2.0f, 6.0f};
    glm::vec3 p;
    ASSERT_TRUE(segmentHitsCrown({{-3, 4, 0}, {3, 4, 0}}, c, &p));
    EXPECT_NEAR(p.x, -1.0f, 1e-6f);
    EXPECT_FALSE(segmentHitsCrown({{-3, 1, 0}, {3, 1, 0}}, c));          // below the crown
    EXPECT_FALSE(segmentHitsCrown({{-3, 4, 1.5f}, {3, 4, 1.5f}}, c));    // beside it
    EXPECT_TRUE(segmentHitsCrown({{0.1f, 3, 0}, {0.2f, 3.5f, 0}}, c));   // wholly inside
    ASSERT_TRUE(segmentHitsCrown({{0.5f, 0, 0}, {0.5f, 10, 0}}, c, &p)); // up through the bottom
    EXPECT_NEAR(p.y, 2.0f, 1e-5f);
}

TEST(Adapt, FarFromObstaclesTheTreeIsUnchanged) {
    skel::Skeleton s = trunk(12);
    addBranch(s, 4, glm::vec3(0.2f, 0.1f, 0), 5, 1);
    const ObstacleScene scene = wallAt(5.0f, 5.2f);
    const AdaptResult r = adaptTree(s, scene, glm::mat4(1.0f), AdaptParams{});
    expectSameSkeleton(r.skeleton, s);
    EXPECT_EQ(r.stats.collidingBefore, 0u);
    EXPECT_FALSE(r.stats.bent);
    EXPECT_NEAR(r.stats.totalLengthBefore, restLength(s), 1e-5);
}

TEST(Adapt, TreeNextToAWallBendsAwayFromIt) {
    skel::Skeleton s = trunk(12);
    // A branch whose tip just enters a wall standing at x = 1.
    const std::int32_t tip = addBranch(s, 4, glm::vec3(0.22f, 0.1f, 0), 5, 1);
    const ObstacleScene scene = wallAt(1.0f, 1.2f);
    const AdaptResult r = adaptTree(s, scene, glm::mat4(1.0f), AdaptParams{});
    EXPECT_GE(r.stats.collidingBefore, 1u);
    EXPECT_TRUE(r.stats.bent);
    EXPECT_EQ(r.stats.hiddenNodes, 0u);
    EXPECT_EQ(r.stats.collidingAfter, 0u);
    // Away from the wall: toward -x, the tip pulled out of it, nothing moved sideways in z.
    EXPECT_LT(r.skeleton.position[kTop].x, -0.2f);
    EXPECT_LT(r.skeleton.position[static_cast<std::size_t>(tip)].x, 1.0f);
    for (const glm::vec3& p : r.skeleton.position)
        EXPECT_NEAR(p.z, 0.0f, 1e-5f);
    // The root stays; segment lengths are kept (bending is a rotation).
    EXPECT_EQ(r.skeleton.position[0], s.position[0]);
    EXPECT_NEAR(visibleLength(r.skeleton), restLength(s), 1e-4);
    // Both backends agree.
    const ObstacleScene brute = wallAt(1.0f, 1.2f, 3.0f, CollisionBackend::BruteForce);
    const AdaptResult b = adaptTree(s, brute, glm::mat4(1.0f), AdaptParams{});
    ASSERT_EQ(b.skeleton.size(), r.skeleton.size());
    for (std::size_t i = 0; i < s.size(); ++i) {
        EXPECT_LT(glm::length(b.skeleton.position[i] - r.skeleton.position[i]), 1e-4f);
        EXPECT_EQ(b.skeleton.flags[i], r.skeleton.flags[i]);
    }
}

TEST(Adapt, BranchThroughAWallIsPrunedWithItsChildren) {
    skel::Skeleton s = trunk(12);
    // A long branch at 1 m right through the wall, with a side twig beyond the wall.
    const std::int32_t tip = addBranch(s, 2, glm::vec3(0.45f, 0.02f, 0), 7, 1);
    const std::int32_t twig = addBranch(s, tip - 1, glm::vec3(0, 0.05f, 0.3f), 3, 2);
    const ObstacleScene scene = wallAt(1.0f, 1.2f);
    const AdaptResult r = adaptTree(s, scene, glm::mat4(1.0f), noRedistribution());
    const skel::Skeleton& out = r.skeleton;
    ASSERT_EQ(out.size(), s.size()); // hidden, not removed
    EXPECT_GT(r.stats.hiddenNodes, 0u);
    for (std::int32_t i = 0; i <= kTop; ++i)
        EXPECT_FALSE(hidden(out, i)) << "trunk node " << i;
    EXPECT_TRUE(hidden(out, tip));
    EXPECT_TRUE(hidden(out, twig));
    // Oracle: a node is hidden exactly when its parent is hidden or its own segment (in the
    // final pose, which equals the bent pose without redistribution) still hits the wall.
    const ObstacleScene brute = wallAt(1.0f, 1.2f, 3.0f, CollisionBackend::BruteForce);
    double hiddenLength = 0.0;
    for (std::size_t i = 1; i < out.size(); ++i) {
        const auto p = static_cast<std::size_t>(out.parent[i]);
        const bool collides = brute.occluded({out.position[p], out.position[i]});
        const bool parentHidden = (out.flags[p] & skel::kHidden) != 0;
        EXPECT_EQ(hidden(out, static_cast<std::int32_t>(i)), collides || parentHidden) << i;
        if (hidden(out, static_cast<std::int32_t>(i)))
            hiddenLength += glm::length(s.position[i] - s.position[p]);
    }
    EXPECT_NEAR(r.stats.prunedLength, hiddenLength, 1e-5);
    EXPECT_EQ(r.stats.collidingAfter, 0u);
    EXPECT_EQ(r.stats.redistributedLength, 0.0);

    AdaptParams keep = noRedistribution();
    keep.prune = false;
    const AdaptResult k = adaptTree(s, scene, glm::mat4(1.0f), keep);
    EXPECT_EQ(k.stats.hiddenNodes, 0u);
    EXPECT_GT(k.stats.collidingAfter, 0u);
}

TEST(Adapt, RedistributionConservesTotalLength) {
    skel::Skeleton s = trunk(12);
    const std::int32_t tip = addBranch(s, 2, glm::vec3(0.45f, 0.02f, 0), 7, 1);
    addBranch(s, tip - 1, glm::vec3(0, 0.05f, 0.3f), 3, 2);
    addBranch(s, 8, glm::vec3(-0.3f, 0.2f, 0.1f), 4, 1);
    s.leaves.push_back(
        {s.position[kTop] + glm::vec3(0, 0.1f, 0), glm::quat(1, 0, 0, 0), 0.2f, kTop});
    s.leaves.push_back(
        {s.position[static_cast<std::size_t>(tip)], glm::quat(1, 0, 0, 0), 0.2f, tip});
    const ObstacleScene scene = wallAt(1.0f, 1.2f);
    const double total = restLength(s);
    for (glm::vec3 light : {glm::vec3(0, -1, 0), glm::vec3(0.3f, -1, 0.2f), glm::vec3(0.0f)}) {
        AdaptParams params;
        params.lightDirection = light;
        const AdaptResult r = adaptTree(s, scene, glm::mat4(1.0f), params);
        ASSERT_GT(r.stats.prunedLength, 0.5);
        EXPECT_NEAR(r.stats.redistributedLength, r.stats.prunedLength, 1e-6);
        EXPECT_NEAR(visibleLength(r.skeleton), total, 1e-4 * total);
        EXPECT_NEAR(r.stats.visibleLengthAfter, total, 1e-4 * total);
        // Every visible segment grew (or kept its length); nothing shrank.
        for (std::size_t i = 1; i < s.size(); ++i) {
            if (hidden(r.skeleton, static_cast<std::int32_t>(i))) continue;
            const auto p = static_cast<std::size_t>(s.parent[i]);
            EXPECT_GE(glm::length(r.skeleton.position[i] - r.skeleton.position[p]),
                      glm::length(s.position[i] - s.position[p]) - 1e-5f);
        }
        // The leaf on the pruned branch is gone, the other follows the trunk top.
        ASSERT_EQ(r.skeleton.leaves.size(), 1u);
        EXPECT_LT(glm::length(r.skeleton.leaves[0].position - r.skeleton.position[kTop]), 0.1001f);
    }
    // Toward the light: with light from straight above, the upward trunk gains more than the
    // horizontal branch per metre.
    AdaptParams params;
    const AdaptResult r = adaptTree(s, scene, glm::mat4(1.0f), params);
    const auto grow = [&](std::size_t i) {
        const auto p = static_cast<std::size_t>(s.parent[i]);
        return glm::length(r.skeleton.position[i] - r.skeleton.position[p]) -
               glm::length(s.position[i] - s.position[p]);
    };
    EXPECT_GT(grow(kTop), grow(static_cast<std::size_t>(tip) + 4));
}

TEST(Adapt, ReadaptingStartsFromTheRestPose) {
    skel::Skeleton s = trunk(12);
    addBranch(s, 2, glm::vec3(0.45f, 0.02f, 0), 7, 1);
    const ObstacleScene scene = wallAt(1.0f, 1.2f);
    const AdaptResult a = adaptTree(s, scene, glm::mat4(1.0f), AdaptParams{});
    const AdaptResult b = adaptTree(s, scene, glm::mat4(1.0f), AdaptParams{});
    expectSameSkeleton(a.skeleton, b.skeleton);
    // Stale hidden flags on the input are ignored: adaptation restarts from the rest pose.
    skel::Skeleton stale = s;
    for (std::uint8_t& f : stale.flags)
        f |= skel::kHidden;
    expectSameSkeleton(adaptTree(stale, scene, glm::mat4(1.0f), AdaptParams{}).skeleton,
                       a.skeleton);
    // Same answer on one and two threads.
    const int saved = omp_get_max_threads();
    omp_set_num_threads(1);
    const AdaptResult one = adaptTree(s, scene, glm::mat4(1.0f), AdaptParams{});
    omp_set_num_threads(2);
    const AdaptResult two = adaptTree(s, scene, glm::mat4(1.0f), AdaptParams{});
    omp_set_num_threads(saved);
    expectSameSkeleton(one.skeleton, two.skeleton);
}

TEST(Adapt, BendFollowsMaxBendAndMultiplierPerBranchLevel) {
    // One fork (node 6, a stub toward +z into a box): branch starts are the root's child
    // (level 0) and the fork's two children (level 1).
    skel::Skeleton s = trunk(12);
    const ObstacleScene scene({makeBoxMesh(glm::vec3(-3, 2.9f, 0.5f), glm::vec3(3, 3.1f, 0.7f))});
    const std::int32_t stub = addBranch(s, 6, glm::vec3(0, 0, 0.3f), 2, 1);
    AdaptParams p = noRedistribution();
    p.maxBend = 0.1f;
    p.bendMultiplier = 0.5f;
    p.returnToVertical = false;
    const AdaptResult r = adaptTree(s, scene, glm::mat4(1.0f), p);
    ASSERT_TRUE(r.stats.bent);
    // Trunk below the fork at node 6: lean = max_bend; above it: max_bend + max_bend·0.5.
    const auto angleOf = [&](std::size_t i) {
        const glm::vec3 d = glm::normalize(r.skeleton.position[i] - r.skeleton.position[i - 1]);
        return std::acos(std::clamp(d.y, -1.0f, 1.0f));
    };
    EXPECT_NEAR(angleOf(3), 0.1f, 1e-5f);
    EXPECT_NEAR(angleOf(10), 0.15f, 1e-5f);
    // Leaning away from +z (where the stub hit).
    EXPECT_LT(r.skeleton.position[kTop].z, 0.0f);
    // The stub starts at the same level as the trunk's continuation: it leans 0.15 too, i.e. its
    // horizontal direction (toward the box) swings up by 0.15 rad, as the crown leans to -z.
    EXPECT_NEAR(r.stats.leanRadians, 0.15, 1e-5);
    const glm::vec3 d = glm::normalize(r.skeleton.position[static_cast<std::size_t>(stub)] -
                                       r.skeleton.position[6]);
    EXPECT_NEAR(std::asin(d.y), 0.15f, 1e-5f);
}

TEST(Adapt, TrunkReturnsTowardVerticalAboveTheObstacle) {
    skel::Skeleton s = trunk(24); // 12 m, the wall is 3 m high
    addBranch(s, 3, glm::vec3(0.22f, 0.05f, 0), 5, 1);
    const ObstacleScene scene = wallAt(1.0f, 1.2f, 3.0f);
    const auto topAngle = [&](bool straighten) {
        AdaptParams p = noRedistribution();
        p.returnToVertical = straighten;
        const AdaptResult r = adaptTree(s, scene, glm::mat4(1.0f), p);
        EXPECT_TRUE(r.stats.bent);
        const glm::vec3 d = glm::normalize(r.skeleton.position[24] - r.skeleton.position[23]);
        return std::acos(std::clamp(d.y, -1.0f, 1.0f));
    };
    const float leaning = topAngle(false);
    const float straight = topAngle(true);
    EXPECT_GT(leaning, 0.15f);
    EXPECT_LT(straight, 1e-4f);
}

TEST(Adapt, RecheckAllCatchesBranchesPushedIntoObstaclesByBending) {
    skel::Skeleton s = trunk(12);
    addBranch(s, 4, glm::vec3(0.22f, 0.1f, 0), 5, 1); // tip just inside the wall at +x
    const std::int32_t b = addBranch(s, 6, glm::vec3(-0.25f, 0.0f, 0), 4, 1); // toward -x
    // A second box just beyond b's tip: free in the rest pose, hit once the tree leans to -x.
    const ObstacleScene scene(
        {makeBoxMesh(glm::vec3(1.0f, 0, -3), glm::vec3(1.2f, 3, 3)),
         makeBoxMesh(glm::vec3(-1.3f, 2.5f, -1), glm::vec3(-1.05f, 3.5f, 1))});
    AdaptParams p = noRedistribution();
    p.recheckAll = false;
    p.prune = false;
    // The reference re-checks only the first colliders: b, pushed in by the bend, is missed.
    const AdaptResult only = adaptTree(s, scene, glm::mat4(1.0f), p);
    EXPECT_FALSE(hidden(only.skeleton, b));
    EXPECT_GT(only.stats.collidingAfter, 0u);
    p.prune = true;
    // With pruning on, the final check of the whole pose catches b all the same.
    const AdaptResult caught = adaptTree(s, scene, glm::mat4(1.0f), p);
    EXPECT_TRUE(hidden(caught.skeleton, b));
    EXPECT_EQ(caught.stats.collidingAfter, 0u);
    p.recheckAll = true;
    const AdaptResult all = adaptTree(s, scene, glm::mat4(1.0f), p);
    EXPECT_TRUE(hidden(all.skeleton, b));
    EXPECT_GT(all.stats.collidingAfterBend, caught.stats.collidingAfterBend);
    EXPECT_EQ(all.stats.collidingAfter, 0u);
}

TEST(Adapt, GrowthNeverPushesABranchIntoAnObstacle) {
    // A branch through a wall is pruned; its length would make the trunk grow through a roof
    // that the rest pose clears by 0.3 m. The trunk's growth is withdrawn and the other branch
    // takes the whole length, so nothing collides and the length is still conserved.
    skel::Skeleton s = trunk(12);
    addBranch(s, 2, glm::vec3(0.45f, 0.02f, 0), 7, 1);                           // into the wall
    const std::int32_t side = addBranch(s, 6, glm::vec3(-0.25f, 0.0f, 0), 4, 1); // free
    for (CollisionBackend backend : {CollisionBackend::Embree, CollisionBackend::BruteForce}) {
        const ObstacleScene scene(
            {makeBoxMesh(glm::vec3(1.0f, 0, -3), glm::vec3(1.2f, 3, 3), "wall"),
             makeBoxMesh(glm::vec3(-0.5f, 6.3f, -0.5f), glm::vec3(0.5f, 7.0f, 0.5f), "roof")},
            backend);
        AdaptParams p;
        p.maxBend = 0.0f; // prune and grow only
        p.lightDirection = glm::vec3(0.0f);
        const AdaptResult r = adaptTree(s, scene, glm::mat4(1.0f), p);
        ASSERT_GT(r.stats.prunedLength, 2.0);
        EXPECT_GE(r.stats.growthRounds, 2u);
        EXPECT_EQ(r.stats.collidingAfter, 0u);
        for (std::size_t i = 1; i < s.size(); ++i) {
            if (hidden(r.skeleton, static_cast<std::int32_t>(i))) continue;
            EXPECT_FALSE(scene.occluded({r.skeleton.position[static_cast<std::size_t>(s.parent[i])],
                                         r.skeleton.position[i]}))
                << i;
        }
        EXPECT_LT(r.skeleton.position[kTop].y, 6.3f);
        EXPECT_FALSE(hidden(r.skeleton, side));
        EXPECT_NEAR(visibleLength(r.skeleton), restLength(s), 1e-4 * restLength(s));
        // The side branch (1 m long at rest) took most of the 3.15 m.
        EXPECT_LT(r.skeleton.position[static_cast<std::size_t>(side)].x, -1.0f - 1.5f);
    }
}

TEST(Adapt, LeavesWhoseCardsTouchAnObstacleAreDropped) {
    // The trunk stands 0.2 m from a wall and never touches it; two leaves hang on its top,
    // one pointing at the wall (its 0.3 m card crosses the face), one away from it.
    skel::Skeleton s = trunk(4);
    const glm::vec3 top = s.position[4];
    const glm::quat towardWall = glm::angleAxis(-glm::half_pi<float>(), glm::vec3(0, 0, 1));
    const glm::quat awayFromWall = glm::angleAxis(glm::half_pi<float>(), glm::vec3(0, 0, 1));
    ASSERT_GT(skel::headingOf(towardWall).x, 0.99f);
    s.leaves.push_back({top, towardWall, 0.3f, 4});
    s.leaves.push_back({top, awayFromWall, 0.3f, 4});
    const ObstacleScene scene = wallAt(0.2f, 0.5f);
    AdaptParams p;
    // Axes only: the trunk's 0.2 m bark would touch the wall (BarkStaysOutOfObstacles...).
    const std::vector<float> axes(s.size(), 0.0f);
    p.barkRadii = axes;
    const AdaptResult r = adaptTree(s, scene, glm::mat4(1.0f), p);
    EXPECT_EQ(r.stats.collidingBefore, 0u);
    EXPECT_EQ(r.stats.droppedLeaves, 1u);
    ASSERT_EQ(r.skeleton.leaves.size(), 1u);
    EXPECT_EQ(r.skeleton.leaves[0].orientation, awayFromWall);
    // The card length is Leaf::size · leaf_scale: at 0.5 the card stops short of the wall.
    p.leafScale = 0.5f;
    EXPECT_EQ(adaptTree(s, scene, glm::mat4(1.0f), p).skeleton.leaves.size(), 2u);
    // A card reaching the wall sideways (its width, leaf_aspect) counts as well.
    p.leafScale = 1.0f;
    s.leaves = {{top, glm::quat(1, 0, 0, 0), 0.3f, 4}}; // heading up, 0.5 · 0.3 wide along x
    EXPECT_EQ(adaptTree(s, scene, glm::mat4(1.0f), p).skeleton.leaves.size(), 1u);
    p.leafAspect = 2.0f; // 0.6 wide: its edge at x = 0.3 is inside the wall
    EXPECT_EQ(adaptTree(s, scene, glm::mat4(1.0f), p).skeleton.leaves.size(), 0u);
    // Pruning off keeps every leaf.
    p.prune = false;
    EXPECT_EQ(adaptTree(s, scene, glm::mat4(1.0f), p).skeleton.leaves.size(), 1u);
}

TEST(Adapt, WorksInWorldSpaceThroughTheTreeTransform) {
    skel::Skeleton s = trunk(12);
    addBranch(s, 4, glm::vec3(0.22f, 0.1f, 0), 5, 1); // local +x
    // Rotated 90° about Y local +x is world -z; scale 2 puts the tip at world z = -2.2.
    glm::mat4 m = glm::translate(glm::mat4(1.0f), glm::vec3(10, 0, 0));
    m = glm::rotate(m, glm::half_pi<float>(), glm::vec3(0, 1, 0));
    m = glm::scale(m, glm::vec3(2.0f));
    const ObstacleScene scene({makeBoxMesh(glm::vec3(7, 0, -2.4f), glm::vec3(13, 6, -2.1f))});
    const AdaptResult r = adaptTree(s, scene, m, AdaptParams{});
    EXPECT_GE(r.stats.collidingBefore, 1u);
    EXPECT_EQ(r.stats.collidingAfter, 0u);
    EXPECT_EQ(r.stats.hiddenNodes, 0u);
    const glm::vec3 top = glm::vec3(m * glm::vec4(r.skeleton.position[kTop], 1.0f));
    EXPECT_GT(top.z, 0.5f); // away from the wall at -z
    EXPECT_NEAR(top.x, 10.0f, 1e-4f);
}

TEST(Adapt, NeighbourCrownsAreObstacles) {
    skel::Skeleton s = trunk(12);
    addBranch(s, 6, glm::vec3(0.3f, 0.05f, 0), 5, 1);
    const ObstacleScene none;
    const std::vector<CrownVolume> crowns = {{glm::vec3(2.5f, 0, 0), 1.2f, 2.0f, 8.0f}};
    const AdaptResult r = adaptTree(s, none, glm::mat4(1.0f), noRedistribution(), crowns);
    EXPECT_GE(r.stats.collidingBefore, 1u);
    EXPECT_LT(r.skeleton.position[kTop].x, 0.0f);
    for (std::size_t i = 1; i < s.size(); ++i) {
        if (hidden(r.skeleton, static_cast<std::int32_t>(i))) continue;
        const auto p = static_cast<std::size_t>(s.parent[i]);
        EXPECT_FALSE(segmentHitsCrown({r.skeleton.position[p], r.skeleton.position[i]}, crowns[0]));
    }
}

TEST(Adapt, RejectsBadParameters) {
    const skel::Skeleton s = trunk(3);
    const ObstacleScene scene;
    AdaptParams p;
    p.maxBend = 2.0f;
    try {
        adaptTree(s, scene, glm::mat4(1.0f), p);
        ADD_FAILURE() << "max_bend out of range accepted";
    } catch (const InvalidInput& e) {
        EXPECT_NE(std::string(e.what()).find("max_bend"), std::string::npos) << e.what();
    }
    p = AdaptParams{};
    p.bendMultiplier = -0.1f;
    try {
        adaptTree(s, scene, glm::mat4(1.0f), p);
        ADD_FAILURE() << "bend_multiplier out of range accepted";
    } catch (const InvalidInput& e) {
        EXPECT_NE(std::string(e.what()).find("bend_multiplier"), std::string::npos) << e.what();
    }
    skel::Skeleton broken = s;
    broken.parent[2] = 5;
    EXPECT_THROW(adaptTree(broken, scene, glm::mat4(1.0f), AdaptParams{}), InvalidInput);
}

namespace {
class CancelAtOnce : public Progress {
public:
    bool isCancelled() const override { return true; }
};
} // namespace

TEST(Adapt, ManyTreesInParallelMatchOneByOne) {
    skel::Skeleton s = trunk(12);
    addBranch(s, 2, glm::vec3(0.45f, 0.02f, 0), 7, 1);
    addBranch(s, 6, glm::vec3(-0.3f, 0.1f, 0.2f), 5, 1);
    const ObstacleScene scene = wallAt(1.0f, 1.2f);
    std::vector<const skel::Skeleton*> rest;
    std::vector<glm::mat4> transforms;
    for (int i = 0; i < 40; ++i) {
        rest.push_back(&s);
        glm::mat4 m = glm::translate(glm::mat4(1.0f), glm::vec3(-3.0f + 0.15f * i, 0, 0));
        transforms.push_back(glm::rotate(m, 0.3f * static_cast<float>(i), glm::vec3(0, 1, 0)));
    }
    const int saved = omp_get_max_threads();
    omp_set_num_threads(1);
    const std::vector<AdaptResult> one = adaptTrees(rest, transforms, scene, AdaptParams{});
    omp_set_num_threads(2);
    const std::vector<AdaptResult> two = adaptTrees(rest, transforms, scene, AdaptParams{});
    omp_set_num_threads(saved);
    ASSERT_EQ(one.size(), 40u);
    std::size_t touched = 0;
    for (std::size_t i = 0; i < one.size(); ++i) {
        expectSameSkeleton(one[i].skeleton, two[i].skeleton);
        expectSameSkeleton(one[i].skeleton,
                           adaptTree(s, scene, transforms[i], AdaptParams{}).skeleton);
        touched += one[i].stats.collidingBefore > 0 ? 1 : 0;
    }
    EXPECT_GT(touched, 5u);
    CancelAtOnce cancel;
    EXPECT_THROW(adaptTrees(rest, transforms, scene, AdaptParams{}, {}, cancel), Cancelled);
    EXPECT_THROW(
        adaptTrees(rest, std::span<const glm::mat4>(transforms).first(3), scene, AdaptParams{}),
        InvalidInput);
}

// Bark, not only axes: a branch whose axis passes 5 cm above a box while its bark (10 cm
// radius) dips into it. Tested as axes (zero bark radii) nothing collides; tested as tubes the
// branch collides, and no vertex of the adapted tree's tube mesh is inside the box.
TEST(Adapt, BarkStaysOutOfObstaclesNotOnlyAxes) {
    skel::Skeleton s;
    s.addNode(glm::vec3(0.0f), -1, 0.15f, 0, glm::quat(1, 0, 0, 0));
    const std::int32_t fork = addBranch(s, 0, glm::vec3(0, 0.5f, 0), 4, 0, 0.15f); // y = 2
    addBranch(s, fork, glm::vec3(0, 0.5f, 0), 2, 0, 0.12f);
    addBranch(s, fork, glm::vec3(0.25f, 0, 0), 6, 1, 0.1f); // to x = 1.5 at y = 2
    const glm::vec3 lo(0.5f, 0.0f, -1.0f), hi(1.0f, 1.95f, 1.0f);
    const ObstacleScene scene({makeBoxMesh(lo, hi)});
    const glm::mat4 m(1.0f);

    AdaptParams axes;
    const std::vector<float> zero(s.size(), 0.0f);
    axes.barkRadii = zero;
    EXPECT_EQ(adaptTree(s, scene, m, axes).stats.collidingBefore, 0u);

    {
        const AdaptParams bark; // the skeleton's radii
        const AdaptResult r = adaptTree(s, scene, m, bark);
        EXPECT_GT(r.stats.collidingBefore, 0u);
        EXPECT_EQ(r.stats.collidingAfter, 0u);
        const mesh::Mesh tubes = mesh::buildTubeMesh(r.skeleton, mesh::TubeSettings{});
        ASSERT_FALSE(tubes.positions.empty());
        std::size_t inside = 0;
        for (const glm::vec3& p : tubes.positions)
            inside +=
                glm::all(glm::greaterThan(p, lo + 1e-5f)) && glm::all(glm::lessThan(p, hi - 1e-5f));
        EXPECT_EQ(inside, 0u);
        // The same skeleton unadapted has tube vertices inside the box: the test can fail.
        const mesh::Mesh rest = mesh::buildTubeMesh(s, mesh::TubeSettings{});
        std::size_t restInside = 0;
        for (const glm::vec3& p : rest.positions)
            restInside +=
                glm::all(glm::greaterThan(p, lo + 1e-5f)) && glm::all(glm::lessThan(p, hi - 1e-5f));
        EXPECT_GT(restInside, 0u);
    }
    // Bark radii of another size than the skeleton are refused.
    AdaptParams wrong;
    const std::vector<float> three(3, 0.1f);
    wrong.barkRadii = three;
    EXPECT_THROW(adaptTree(s, scene, m, wrong), InvalidInput);
}
