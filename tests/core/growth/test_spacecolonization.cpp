// Space colonization: the accelerated search against the brute-force oracle, the end state,
// the envelope bound, the pipe model, determinism across thread counts and the validation.
#include <gtest/gtest.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <omp.h>

#include "engine/growth/colonizationsearch.h"
#include "engine/growth/envelope.h"
#include "engine/growth/pipemodel.h"
#include "engine/growth/spacecolonization.h"
#include "engine/growth/spatialgrid.h"
#include "engine/util/error.h"
#include "engine/util/random.h"

using namespace sylva;
using namespace sylva::growth;

namespace {

// Bit-exact comparison of two skeletons.
void expectIdentical(const skel::Skeleton& a, const skel::Skeleton& b) {
    ASSERT_EQ(a.size(), b.size());
    for (std::size_t i = 0; i < a.size(); ++i) {
        ASSERT_EQ(std::memcmp(&a.position[i], &b.position[i], sizeof(glm::vec3)), 0)
            << "node " << i;
        ASSERT_EQ(a.parent[i], b.parent[i]) << "node " << i;
        ASSERT_EQ(std::memcmp(&a.radius[i], &b.radius[i], sizeof(float)), 0) << "node " << i;
        ASSERT_EQ(a.order[i], b.order[i]) << "node " << i;
        ASSERT_EQ(a.flags[i], b.flags[i]) << "node " << i;
        ASSERT_EQ(std::memcmp(&a.orientation[i], &b.orientation[i], sizeof(glm::quat)), 0);
    }
}

ColonizationParams referenceParams() {
    ColonizationParams p; // the reference's values: d_i 3, d_k 0.6, D 0.2, randomness 0.147
    p.trunkHeight = 2.0f;
    return p;
}

std::vector<glm::vec3> spherePoints(std::size_t n, std::uint64_t seed = 7) {
    return Envelope::sphere({0, 6, 0}, 4.5f).sample(n, seed);
}

// The end-state oracle, by brute force over the final skeleton.
void expectEveryPointKilledOrOutOfReach(const std::vector<glm::vec3>& points,
                                        const ColonizationResult& r, const ColonizationParams& p) {
    ASSERT_NE(r.stopReason, StopReason::IterationCap);
    const float di2 = p.influenceDistance * p.influenceDistance;
    const float dk2 = p.killDistance * p.killDistance;
    for (std::size_t a = 0; a < points.size(); ++a) {
        float best = INFINITY;
        for (const glm::vec3& n : r.skeleton.position)
            best = std::min(best, distance2(points[a], n));
        if (r.killed[a])
            EXPECT_LT(best, dk2) << "point " << a << " killed without a node in the kill zone";
        else
            EXPECT_GE(best, di2) << "point " << a << " alive yet in reach of a node";
    }
}

} // namespace

TEST(SpaceColonization, AcceleratedEqualsNaive) {
    for (std::uint64_t seed : {1u, 2u, 3u}) {
        const auto points = spherePoints(800, seed);
        ColonizationParams p = referenceParams();
        p.seed = seed;
        const ColonizationResult fast = colonize(points, p, nullptr, NeighbourSearch::Accelerated);
        const ColonizationResult slow = colonize(points, p, nullptr, NeighbourSearch::Naive);
        expectIdentical(fast.skeleton, slow.skeleton);
        EXPECT_EQ(fast.killed, slow.killed);
        EXPECT_EQ(fast.iterations, slow.iterations);
        EXPECT_EQ(fast.killedCount, slow.killedCount);
        EXPECT_EQ(fast.stopReason, slow.stopReason);
        EXPECT_GT(fast.skeleton.size(), 200u);
    }
}

// A crown that stops with points out of reach (a far clump, more points than the crown): the
// accelerated search leaves its killed points in the live list until they are an eighth of
// it, so some are still there at the stop; the counts and the stop reason are the oracle's.
TEST(SpaceColonization, AcceleratedEqualsNaiveStoppingOutOfReach) {
    for (std::uint64_t seed : {1u, 2u}) {
        auto points = spherePoints(400, seed);
        Rng rng(seed + 10);
        for (int k = 0; k < 3000; ++k)
            points.push_back({static_cast<float>(rng.uniform(40.0, 44.0)),
                              static_cast<float>(rng.uniform(4.0, 8.0)),
                              static_cast<float>(rng.uniform(-2.0, 2.0))});
        ColonizationParams p = referenceParams();
        p.seed = seed;
        const ColonizationResult fast = colonize(points, p, nullptr, NeighbourSearch::Accelerated);
        const ColonizationResult slow = colonize(points, p, nullptr, NeighbourSearch::Naive);
        expectIdentical(fast.skeleton, slow.skeleton);
        EXPECT_EQ(fast.killed, slow.killed);
        EXPECT_EQ(fast.iterations, slow.iterations);
        EXPECT_EQ(fast.stopReason, StopReason::NothingInReach);
        EXPECT_EQ(slow.stopReason, StopReason::NothingInReach);
        EXPECT_EQ(fast.killedCount, slow.killedCount);
        EXPECT_GT(fast.killedCount, 300u);
        EXPECT_LT(fast.killedCount, 500u);
    }
}

