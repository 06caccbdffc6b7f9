// Issue #43: branches of a grown Skeleton on stable ids, and hand edits of single branches.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "engine/forest/metrics.h"
#include "engine/skeleton/branches.h"
#include "engine/util/error.h"

using namespace sylva;

namespace {

const glm::quat kUp(1, 0, 0, 0);

// A trunk of 4 segments up +Y; branch A leaves node 1 towards +X, branch B node 2 towards -X;
// A carries a twig C at its second node; a leaf hangs on C's tip.
skel::Skeleton sample(float scale = 1.0f) {
    skel::Skeleton s;
    s.addNode(glm::vec3(0), -1, 0.3f, 0, kUp); // 0
    for (int i = 1; i <= 4; ++i)               // 1..4
        s.addNode(glm::vec3(0, scale * static_cast<float>(i), 0), i - 1, 0.3f - 0.05f * i, 0, kUp);
    s.addNode(glm::vec3(scale * 1, scale * 1.2f, 0), 1, 0.1f, 1, kUp);  // 5: A
    s.addNode(glm::vec3(scale * 2, scale * 1.4f, 0), 5, 0.08f, 1, kUp); // 6: A
    s.addNode(glm::vec3(scale * 3, scale * 1.6f, 0), 6, 0.06f, 1, kUp); // 7: A tip
    s.addNode(glm::vec3(-scale, scale * 2.2f, 0), 2, 0.1f, 1, kUp);     // 8: B
    s.addNode(glm::vec3(scale * 2, scale * 2.0f, 0), 6, 0.03f, 2, kUp); // 9: C
    skel::Leaf leaf;
    leaf.position = s.position[9];
    leaf.node = 9;
    s.leaves.push_back(leaf);
    s.finalize();
    return s;
}

const skel::Branch* find(const std::vector<skel::Branch>& bs, const std::string& id) {
    auto it = std::find_if(bs.begin(), bs.end(), [&](const skel::Branch& b) { return b.id == id; });
    return it == bs.end() ? nullptr : &*it;
}

skel::BranchEdit edit(std::string id, bool prune = false, std::optional<glm::vec3> bend = {},
                      float length = 1.0f, float radius = 1.0f) {
    skel::BranchEdit e;
    e.branch = std::move(id);
    e.prune = prune;
    e.bend = bend;
    e.length = length;
    e.radius = radius;
    return e;
}

} // namespace

TEST(Branches, IdsFollowTheGrowthStructure) {
    const std::vector<skel::Branch> bs = skel::branchesOf(sample());
    ASSERT_EQ(bs.size(), 4u);
    EXPECT_EQ(bs[0].id, "0");
    EXPECT_EQ(bs[0].nodes, (std::vector<std::int32_t>{0, 1, 2, 3, 4}));
    EXPECT_EQ(bs[0].parent, "");
    EXPECT_FLOAT_EQ(bs[0].length, 4.0f);
    const skel::Branch* a = find(bs, "0.0");
    const skel::Branch* b = find(bs, "0.1");
    const skel::Branch* c = find(bs, "0.0.0");
    ASSERT_TRUE(a && b && c);
    EXPECT_EQ(a->nodes, (std::vector<std::int32_t>{5, 6, 7})); // leaves lower: rank 0
    EXPECT_EQ(b->nodes, (std::vector<std::int32_t>{8}));
    EXPECT_EQ(c->nodes, (std::vector<std::int32_t>{9}));
    EXPECT_EQ(c->parent, "0.0");
    EXPECT_EQ(c->order, 2);
    EXPECT_EQ(a->baseNode, 1);
    EXPECT_EQ(a->base, glm::vec3(0, 1, 0));
    EXPECT_EQ(a->tip, glm::vec3(3, 1.6f, 0));
    EXPECT_FLOAT_EQ(a->baseRadius, 0.1f);
}

TEST(Branches, IdsSurviveAChangeThatKeepsTheTopology) {
    const std::vector<skel::Branch> a = skel::branchesOf(sample(1.0f));
    const std::vector<skel::Branch> b = skel::branchesOf(sample(1.7f));
    ASSERT_EQ(a.size(), b.size());
    for (std::size_t i = 0; i < a.size(); ++i) {
        EXPECT_EQ(a[i].id, b[i].id);
        EXPECT_EQ(a[i].nodes, b[i].nodes);
    }
}

