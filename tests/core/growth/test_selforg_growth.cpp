// Whole-tree behaviour of the self-organizing model: competition, obstacles, shedding,
// determinism, validation and limits.
#include <gtest/gtest.h>

#include <omp.h>

#include "engine/growth/selforganizing.h"
#include "engine/util/error.h"
#include "selforgparams.h"

using namespace sylva;
using namespace sylva::growth;

namespace {

SelfOrganizingParams small(SoEnvironment env) {
    SelfOrganizingParams p;
    p.environment = env;
    p.cycles = 10;
    p.markers = 6000;
    p.crownRadius = 1.5;
    p.crownBase = 0.3;
    p.crownTop = 3.5;
    return p;
}

glm::vec3 centreOfMass(const skel::Skeleton& s) {
    glm::vec3 c(0.0f);
    for (const glm::vec3& p : s.position)
        c += p;
    return c / static_cast<float>(s.size());
}

/// A vertical wall x = x0, z ∈ [−4, 4], y ∈ [0, height], as two triangles.
std::vector<glm::vec3> wall(float x0, float height) {
    return {{x0, 0, -4}, {x0, height, -4}, {x0, height, 4},
            {x0, 0, -4}, {x0, height, 4},  {x0, 0, 4}};
}

bool sameSkeleton(const skel::Skeleton& a, const skel::Skeleton& b) {
    return a.position == b.position && a.parent == b.parent && a.radius == b.radius &&
           a.order == b.order && a.flags == b.flags && a.leaves.size() == b.leaves.size();
}

} // namespace

TEST(SelfOrgGrowth, GrowsAValidTreeWithAttributes) {
    for (SoEnvironment env : {SoEnvironment::ShadowPropagation, SoEnvironment::SpaceColonization}) {
        const SelfOrganizingResult r = growSelfOrganizingDetailed(small(env), 3);
        r.skeleton.validate();
        EXPECT_GT(r.internodes, 100u);
        EXPECT_EQ(r.skeleton.size(), r.internodes + 1);
        EXPECT_EQ(r.light.size(), r.skeleton.size());
        EXPECT_EQ(r.vigour.size(), r.skeleton.size());
        EXPECT_EQ(r.age.size(), r.skeleton.size());
        EXPECT_EQ(r.skeleton.position[0], glm::vec3(0.0f));
        // The base carries all light, and is the oldest node.
        for (std::size_t i = 1; i < r.skeleton.size(); ++i) {
            EXPECT_LE(r.light[i], r.light[0] * (1 + 1e-5f));
            EXPECT_LE(r.age[i], r.age[0]);
        }
        // Pipe model: the trunk is thicker than the tips.
        EXPECT_GT(r.skeleton.radius[0], 3 * r.skeleton.radius.back());
        glm::vec3 lo, hi;
        r.skeleton.bounds(lo, hi);
        EXPECT_GT(hi.y, 1.0f);
    }
}

TEST(SelfOrgGrowth, DeterministicOnOneAndTwoThreads) {
    for (SoEnvironment env : {SoEnvironment::ShadowPropagation, SoEnvironment::SpaceColonization}) {
        SelfOrganizingParams p = small(env);
        std::vector<StandTree> trees = {{{0, 0, 0}, p, 11}, {{1.2f, 0, 0.4f}, p, 12}};
        trees[1].params.allocation = SoAllocation::Priority;
        const int before = omp_get_max_threads();
        omp_set_num_threads(1);
        const std::vector<skel::Skeleton> one = growStand(trees, wall(-1.0f, 3.0f));
        omp_set_num_threads(2);
        const std::vector<skel::Skeleton> two = growStand(trees, wall(-1.0f, 3.0f));
        omp_set_num_threads(before);
        ASSERT_EQ(one.size(), 2u);
        for (std::size_t t = 0; t < 2; ++t)
            EXPECT_TRUE(sameSkeleton(one[t], two[t]));
        // A different seed gives a different tree.
        const skel::Skeleton other = growSelfOrganizing(p, 99);
        EXPECT_FALSE(sameSkeleton(other, growSelfOrganizing(p, 11)));
    }
}