TEST(SpaceColonization, AcceleratedEqualsNaiveOtherShapesAndTropism) {
    ColonizationParams p;
    p.influenceDistance = 1.5f;
    p.killDistance = 0.3f;
    p.segmentLength = 0.1f;
    p.trunkHeight = 1.0f;
    p.tropism = {0.1f, -0.2f, 0.0f};
    p.randomness = 0.3f;
    const auto points = Envelope::cone({0, 2, 0}, 1.5f, 4.0f).sample(700, 5);
    const ColonizationResult fast = colonize(points, p, nullptr, NeighbourSearch::Accelerated);
    const ColonizationResult slow = colonize(points, p, nullptr, NeighbourSearch::Naive);
    expectIdentical(fast.skeleton, slow.skeleton);
    EXPECT_EQ(fast.killed, slow.killed);
}

// Enough points for a few dozen cells (192 a cell with AVX, 64 without), two clumps of
// different density: cells skipped, shrunk as their points die and emptied.
TEST(SpaceColonization, AcceleratedEqualsNaiveManyCells) {
    ColonizationParams p;
    p.influenceDistance = 2.0f;
    p.killDistance = 0.4f;
    p.segmentLength = 0.15f;
    p.trunkHeight = 1.5f;
    p.randomness = 0.25f;
    p.clearTrunk = 1.0f;
    std::vector<glm::vec3> points = Envelope::ellipsoid({0, 5, 0}, {4, 3, 4}).sample(2600, 11);
    for (const glm::vec3& q : Envelope::sphere({3, 7, 1}, 1.2f).sample(1400, 12))
        points.push_back(q);
    const ColonizationResult fast = colonize(points, p, nullptr, NeighbourSearch::Accelerated);
    const ColonizationResult slow = colonize(points, p, nullptr, NeighbourSearch::Naive);
    expectIdentical(fast.skeleton, slow.skeleton);
    EXPECT_EQ(fast.killed, slow.killed);
    EXPECT_EQ(fast.iterations, slow.iterations);
    EXPECT_GT(fast.killedCount, 3000u);
}

// A bush of 300 initial nodes, every one in reach of every cell at first: the search gathers
// the nodes that pass a cell's bound 64 at a time (more than one gathering a cell), and offers
// them to its lanes 16, 8 and 4 at a time. Pairs of nodes at one position, 1, 63, 64 and 65
// apart in index, tie exactly: the lower index must win across a gathering's end.
TEST(SpaceColonization, AcceleratedEqualsNaiveManyNodesACell) {
    skel::Skeleton bush;
    bush.addNode({0, 0, 0}, -1, 0.2f, 0, glm::quat(1, 0, 0, 0));
    const std::vector<glm::vec3> spots = Envelope::ellipsoid({0, 4, 0}, {3, 2, 3}).sample(240, 21);
    for (std::size_t i = 0; bush.size() < 300; ++i) {
        const std::size_t k = bush.size();
        // Every fourth node repeats the position of the node 1, 63, 64 or 65 before it.
        const std::size_t back = k % 4 == 0 && k > 70  ? std::size_t{63} + (k / 4) % 3
                                 : k % 4 == 1 && k > 2 ? 1
                                                       : 0;
        const glm::vec3 at = back > 0 ? bush.position[k - back] : spots[i % spots.size()];
        bush.addNode(at, 0, 0.05f, 1, glm::quat(1, 0, 0, 0));
    }
    bush.finalize();
    ColonizationParams p;
    p.influenceDistance = 7.0f;
    p.killDistance = 0.35f;
    p.segmentLength = 0.12f;
    p.randomness = 0.2f;
    for (std::uint64_t seed : {3u, 4u}) {
        p.seed = seed;
        const auto points = Envelope::ellipsoid({0, 4, 0}, {4, 3, 4}).sample(2501, seed);
        const ColonizationResult fast = colonize(points, p, &bush, NeighbourSearch::Accelerated);
        const ColonizationResult slow = colonize(points, p, &bush, NeighbourSearch::Naive);
        expectIdentical(fast.skeleton, slow.skeleton);
        EXPECT_EQ(fast.killed, slow.killed);
        EXPECT_EQ(fast.iterations, slow.iterations);
        EXPECT_GT(fast.skeleton.size(), bush.size() + 500);
    }
}