TEST(Branches, SameNodeBranchesAreRankedByAngle) {
    skel::Skeleton s;
    s.addNode(glm::vec3(0), -1, 0.3f, 0, kUp);
    s.addNode(glm::vec3(0, 1, 0), 0, 0.2f, 0, kUp);
    s.addNode(glm::vec3(0, 2, 0), 1, 0.2f, 0, kUp);
    // Three branches of a whorl at node 1, added in an order unlike their angles.
    s.addNode(glm::vec3(0, 1.2f, 1), 1, 0.05f, 1, kUp);  // +Z
    s.addNode(glm::vec3(-1, 1.2f, 0), 1, 0.05f, 1, kUp); // -X: the turtle's left, angle 0
    s.addNode(glm::vec3(1, 1.2f, 0), 1, 0.05f, 1, kUp);  // +X
    s.finalize();
    const std::vector<skel::Branch> bs = skel::branchesOf(s);
    ASSERT_EQ(bs.size(), 4u);
    EXPECT_EQ(find(bs, "0.0")->nodes.front(), 4);
    EXPECT_EQ(find(bs, "0.1")->nodes.front(), 3);
    EXPECT_EQ(find(bs, "0.2")->nodes.front(), 5);
}

TEST(BranchEdits, PruneRemovesTheBranchAndWhatItCarries) {
    skel::Skeleton s = sample();
    const forest::TreeMetrics before = forest::measureTree(s, {}, 1.0f);
    const skel::BranchEditReport r = skel::applyBranchEdits(s, {edit("0.0", true)});
    EXPECT_EQ(r.applied, 1u);
    EXPECT_EQ(r.prunedNodes, 4u);
    EXPECT_TRUE(r.orphaned.empty());
    EXPECT_EQ(s.size(), 6u);
    EXPECT_NO_THROW(s.validate());
    EXPECT_TRUE(s.leaves.empty()); // the leaf hung on the twig
    EXPECT_EQ(s.position[5], glm::vec3(-1, 2.2f, 0));
    EXPECT_EQ(s.parent[5], 2);
    EXPECT_LT(forest::measureTree(s, {}, 1.0f).woodVolumeM3, before.woodVolumeM3);
    EXPECT_EQ(skel::branchesOf(s).size(), 2u);
}

TEST(BranchEdits, BendTurnsTheBranchAndWhatItCarriesAboutItsBase) {
    skel::Skeleton s = sample();
    const skel::Skeleton before = s;
    skel::applyBranchEdits(s, {edit("0.0", false, glm::vec3(0, 5, 0))});
    const glm::vec3 base(0, 1, 0);
    EXPECT_NEAR(s.position[7].x, 0.0f, 1e-5f);
    EXPECT_NEAR(s.position[7].y, 1.0f + glm::length(before.position[7] - base), 1e-5f);
    // Rigid: distances from the base kept, the twig and its leaf carried along.
    for (int i : {5, 6, 7, 9})
        EXPECT_NEAR(glm::length(s.position[i] - base), glm::length(before.position[i] - base),
                    1e-5f);
    EXPECT_NEAR(glm::length(s.leaves[0].position - s.position[9]), 0.0f, 1e-5f);
    for (int i : {0, 1, 2, 3, 4, 8})
        EXPECT_EQ(s.position[i], before.position[i]) << i;
}

TEST(BranchEdits, LengthScalesTheBranchesOwnSegmentsAndRadiusItsSubtree) {
    skel::Skeleton s = sample();
    const skel::Skeleton before = s;
    skel::applyBranchEdits(s, {edit("0.0", false, {}, 0.5f, 2.0f)});
    const std::vector<skel::Branch> after = skel::branchesOf(s), was = skel::branchesOf(before);
    const skel::Branch* a = find(after, "0.0");
    ASSERT_TRUE(a);
    EXPECT_NEAR(a->length, 0.5f * find(was, "0.0")->length, 1e-5f);
    // The twig moves with the node it leaves, keeping its own segment.
    EXPECT_NEAR(
        glm::length((s.position[9] - s.position[6]) - (before.position[9] - before.position[6])),
        0.0f, 1e-6f);
    EXPECT_FLOAT_EQ(s.radius[9], 0.06f);
    EXPECT_FLOAT_EQ(s.radius[5], 0.2f);
    EXPECT_FLOAT_EQ(s.radius[8], 0.1f);
}

TEST(BranchEdits, AThickenedBranchIsNoThickerThanWhereItLeaves) {
    skel::Skeleton s = sample();
    skel::applyBranchEdits(s, {edit("0.0", false, {}, 1.0f, 5.0f)});
    // 0.1 x 5 would be twice the trunk node it leaves (0.25): clamped as the radius pass does.
    EXPECT_FLOAT_EQ(s.radius[5], s.radius[1]);
    for (std::size_t i = 0; i < s.size(); ++i)
        if (s.parent[i] >= 0) {
            EXPECT_LE(s.radius[i], s.radius[std::size_t(s.parent[i])]) << i;
        }
    EXPECT_FLOAT_EQ(s.radius[9], 0.15f); // the twig, x5, still under its parent
    EXPECT_FLOAT_EQ(s.radius[8], 0.1f);  // the other branch untouched
}

