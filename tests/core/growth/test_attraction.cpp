// Space colonization's attraction sums (sumAttraction) and closest points (nearestPoint) against
// the straightforward loop that colonize() ran before: the attracted nodes pushed as first met
// and sorted, the closest point tracked point by point, every array through its vector. Bit for
// bit over random points, nodes and live lists; without the hash (killed points, node −1, left
// in the list), both by the packed sums (each point, node and sum one register) and by the
// scalar loop.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <vector>

#include "engine/growth/attraction.h"
#include "engine/growth/spatialgrid.h"
#include "engine/util/random.h"

using namespace sylva;
using namespace sylva::growth;

namespace {

struct Reference {
    std::vector<glm::vec3> sum;
    std::vector<std::uint32_t> count;
    std::vector<std::uint64_t> setHash;
    std::vector<float> nearest2;
    std::vector<std::uint32_t> nearest;
    std::vector<std::uint32_t> attracted;
};

// The loop as colonize() had it inline.
void referenceSums(Reference& r, const std::vector<std::uint32_t>& live,
                   const std::vector<glm::vec3>& points, const std::vector<float>& best2,
                   const std::vector<std::int32_t>& bestNode, const std::vector<glm::vec3>& nodes) {
    const std::size_t n = nodes.size();
    r.sum.resize(n);
    r.count.resize(n, 0);
    r.setHash.resize(n);
    r.nearest2.resize(n);
    r.nearest.resize(n);
    r.attracted.clear();
    for (const std::uint32_t a : live) {
        const std::int32_t bn = bestNode[a];
        if (bn < 0) continue;
        const auto j = static_cast<std::size_t>(bn);
        if (r.count[j]++ == 0) {
            r.attracted.push_back(static_cast<std::uint32_t>(j));
            r.sum[j] = glm::vec3(0.0f);
            r.setHash[j] = 0x243F6A8885A308D3ull;
            r.nearest2[j] = std::numeric_limits<float>::infinity();
        }
        const float b2 = best2[a];
        r.sum[j] += (points[a] - nodes[j]) * (1.0f / std::sqrt(b2));
        r.setHash[j] = mixSeed(r.setHash[j], a);
        if (b2 < r.nearest2[j]) {
            r.nearest2[j] = b2;
            r.nearest[j] = a;
        }
    }
    std::sort(r.attracted.begin(), r.attracted.end());
}

float uniform(Rng& rng, float lo, float hi) {
    return static_cast<float>(rng.uniform(lo, hi));
}

} // namespace