// The search's update against the oracle's on its own, bit for bit: the offers choose and keep
// a distance by the integer order of its bits (AVX-512), which must equal the float order for
// every distance they meet: points exactly on a node (+0), equal distances to mirrored and
// repeated nodes (the lowest index wins), distances from 1e-6 to past d_i, cells of every size
// (their padding lanes and the 32/16/masked blocks). Checked after every batch of nodes.
TEST(SpaceColonization, SearchUpdateEqualsNaiveOnTiesAndZeros) {
    Rng rng(29);
    for (int round = 0; round < 6; ++round) {
        const float di = 2.5f, dk = round % 2 == 0 ? 0.05f : 0.4f;
        std::vector<glm::vec3> nodes;
        for (int k = 0; k < 90; ++k) {
            const glm::vec3 at(static_cast<float>(rng.uniform(-3.0, 3.0)),
                               static_cast<float>(rng.uniform(-3.0, 3.0)),
                               static_cast<float>(rng.uniform(-3.0, 3.0)));
            nodes.push_back(at);
            if (k % 3 == 0) nodes.push_back({-at.x, at.y, at.z}); // ties for points on x = 0
            if (k % 5 == 0) nodes.push_back(at);                  // a repeated node
        }
        std::vector<glm::vec3> points;
        for (int a = 0; a < 1500 + 37 * round; ++a) {
            const int kind = a % 4;
            const glm::vec3 n = nodes[static_cast<std::size_t>(a) % nodes.size()];
            if (kind == 0) {
                points.push_back(n); // on a node: distance +0
            } else if (kind == 1) {
                points.push_back({0.0f, n.y, n.z}); // equally far from n and its mirror
            } else {
                const double r = kind == 2 ? 1e-6 * rng.uniform(1.0, 1e5) : rng.uniform(0.0, 4.0);
                points.push_back(n + glm::vec3(static_cast<float>(rng.uniform(-r, r)),
                                               static_cast<float>(rng.uniform(-r, r)),
                                               static_cast<float>(rng.uniform(-r, r))));
            }
        }
        const std::size_t n = points.size();
        std::vector<std::uint32_t> all(n);
        for (std::uint32_t a = 0; a < n; ++a)
            all[a] = a;
        auto state = [&] {
            return PointState{points, std::vector<float>(n, di * di),
                              std::vector<std::int32_t>(n, -1), std::vector<std::uint8_t>(n, 0),
                              all};
        };
        PointState fast = state(), slow = state();
        AcceleratedSearch search(points, di);
        std::vector<glm::vec3> offered;
        std::size_t firstNew = 0;
        for (std::size_t batch : {1u, 7u, 40u, 0u}) {
            const std::size_t end =
                batch == 0 ? nodes.size() : std::min(nodes.size(), firstNew + batch);
            offered.assign(nodes.begin(), nodes.begin() + static_cast<std::ptrdiff_t>(end));
            search.update(fast, offered, firstNew, dk * dk);
            updateNaive(slow, offered, di * di, dk * dk);
            ASSERT_EQ(fast.killed, slow.killed) << "round " << round << " batch " << batch;
            for (const std::uint32_t a : slow.live) {
                if (slow.killed[a] != 0) continue;
                ASSERT_EQ(std::bit_cast<std::uint32_t>(fast.best2[a]),
                          std::bit_cast<std::uint32_t>(slow.best2[a]))
                    << "round " << round << " point " << a;
                ASSERT_EQ(fast.bestNode[a], slow.bestNode[a])
                    << "round " << round << " point " << a;
            }
            dropKilled(fast);
            dropKilled(slow);
            firstNew = end;
        }
    }
}