TEST(BranchEdits, MissingBranchesAreReportedNotErrors) {
    skel::Skeleton s = sample();
    const skel::BranchEditReport r =
        skel::applyBranchEdits(s, {edit("0.7", true), edit("0.1", false, {}, 2.0f)});
    EXPECT_EQ(r.applied, 1u);
    EXPECT_EQ(r.orphaned, std::vector<std::string>{"0.7"});
}

TEST(BranchEdits, OutOfRangeEditsAreRefused) {
    skel::Skeleton s = sample();
    EXPECT_THROW(skel::applyBranchEdits(s, {edit("0.1", false, {}, 0.0f)}), InvalidInput);
    EXPECT_THROW(skel::applyBranchEdits(s, {edit("0.1", false, {}, 1.0f, 21.0f)}), InvalidInput);
    EXPECT_THROW(skel::applyBranchEdits(s, {edit("0.1", false, glm::vec3(0))}), InvalidInput);
    EXPECT_THROW(skel::applyBranchEdits(s, {edit("0", true)}), InvalidInput);
}

TEST(BranchEdits, EditedBranchesKeepTheGrownIds) {
    const skel::Skeleton s = sample();
    const std::vector<skel::Branch> bs =
        skel::editedBranches(s, {edit("0.0", true), edit("0.1", false, glm::vec3(0, 1, 0))});
    ASSERT_EQ(bs.size(), 2u); // the trunk and 0.1; 0.0 and its twig 0.0.0 are pruned
    EXPECT_EQ(bs[1].id, "0.1");
    EXPECT_EQ(bs[1].nodes, std::vector<std::int32_t>{5});
    EXPECT_NEAR(bs[1].tip.x, 0.0f, 1e-5f);
    EXPECT_GT(bs[1].tip.y, 2.0f);
}

TEST(BranchEdits, ALockedBranchKeepsItsGeometryThroughRegrowth) {
    skel::BranchEdit e = edit("0.0", false, {}, 0.5f);
    e.lock = true;
    skel::lockBranch(sample(), {}, e);
    ASSERT_EQ(e.locked.size(), 4u); // 5, 6, 7 and the twig 9
    ASSERT_EQ(e.lockedLeaves.size(), 1u);
    EXPECT_EQ(e.lockedBase, glm::vec3(0, 1, 0));
    EXPECT_NO_THROW(skel::validate(e));
    // Regrown larger (the same topology, other lengths): the locked branch keeps its shape,
    // shortened as it was when locked, at its parent's node where it now is.
    skel::Skeleton s = sample(1.7f);
    const skel::BranchEditReport r = skel::applyBranchEdits(s, {e});
    EXPECT_EQ(r.applied, 1u);
    EXPECT_NO_THROW(s.validate());
    EXPECT_EQ(s.size(), 10u);
    const std::vector<skel::Branch> bs = skel::branchesOf(s);
    const skel::Branch* a = find(bs, "0.0");
    ASSERT_TRUE(a);
    EXPECT_EQ(a->base, glm::vec3(0, 1.7f, 0));
    EXPECT_NEAR(a->length, 0.5f * 3.0f * std::sqrt(1.04f), 1e-4f);
    EXPECT_EQ(s.leaves.size(), 1u);
    // Listed with the grown tree's ids.
    const std::vector<skel::Branch> listed = skel::editedBranches(sample(1.7f), {e});
    ASSERT_TRUE(find(listed, "0.0"));
    EXPECT_NEAR(find(listed, "0.0")->length, a->length, 1e-5f);
    // What it carries is kept with it: not listed, not edited on its own.
    EXPECT_FALSE(find(listed, "0.0.0"));
}

TEST(BranchEdits, ALockedBranchWhoseIdIsGoneIsGraftedOntoItsParent) {
    skel::BranchEdit e = edit("0.1");
    e.lock = true;
    skel::lockBranch(sample(), {}, e);
    // Regrown without branch B (node 8): "0.1" is gone; it comes back at the trunk's node 2.
    skel::Skeleton s = sample();
    skel::applyBranchEdits(s, {edit("0.1", true)});
    ASSERT_EQ(skel::branchesOf(s).size(), 3u);
    const skel::BranchEditReport r = skel::applyBranchEdits(s, {e});
    EXPECT_EQ(r.reattached, 1u);
    EXPECT_TRUE(r.orphaned.empty());
    EXPECT_EQ(s.size(), 10u);
    EXPECT_EQ(s.position.back(), glm::vec3(-1, 2.2f, 0));
    EXPECT_EQ(s.parent.back(), 2);
    // Without its geometry a lock changes nothing and an edit of a missing branch is orphaned.
    skel::Skeleton t = sample();
    skel::applyBranchEdits(t, {edit("0.1", true)});
    skel::BranchEdit flagOnly = edit("0.1");
    flagOnly.lock = true;
    EXPECT_EQ(skel::applyBranchEdits(t, {flagOnly}).orphaned.size(), 1u);
}