// The test above stays below the sizes where the parallel loops of a cycle split their work.
// Here a tree grows past 20k metamers and every cycle must give the same arrays on 1, 2 and 3
// threads, with the Borchert–Honda scan and with the two-pass (priority) path.
// (SelfOrgShadow.NaiveAndIncrementalGrowTheSameTree also compares 1 and 2 threads at size, but
// across the naive and incremental paths, Borchert–Honda only, and at the end of the run.)
TEST(SelfOrgGrowth, DeterministicOnOneTwoAndThreeThreadsAtSize) {
    for (SoAllocation allocation : {SoAllocation::BorchertHonda, SoAllocation::Priority}) {
        SelfOrganizingParams p =
            test::vigorousParams(allocation == SoAllocation::BorchertHonda ? 14 : 10);
        p.allocation = allocation;
        const int before = omp_get_max_threads();
        std::vector<SelfOrganizingSimulation> sims;
        for (int threads = 1; threads <= 3; ++threads)
            sims.emplace_back(std::vector<StandTree>{{{0, 0, 0}, p, 5}}, std::vector<glm::vec3>{});
        std::size_t largest = 0;
        while (!sims[0].done()) {
            for (int threads = 1; threads <= 3; ++threads) {
                omp_set_num_threads(threads);
                sims[static_cast<std::size_t>(threads - 1)].step();
            }
            const MetamerArrays& a = sims[0].metamers();
            largest = std::max(largest, a.size());
            for (std::size_t k = 1; k < 3; ++k) {
                const MetamerArrays& b = sims[k].metamers();
                ASSERT_EQ(a.size(), b.size());
                ASSERT_TRUE(a.end == b.end && a.frame == b.frame && a.parent == b.parent &&
                            a.mainChild == b.mainChild && a.lateralChild == b.lateralChild &&
                            a.deadBuds == b.deadBuds && a.born == b.born)
                    << "threads " << k + 1 << ", " << a.size() << " metamers";
            }
        }
        omp_set_num_threads(before);
        EXPECT_GT(largest, 20000u);
    }
}

TEST(SelfOrgGrowth, SheddingRemovesExactlyTheDimSubtrees) {
    SelfOrganizingParams p = small(SoEnvironment::ShadowPropagation);
    p.sheddingThreshold = 0.3;
    SelfOrganizingSimulation sim({{glm::vec3(0), p, 4}}, {});
    std::size_t shedSeen = 0;
    for (int c = 0; c < 8; ++c) {
        sim.step();
        // Oracle from the state before the next cycle: light per bud, then for every lateral
        // branch its light per internode by recursion.
        const MetamerArrays before = sim.metamers();
        std::vector<double> t, a;
        sim.evaluateLight(t, a);
        const std::size_t n = before.size();
        std::vector<double> q(n);
        std::vector<int> cnt(n);
        for (std::size_t i = n; i-- > 0;) {
            q[i] += t[i] + a[i];
            cnt[i] += 1;
            if (before.parent[i] >= 0) {
                q[static_cast<std::size_t>(before.parent[i])] += q[i];
                cnt[static_cast<std::size_t>(before.parent[i])] += cnt[i];
            }
        }
        std::vector<char> gone(n, 0);
        std::size_t expected = 0;
        for (std::size_t i = 0; i < n; ++i) {
            const std::int32_t par = before.parent[i];
            if (par >= 0 && gone[static_cast<std::size_t>(par)])
                gone[i] = 1;
            else if (par >= 0 &&
                     before.lateralChild[static_cast<std::size_t>(par)] ==
                         static_cast<std::int32_t>(i) &&
                     q[i] < 0.3 * cnt[i])
                gone[i] = 1;
            expected += gone[i];
        }
        const std::size_t shedBefore = sim.shedCount();
        if (sim.done()) break;
        sim.step();
        ASSERT_EQ(sim.shedCount() - shedBefore, expected) << "cycle " << c;
        // The survivors keep their order and positions at the front of the arrays.
        std::size_t k = 0;
        for (std::size_t i = 0; i < n; ++i) {
            if (gone[i]) continue;
            ASSERT_EQ(sim.metamers().end[k], before.end[i]);
            ++k;
        }
        shedSeen += expected;
    }
    EXPECT_GT(shedSeen, 0u);
}