// dropKilled (sixteen ids at a time with AVX-512, their flags gathered four bytes a flag)
// against erase_if on the flags: every live list of up to 70 of 40-80 points, kills dense and
// sparse, ids up to the last point (the blocks within three of the end go one by one).
TEST(SpaceColonization, DropKilledEqualsEraseIf) {
    Rng rng(17);
    for (int round = 0; round < 400; ++round) {
        const std::size_t points = 40 + rng.below(41);
        const std::vector<glm::vec3> none(points);
        PointState s{none, {}, {}, std::vector<std::uint8_t>(points, 0), {}};
        const double keep = rng.uniform(0.2, 1.0);
        for (std::uint32_t a = 0; a < points; ++a)
            if (rng.uniform(0.0, 1.0) < keep || a + 3 >= points) s.live.push_back(a);
        const double die = round % 4 == 0 ? 0.02 : rng.uniform(0.0, 0.9);
        for (const std::uint32_t a : s.live)
            s.killed[a] = rng.uniform(0.0, 1.0) < die ? 1 : 0;
        std::vector<std::uint32_t> expected = s.live;
        std::erase_if(expected, [&s](std::uint32_t a) { return s.killed[a] != 0; });
        dropKilled(s);
        ASSERT_EQ(s.live, expected) << "round " << round;
    }
}

TEST(SpaceColonization, EveryPointKilledOrOutOfReach) {
    const auto points = spherePoints(1000);
    const ColonizationParams p = referenceParams();
    const ColonizationResult r = colonize(points, p);
    expectEveryPointKilledOrOutOfReach(points, r, p);
    EXPECT_EQ(r.killedCount, points.size()); // a sphere in reach of its trunk is eaten whole
    EXPECT_EQ(r.stopReason, StopReason::NoPointsLeft);

    // A far cluster nobody reaches: it stays, and the growth stops for lack of reach.
    std::vector<glm::vec3> more = points;
    for (int i = 0; i < 20; ++i)
        more.push_back({40.0f + 0.1f * i, 6.0f, 0.0f});
    const ColonizationResult r2 = colonize(more, p);
    expectEveryPointKilledOrOutOfReach(more, r2, p);
    EXPECT_EQ(r2.stopReason, StopReason::NothingInReach);
    EXPECT_EQ(r2.killedCount, points.size());
}

TEST(SpaceColonization, NodesStayInsideEnvelopeGrownByOneSegment) {
    ColonizationParams p = referenceParams();
    for (float randomness : {0.0f, 0.147f}) {
        p.randomness = randomness;
        const glm::vec3 c(0, 6, 0);
        const float radius = 4.5f;
        const ColonizationResult r = colonize(spherePoints(1500), p);
        for (std::size_t i = r.initialNodes; i < r.skeleton.size(); ++i)
            ASSERT_LE(glm::length(r.skeleton.position[i] - c), radius + p.segmentLength + 1e-4f)
                << "node " << i << " randomness " << randomness;
    }
    // A cylinder: radial and vertical bounds.
    const auto points = Envelope::cylinder({0, 3, 0}, 1.2f, 6.0f).sample(1200, 3);
    p = referenceParams();
    p.influenceDistance = 1.5f;
    p.killDistance = 0.35f;
    p.segmentLength = 0.15f;
    p.trunkHeight = 3.0f;
    const ColonizationResult r = colonize(points, p);
    for (std::size_t i = r.initialNodes; i < r.skeleton.size(); ++i) {
        const glm::vec3 q = r.skeleton.position[i];
        ASSERT_LE(std::sqrt(q.x * q.x + q.z * q.z), 1.2f + p.segmentLength + 1e-4f);
        ASSERT_GE(q.y, 3.0f - p.segmentLength - 1e-4f);
        ASSERT_LE(q.y, 9.0f + p.segmentLength + 1e-4f);
    }
}

TEST(SpaceColonization, PipeModelHoldsAtEveryFork) {
    ColonizationParams p = referenceParams();
    const ColonizationResult r = colonize(spherePoints(1000), p);
    const skel::Skeleton& s = r.skeleton;
    std::vector<double> sum(s.size(), 0.0);
    std::vector<int> children(s.size(), 0);
    for (std::size_t i = 1; i < s.size(); ++i) {
        sum[static_cast<std::size_t>(s.parent[i])] +=
            std::pow(double(s.radius[i]), double(p.pipeExponent));
        ++children[static_cast<std::size_t>(s.parent[i])];
    }
    int forks = 0;
    for (std::size_t i = 0; i < s.size(); ++i) {
        if (children[i] == 0) {
            EXPECT_FLOAT_EQ(s.radius[i], p.tipRadius);
            continue;
        }
        forks += children[i] > 1;
        const double lhs = std::pow(double(s.radius[i]), double(p.pipeExponent));
        ASSERT_NEAR(lhs, sum[i], 1e-4 * lhs) << "node " << i;
    }
    EXPECT_GT(forks, 50);
    EXPECT_GT(s.radius[0], 5 * p.tipRadius);
}