// Several iterations of a growing node set over the same scratch (as colonize() reuses it),
// with points out of reach (−1), ties, nodes attracted again, node counts across 64-bit words.
TEST(Attraction, SameBitsAsSortedPushBack) {
    for (std::uint64_t seed = 1; seed <= 8; ++seed) {
        Rng rng(seed);
        const std::size_t pointCount = 200 + rng.below(3000);
        std::vector<glm::vec3> points(pointCount);
        for (glm::vec3& p : points)
            p = {uniform(rng, -5, 5), uniform(rng, 0, 10), uniform(rng, -5, 5)};
        std::vector<glm::vec3> nodes;
        // noHash takes the packed sums (on SSE2), noHashScalar the scalar loop.
        Attraction fast, noHash, noHashScalar;
        Reference ref;
        std::size_t attractedTotal = 0;
        for (int iteration = 0; iteration < 12; ++iteration) {
            const std::size_t grow = 1 + rng.below(iteration == 0 ? 5 : 150);
            for (std::size_t k = 0; k < grow; ++k)
                nodes.push_back({uniform(rng, -5, 5), uniform(rng, 0, 10), uniform(rng, -5, 5)});
            // A node may repeat one before it: points equally far from both keep the lower.
            if (nodes.size() > 2 && rng.below(2) == 0) nodes.back() = nodes[nodes.size() - 2];
            std::vector<std::uint32_t> live, withKilled;
            std::vector<std::uint8_t> killed(pointCount, 0);
            std::vector<float> best2(pointCount, 0.0f);
            std::vector<std::int32_t> bestNode(pointCount, -1);
            const float di2 = 2.5f * 2.5f;
            for (std::uint32_t a = 0; a < pointCount; ++a) {
                withKilled.push_back(a); // as colonize leaves the list: kills still in it
                if (rng.below(5) == 0) {
                    killed[a] = 1;
                    continue;
                }
                live.push_back(a);
                float b2 = di2;
                for (std::size_t j = 0; j < nodes.size(); ++j) {
                    const float d2 = distance2(points[a], nodes[j]);
                    if (d2 < b2) {
                        b2 = d2;
                        bestNode[a] = static_cast<std::int32_t>(j);
                    }
                }
                best2[a] = b2;
            }
            referenceSums(ref, live, points, best2, bestNode, nodes);
            sumAttraction(fast, live, points, best2.data(), bestNode.data(), nodes.data(),
                          nodes.size());
            // Without the hash, over the list as colonize() leaves it: the killed points (their
            // node −1, their distance 0 here) still in it, passed by.
            sumAttraction(noHash, withKilled, points, best2.data(), bestNode.data(), nodes.data(),
                          nodes.size(), false);
            sumAttraction(noHashScalar, withKilled, points, best2.data(), bestNode.data(),
                          nodes.data(), nodes.size(), false, false);
            ASSERT_EQ(noHashScalar.attracted, ref.attracted);
            std::vector<std::uint32_t> even;
            for (const std::uint32_t j : ref.attracted)
                if (j % 2 == 0) even.push_back(j);
            nearestPoints(fast, even, live, best2.data(), bestNode.data());
            for (const std::uint8_t w : fast.wanted)
                ASSERT_EQ(w, 0); // left clear for the next call
            ASSERT_EQ(noHash.attracted, ref.attracted) << "seed " << seed << " it " << iteration;
            attractedTotal += ref.attracted.size();
            for (const std::uint32_t j : ref.attracted) {
                ASSERT_EQ(std::memcmp(&fast.sum[j], &ref.sum[j], sizeof(glm::vec3)), 0)
                    << "node " << j;
                ASSERT_EQ(fast.count[j], ref.count[j]) << "node " << j;
                ASSERT_EQ(fast.setHash[j], ref.setHash[j]) << "node " << j;
                // The closest point, found by nearestPoints' pass (above, every other node).
                if (j % 2 == 0) {
                    ASSERT_EQ(std::memcmp(&fast.nearest2[j], &ref.nearest2[j], sizeof(float)), 0);
                    ASSERT_EQ(fast.nearest[j], ref.nearest[j]) << "node " << j;
                }
                // Without the hash: everything else the same.
                ASSERT_EQ(std::memcmp(&noHash.sum[j], &ref.sum[j], sizeof(glm::vec3)), 0);
                ASSERT_EQ(noHash.count[j], ref.count[j]) << "node " << j;
                noHash.count[j] = 0;
                // The scalar loop.
                ASSERT_EQ(std::memcmp(&noHashScalar.sum[j], &ref.sum[j], sizeof(glm::vec3)), 0);
                ASSERT_EQ(noHashScalar.count[j], ref.count[j]) << "node " << j;
                noHashScalar.count[j] = 0;
                // As colonize() does once it has grown the node.
                fast.count[j] = 0;
                ref.count[j] = 0;
            }
            ASSERT_EQ(std::vector<std::uint32_t>(fast.count.begin(),
                                                 fast.count.begin() + ref.count.size()),
                      ref.count);
            for (const std::uint32_t c : noHash.count)
                ASSERT_EQ(c, 0u); // the spare entry too
            for (const std::uint32_t c : noHashScalar.count)
                ASSERT_EQ(c, 0u);
            // The packed sums' scratch left clear for the next call.
            for (const std::uint8_t m : noHash.met)
                ASSERT_EQ(m, 0);
            for (const Attraction::NodeLanes& e : noHash.node4)
                ASSERT_TRUE(e.sum.count == 0.0f && e.sum.x == 0.0f && e.sum.y == 0.0f &&
                            e.sum.z == 0.0f);
        }
        EXPECT_GT(attractedTotal, 100u) << "seed " << seed; // the test exercises something
    }
}

// No live point in reach: nothing attracted, and the marks stay clear for the next call.
TEST(Attraction, NothingInReach) {
    const std::vector<glm::vec3> points{{0, 0, 0}, {1, 1, 1}};
    const std::vector<glm::vec3> nodes{{9, 9, 9}};
    const std::vector<float> best2{4.0f, 4.0f};
    const std::vector<std::int32_t> none{-1, -1};
    const std::vector<std::uint32_t> live{0, 1};
    Attraction a;
    sumAttraction(a, live, points, best2.data(), none.data(), nodes.data(), 1);
    EXPECT_TRUE(a.attracted.empty());
    const std::vector<std::int32_t> second{0, -1};
    sumAttraction(a, live, points, best2.data(), second.data(), nodes.data(), 1);
    EXPECT_EQ(a.attracted, std::vector<std::uint32_t>{0});
    EXPECT_EQ(a.count[0], 1u);
}