TEST(SelfOrgGrowth, StarvedNodesAreExactlyWhatTheNextCycleSheds) {
    // results() flags (skel::kStarved) the branches below the shedding threshold; stepping on
    // must shed exactly those metamers and keep the others, in order.
    SelfOrganizingParams p = small(SoEnvironment::ShadowPropagation);
    p.sheddingThreshold = 0.3;
    SelfOrganizingSimulation sim({{glm::vec3(0), p, 4}}, {});
    std::size_t starvedSeen = 0;
    sim.step();
    while (!sim.done()) {
        const MetamerArrays before = sim.metamers();
        const SelfOrganizingResult r = sim.results()[0];
        const skel::Skeleton& s = r.skeleton;
        EXPECT_EQ(s.shedThreshold, 0.3f);
        ASSERT_EQ(s.size(), before.size() + 1); // the root node, then one node per metamer
        EXPECT_EQ(s.flags[0] & skel::kStarved, 0);
        std::size_t flagged = 0;
        for (std::size_t i = 0; i < before.size(); ++i) {
            ASSERT_EQ(s.position[i + 1], before.end[i]);
            flagged += (s.flags[i + 1] & skel::kStarved) ? 1 : 0;
        }
        EXPECT_EQ(r.starved, flagged);
        const std::size_t shedBefore = sim.shedCount();
        sim.step();
        ASSERT_EQ(sim.shedCount() - shedBefore, flagged) << "cycle " << sim.cycle();
        std::size_t k = 0;
        for (std::size_t i = 0; i < before.size(); ++i) {
            if (s.flags[i + 1] & skel::kStarved) continue;
            ASSERT_EQ(sim.metamers().end[k], before.end[i]) << "metamer " << i;
            ++k;
        }
        starvedSeen += flagged;
    }
    EXPECT_GT(starvedSeen, 0u);
}

TEST(SelfOrgGrowth, LeansAwayFromATallObstacle) {
    for (SoEnvironment env : {SoEnvironment::ShadowPropagation, SoEnvironment::SpaceColonization}) {
        SelfOrganizingParams p = small(env);
        p.cycles = 12;
        const std::vector<StandTree> tree = {{glm::vec3(0), p, 8}};
        const skel::Skeleton alone = growStand(tree, {})[0];
        const skel::Skeleton beside = growStand(tree, wall(0.5f, 8.0f))[0];
        const float shift = centreOfMass(beside).x - centreOfMass(alone).x;
        EXPECT_LT(shift, -0.05f) << "environment " << static_cast<int>(env);
        glm::vec3 lo, hi;
        beside.bounds(lo, hi);
        EXPECT_LT(hi.x, 0.5f); // never through the wall
    }
}

TEST(SelfOrgGrowth, NeighboursShrinkFacingCrowns) {
    for (SoEnvironment env : {SoEnvironment::ShadowPropagation, SoEnvironment::SpaceColonization}) {
        SelfOrganizingParams p = small(env);
        p.cycles = 12;
        const float d = 1.2f;
        const skel::Skeleton alone = growStand({{glm::vec3(0), p, 21}}, {})[0];
        const std::vector<skel::Skeleton> pair =
            growStand({{glm::vec3(0), p, 21}, {glm::vec3(d, 0, 0), p, 22}}, {});
        // Crown reach of tree 0 towards +x (where its neighbour stands) and of tree 1 towards −x.
        auto reach = [](const skel::Skeleton& s, float sign) {
            float r = 0.0f;
            for (const glm::vec3& q : s.position)
                r = std::max(r, sign * q.x);
            return r;
        };
        auto facing = [](const skel::Skeleton& s, float sign) {
            std::size_t c = 0;
            for (const glm::vec3& q : s.position)
                c += sign * q.x > 0.2f;
            return c;
        };
        EXPECT_LT(reach(pair[0], 1), reach(alone, 1)) << static_cast<int>(env);
        EXPECT_LT(facing(pair[0], 1), facing(alone, 1)) << static_cast<int>(env);
        EXPECT_LT(facing(pair[1], -1), facing(alone, -1) + facing(alone, 1));
    }
}