TEST(PipeModel, HandComputed) {
    skel::Skeleton s;
    const glm::quat q(1, 0, 0, 0);
    s.addNode({0, 0, 0}, -1, 0, 0, q);
    s.addNode({0, 1, 0}, 0, 0, 0, q);
    s.addNode({1, 2, 0}, 1, 0, 0, q);
    s.addNode({-1, 2, 0}, 1, 0, 1, q);
    s.addNode({0, 3, 0}, 1, 0, 1, q, skel::kHidden); // pruned: does not feed its parent
    applyPipeModel(s, 0.5f, 2.0f);
    EXPECT_FLOAT_EQ(s.radius[2], 0.5f);
    EXPECT_FLOAT_EQ(s.radius[3], 0.5f);
    EXPECT_FLOAT_EQ(s.radius[4], 0.5f);
    EXPECT_FLOAT_EQ(s.radius[1], std::sqrt(0.5f)); // sqrt(0.25 + 0.25)
    EXPECT_FLOAT_EQ(s.radius[0], std::sqrt(0.5f));
    applyPipeModel(s, 0.5f, 1.0f);
    EXPECT_FLOAT_EQ(s.radius[1], 1.0f);
    EXPECT_THROW(applyPipeModel(s, 0.5f, 0.9f), InvalidInput);
    EXPECT_THROW(applyPipeModel(s, 0.5f, 4.1f), InvalidInput);
    EXPECT_THROW(applyPipeModel(s, 0.0f, 2.0f), InvalidInput);
}

// The pipe model as it was written before its pow calls were saved (a tip's r^e once, r * r
// for the exponent 2): the radii must be the same bits, on random trees with hidden nodes, for
// the exponent 2 and others, and for tip radii whose squares are powers of two.
TEST(PipeModel, SameBitsAsPowEveryNode) {
    std::uint64_t state = 0x9E3779B97F4A7C15ull;
    auto next = [&state] {
        state = state * 6364136223846793005ull + 1442695040888963407ull;
        return static_cast<std::uint32_t>(state >> 33);
    };
    const glm::quat q(1, 0, 0, 0);
    int checked = 0;
    for (int t = 0; t < 12; ++t) {
        skel::Skeleton s;
        s.addNode({0, 0, 0}, -1, 0, 0, q);
        for (int i = 1; i < 3000; ++i) {
            // Chains and forks: the parent among the last few nodes, or anywhere.
            const auto size = static_cast<std::uint32_t>(s.size());
            const std::uint32_t back =
                next() % 4 == 0 ? next() % size : next() % std::min(size, 3u);
            const auto parent = static_cast<std::int32_t>(size - 1 - back);
            s.addNode({0, float(i), 0}, parent, 0, 0, q, next() % 17 == 0 ? skel::kHidden : 0);
        }
        const float tips[] = {0.013f, 0.5f, 0.25f, 1.0f / 3.0f, 7.9f, 1e-6f};
        const float others[] = {2.5f, 1.0f, 3.0f, 1.5f, 4.0f, 2.2f};
        const float tip = tips[t % 6];
        const float e = t < 6 ? 2.0f : others[t % 6]; // every tip radius with the exponent 2
        applyPipeModel(s, tip, e);
        std::vector<double> sum(s.size(), 0.0);
        for (std::size_t k = s.size(); k-- > 0;) {
            const float r = sum[k] > 0.0 ? static_cast<float>(std::pow(sum[k], 1.0 / e)) : tip;
            ASSERT_EQ(std::memcmp(&r, &s.radius[k], sizeof r), 0)
                << "tree " << t << " node " << k << ": " << r << " vs " << s.radius[k];
            const std::int32_t p = s.parent[k];
            if (p >= 0 && (s.flags[k] & skel::kHidden) == 0)
                sum[static_cast<std::size_t>(p)] += std::pow(static_cast<double>(r), double(e));
            ++checked;
        }
    }
    EXPECT_EQ(checked, 12 * 3000);
}