TEST(SelfOrgGrowth, InternodeLimitStopsRunawayGrowth) {
    SelfOrganizingParams p = small(SoEnvironment::ShadowPropagation);
    p.maxInternodes = 50;
    try {
        growSelfOrganizing(p, 1);
        FAIL() << "expected LimitExceeded";
    } catch (const LimitExceeded& e) {
        EXPECT_NE(std::string(e.what()).find("max_internodes"), std::string::npos) << e.what();
        EXPECT_NE(std::string(e.what()).find("50"), std::string::npos) << e.what();
    }
}

TEST(SelfOrgGrowth, ValidationNamesTheRange) {
    auto expectRange = [](auto mutate, const std::string& what) {
        SelfOrganizingParams p;
        mutate(p);
        try {
            p.validate();
            ADD_FAILURE() << what << " accepted";
        } catch (const InvalidInput& e) {
            const std::string m = e.what();
            EXPECT_NE(m.find(what), std::string::npos) << m;
            EXPECT_NE(m.find('['), std::string::npos) << m;
        }
    };
    expectRange([](auto& p) { p.lambda = 1.5; }, "lambda");
    expectRange([](auto& p) { p.alpha = 0; }, "alpha");
    expectRange([](auto& p) { p.alpha = std::nan(""); }, "alpha");
    expectRange([](auto& p) { p.shadowB = 1.0; }, "shadow_b");
    expectRange([](auto& p) { p.shadowDepth = 40; }, "shadow_depth");
    expectRange([](auto& p) { p.perceptionAngle = 0; }, "perception_angle");
    expectRange([](auto& p) { p.occupancyRadius = 5; }, "occupancy_radius"); // > r = 4
    expectRange([](auto& p) { p.crownTop = 0.5; }, "crown_top");
    expectRange([](auto& p) { p.wMin = 2; }, "w_min");
    expectRange([](auto& p) { p.cycles = 0; }, "cycles");
    expectRange([](auto& p) { p.pipeExponent = 5; }, "pipe_exponent");
    expectRange([](auto& p) { p.internodeLength = INFINITY; }, "internode_length");
    expectRange([](auto& p) { p.maxInternodes = 0; }, "max_internodes");

    SelfOrganizingParams p;
    std::vector<StandTree> mixed = {{glm::vec3(0), p, 1}, {glm::vec3(1, 0, 0), p, 2}};
    mixed[1].params.environment = SoEnvironment::SpaceColonization;
    EXPECT_THROW(growStand(mixed, {}), InvalidInput);
    EXPECT_THROW(growStand({}, {}), InvalidInput);
    EXPECT_THROW(growStand({{glm::vec3(0), p, 1}}, {glm::vec3(0), glm::vec3(1)}), InvalidInput);
}

// A stand holds at most 65,535 trees (node ids keep the tree in 16 bits): one more is refused
// before anything grows, with a message saying what to do.
TEST(SelfOrganizing, StandsAreLimitedTo65535Trees) {
    const SelfOrganizingParams p = test::vigorousParams(2);
    const std::vector<StandTree> trees(65536, StandTree{glm::vec3(0), p, 1});
    try {
        growStand(trees, {});
        FAIL() << "no limit";
    } catch (const LimitExceeded& e) {
        EXPECT_STREQ(e.what(), "a stand of self-organizing trees holds at most 65,535 trees, got "
                               "65536; lower the domains' counts or split the scene into several "
                               "projects");
    }
}