// The pipe model's radius for the exponent 2 against the float of pow(x, 1/2) it stands for,
// where the float's rounding is closest to a tie: the squares of the midpoints between adjacent
// floats (their root is exactly the midpoint, which pow returns and which rounds to even) and
// the doubles a few steps either side, then random sums of squares.
TEST(PipeModel, FloatSquareRootIsTheFloatOfPow) {
    std::uint64_t state = 0x243F6A8885A308D3ull;
    auto next = [&state] {
        state = state * 6364136223846793005ull + 1442695040888963407ull;
        return state >> 11;
    };
    auto same = [](double x) {
        const float want = static_cast<float>(std::pow(x, 0.5));
        const float got = floatSquareRoot(x);
        return std::memcmp(&want, &got, sizeof want) == 0;
    };
    int checked = 0;
    for (int i = 0; i < 20000; ++i) {
        // A float in [1e-6, 10), the midpoint to the next one, exact in double, and its square
        // (25 bits squared: exact too).
        const auto a = static_cast<float>(1e-6 + 10.0 * static_cast<double>(next()) * 0x1.0p-53);
        const double m =
            (static_cast<double>(a) +
             static_cast<double>(std::nextafter(a, std::numeric_limits<float>::max()))) /
            2.0;
        const double x = m * m;
        for (int step = -6; step <= 6; ++step) {
            const double y = std::bit_cast<double>(std::bit_cast<std::uint64_t>(x) +
                                                   static_cast<std::uint64_t>(step));
            ASSERT_TRUE(same(y)) << "x " << y;
            ++checked;
        }
        double sum = 0.0;
        for (std::uint64_t c = next() % 5; c-- > 0;) {
            const auto r =
                static_cast<double>(static_cast<float>(static_cast<double>(next()) * 0x1.0p-53));
            sum += r * r;
        }
        if (sum > 0.0) {
            ASSERT_TRUE(same(sum)) << "sum " << sum;
        }
    }
    EXPECT_EQ(checked, 20000 * 13);
}

TEST(SpaceColonization, SameResultOnOneAndTwoThreads) {
    // Large enough for the parallel path to engage.
    const auto points = spherePoints(8000, 11);
    const ColonizationParams p = referenceParams();
    const int saved = omp_get_max_threads();
    omp_set_num_threads(1);
    const ColonizationResult one = colonize(points, p);
    omp_set_num_threads(2);
    const ColonizationResult two = colonize(points, p);
    omp_set_num_threads(saved);
    expectIdentical(one.skeleton, two.skeleton);
    // And the same seed twice is the same tree; another seed is another tree.
    ColonizationParams q = p;
    q.seed = 99;
    EXPECT_NE(colonize(points, q).skeleton.position, one.skeleton.position);
}

TEST(SpaceColonization, ZeroAverageAttractionIsResolved) {
    // One node exactly between two points: the unit vectors cancel.
    skel::Skeleton start;
    start.addNode({0, 0, 0}, -1, 0.01f, 0, glm::quat(1, 0, 0, 0));
    const std::vector<glm::vec3> points = {{1, 0, 0}, {-1, 0, 0}};
    ColonizationParams p;
    p.influenceDistance = 3.0f;
    p.killDistance = 0.3f;
    p.segmentLength = 0.1f;
    p.randomness = 0.0f;
    const ColonizationResult r = colonize(points, p, &start);
    EXPECT_GE(r.zeroAverageFixes, 1u);
    EXPECT_EQ(r.killedCount, 2u);
    EXPECT_EQ(r.stopReason, StopReason::NoPointsLeft);
    // The tie goes to the lower point index: the first step heads to +X.
    EXPECT_FLOAT_EQ(r.skeleton.position[1].x, 0.1f);
    expectIdentical(r.skeleton, colonize(points, p, &start, NeighbourSearch::Naive).skeleton);
}

TEST(SpaceColonization, TwoPointOscillationIsResolved) {
    // Two points almost opposite: the mean steps sideways by D, neither point comes closer to
    // the child than to the node, so the node would sprout the same child again and again.
    skel::Skeleton start;
    start.addNode({0, 0, 0}, -1, 0.01f, 0, glm::quat(1, 0, 0, 0));
    const std::vector<glm::vec3> points = {{1, 0.02f, 0}, {-1, 0.02f, 0}};
    ColonizationParams p;
    p.influenceDistance = 3.0f;
    p.killDistance = 0.3f;
    p.segmentLength = 0.1f;
    p.randomness = 0.0f;
    p.maxIterations = 200;
    const ColonizationResult r = colonize(points, p, &start);
    EXPECT_GE(r.oscillationFixes, 1u);
    EXPECT_EQ(r.killedCount, 2u);
    EXPECT_EQ(r.stopReason, StopReason::NoPointsLeft);
    EXPECT_LT(r.skeleton.size(), 40u); // ~2 × (1 - 0.3) / 0.1 steps plus the fork, no brush
    for (std::size_t i = 0; i < r.skeleton.size(); ++i)
        for (std::size_t j = i + 1; j < r.skeleton.size(); ++j)
            EXPECT_GT(distance2(r.skeleton.position[i], r.skeleton.position[j]), 1e-8f)
                << "duplicate nodes " << i << " and " << j;
    expectIdentical(r.skeleton, colonize(points, p, &start, NeighbourSearch::Naive).skeleton);
}

TEST(SpaceColonization, ContinuesFromInitialSkeleton) {
    // A bent trunk standing in for an L-system's: 12 nodes with orders and orientations.
    skel::Skeleton trunk;
    trunk.addNode({0, 0, 0}, -1, 0.2f, 0, glm::quat(1, 0, 0, 0));
    for (int i = 1; i < 10; ++i)
        trunk.addNode({0.05f * i, 0.4f * i, 0}, i - 1, 0.1f, 0, glm::quat(1, 0, 0, 0));
    trunk.addNode({0.6f, 3.0f, 0}, 7, 0.05f, 1, glm::quat(1, 0, 0, 0)); // a side branch
    trunk.leaves.push_back({{0.6f, 3.0f, 0}, glm::quat(1, 0, 0, 0), 0.1f, 10});
    trunk.finalize();
    const auto points = spherePoints(900);
    const ColonizationParams p = referenceParams();
    const ColonizationResult r = colonize(points, p, &trunk);
    const ColonizationResult slow = colonize(points, p, &trunk, NeighbourSearch::Naive);
    expectIdentical(r.skeleton, slow.skeleton);
    ASSERT_EQ(r.initialNodes, trunk.size());
    ASSERT_GT(r.skeleton.size(), trunk.size() + 100);
    for (std::size_t i = 0; i < trunk.size(); ++i) {
        EXPECT_EQ(r.skeleton.position[i], trunk.position[i]);
        EXPECT_EQ(r.skeleton.parent[i], trunk.parent[i]);
        EXPECT_EQ(r.skeleton.order[i], trunk.order[i]);
    }
    EXPECT_EQ(r.skeleton.leaves.size(), 1u);
    // Every new node descends from the trunk; no new root.
    for (std::size_t i = trunk.size(); i < r.skeleton.size(); ++i)
        EXPECT_GE(r.skeleton.parent[i], 0);
    expectEveryPointKilledOrOutOfReach(points, r, p);
}

TEST(SpaceColonization, ClearTrunkGrowsNoShootFromTheLowerTrunk) {
    // Issue #44: the oak's lower trunk carried sprays. A straight trunk of 3 m under a crown
    // that reaches down to 1.5 m: with clear_trunk 2.5, no shoot leaves the trunk below 2.5 m
    // (accelerated and naive alike); without it, some do.
    skel::Skeleton trunk;
    trunk.addNode({0, 0, 0}, -1, 0.2f, 0, glm::quat(1, 0, 0, 0));
    for (int i = 1; i <= 6; ++i)
        trunk.addNode({0, 0.5f * i, 0}, i - 1, 0.1f, 0, glm::quat(1, 0, 0, 0));
    trunk.finalize();
    const auto points = spherePoints(900); // a sphere of 4.5 m round (0, 6, 0)
    ColonizationParams p = referenceParams();
    auto lowShoots = [&](const ColonizationResult& r) {
        int n = 0;
        for (std::size_t i = trunk.size(); i < r.skeleton.size(); ++i) {
            const auto parent = static_cast<std::size_t>(r.skeleton.parent[i]);
            n += parent < trunk.size() && trunk.position[parent].y < 2.5f ? 1 : 0;
        }
        return n;
    };
    EXPECT_GT(lowShoots(colonize(points, p, &trunk)), 0);
    p.clearTrunk = 2.5f;
    const ColonizationResult r = colonize(points, p, &trunk);
    expectIdentical(r.skeleton, colonize(points, p, &trunk, NeighbourSearch::Naive).skeleton);
    EXPECT_EQ(lowShoots(r), 0);
    EXPECT_GT(r.skeleton.size(), trunk.size() + 100);
    p.clearTrunk = -1.0f;
    EXPECT_THROW(colonize(points, p, &trunk), InvalidInput);
}

TEST(SpaceColonization, TrunkReachesTheCrown) {
    ColonizationParams p = referenceParams();
    p.trunkHeight = 1.0f; // too short: the trunk grows on until the crown is in reach
    const auto points = Envelope::sphere({0, 10, 0}, 3.0f).sample(500, 2);
    const ColonizationResult r = colonize(points, p);
    ASSERT_GT(r.initialNodes, 6u);
    const glm::vec3 top = r.skeleton.position[r.initialNodes - 1];
    float best = INFINITY;
    for (const glm::vec3& a : points)
        best = std::min(best, distance2(a, top));
    EXPECT_LT(best, p.influenceDistance * p.influenceDistance);
    // ... and not one segment more.
    const glm::vec3 below = r.skeleton.position[r.initialNodes - 2];
    for (const glm::vec3& a : points)
        EXPECT_GE(distance2(a, below), p.influenceDistance * p.influenceDistance);
    for (std::size_t i = 0; i < r.initialNodes; ++i)
        EXPECT_EQ(r.skeleton.order[i], 0);
}

TEST(SpaceColonization, ValidationMessagesNameTheRange) {
    auto message = [](ColonizationParams p) -> std::string {
        try {
            validate(p);
        } catch (const InvalidInput& e) {
            return e.what();
        }
        return "";
    };
    ColonizationParams p;
    EXPECT_EQ(message(p), "");
    p.killDistance = 3.0f;
    EXPECT_NE(message(p).find("kill_distance must be smaller than influence_distance"),
              std::string::npos);
    p = {};
    p.killDistance = 0.2f;
    EXPECT_NE(message(p).find("kill_distance must be larger than segment_length"),
              std::string::npos);
    p = {};
    p.segmentLength = -1.0f;
    EXPECT_NE(message(p).find("segment_length"), std::string::npos);
    p = {};
    p.influenceDistance = NAN;
    EXPECT_NE(message(p).find("influence_distance"), std::string::npos);
    p = {};
    p.influenceDistance = INFINITY;
    EXPECT_NE(message(p).find("influence_distance"), std::string::npos);
    p = {};
    p.randomness = 1.5f;
    EXPECT_NE(message(p).find("randomness must be in [0, 1]"), std::string::npos);
    p = {};
    p.pipeExponent = 0.5f;
    EXPECT_NE(message(p).find("pipe_exponent must be in [1, 4]"), std::string::npos);
    p = {};
    p.tipRadius = 0.0f;
    EXPECT_NE(message(p).find("tip_radius"), std::string::npos);
    p = {};
    p.maxIterations = 0;
    EXPECT_NE(message(p).find("max_iterations"), std::string::npos);
    p = {};
    p.tropism = {0, -0.9f, 0.9f};
    EXPECT_NE(message(p).find("tropism"), std::string::npos);
    p = {};
    p.trunkHeight = -1.0f;
    EXPECT_NE(message(p).find("trunk_height"), std::string::npos);
    // colonize() validates too, and rejects non-finite points.
    p = {};
    p.killDistance = 5.0f;
    EXPECT_THROW(colonize(spherePoints(10), p), InvalidInput);
    EXPECT_THROW(colonize({{0, NAN, 0}}, ColonizationParams{}), InvalidInput);
}

TEST(PointGrid, RadiusQueryMatchesBruteForce) {
    const auto points = spherePoints(3000, 4);
    const PointGrid grid(points, 0.7f);
    for (const glm::vec3 c : {glm::vec3(0, 6, 0), glm::vec3(3, 8, -1), glm::vec3(10, 0, 0)}) {
        for (float r : {0.3f, 1.0f, 2.5f}) {
            std::vector<std::uint32_t> got, want;
            grid.forEachInRadius(c, r, [&](std::uint32_t i, float) { got.push_back(i); });
            for (std::uint32_t i = 0; i < points.size(); ++i)
                if (distance2(points[i], c) < r * r) want.push_back(i);
            std::sort(got.begin(), got.end());
            EXPECT_EQ(got, want);
        }
    }
    // Cell bounds bound every point of the cell.
    for (const PointGrid::Cell& cell : grid.cells())
        for (std::uint32_t k = cell.begin; k < cell.end; ++k)
            EXPECT_LE(PointGrid::boxDistance2(cell, {1, 2, 3}),
                      distance2(points[grid.order()[k]], {1, 2, 3}));
}
