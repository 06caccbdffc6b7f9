// Resource allocation of the self-organizing model against hand-computed values and
// brute-force oracles.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>

#include "engine/growth/allocation.h"
#include "engine/util/random.h"

using namespace sylva::growth;

namespace {

/// A metamer tree in the form the allocation functions read.
struct Tree {
    std::vector<std::int32_t> parent, mainChild, lateralChild;
    std::vector<std::uint16_t> tree;
    std::vector<double> terminal, axillary;

    std::int32_t add(std::int32_t p, bool lateral, std::uint16_t t = 0) {
        const auto i = static_cast<std::int32_t>(parent.size());
        parent.push_back(p);
        mainChild.push_back(-1);
        lateralChild.push_back(-1);
        tree.push_back(t);
        terminal.push_back(0.0);
        axillary.push_back(0.0);
        if (p >= 0) (lateral ? lateralChild : mainChild)[static_cast<std::size_t>(p)] = i;
        return i;
    }
    MetamerTopology topo() const { return {parent, mainChild, lateralChild, tree}; }
    /// Light of every bud at a free slot, random in [0, 1) (some exactly 0).
    void randomLight(sylva::Rng& rng) {
        for (std::size_t i = 0; i < parent.size(); ++i) {
            terminal[i] = mainChild[i] < 0 ? (rng.below(5) == 0 ? 0.0 : rng.uniform()) : 0.0;
            axillary[i] = lateralChild[i] < 0 ? (rng.below(5) == 0 ? 0.0 : rng.uniform()) : 0.0;
        }
    }
};

/// A random metamer tree (or several) of about n metamers.
Tree randomTree(std::uint64_t seed, int n, int trees = 1) {
    sylva::Rng rng(seed);
    Tree t;
    for (int k = 0; k < trees; ++k)
        t.add(-1, false, static_cast<std::uint16_t>(k));
    while (static_cast<int>(t.parent.size()) < n) {
        const auto p = static_cast<std::int32_t>(rng.below(t.parent.size()));
        const bool lateral = rng.below(2) == 1;
        const auto& slot = lateral ? t.lateralChild : t.mainChild;
        if (slot[static_cast<std::size_t>(p)] >= 0) continue;
        t.add(p, lateral, t.tree[static_cast<std::size_t>(p)]);
    }
    t.randomLight(rng);
    return t;
}

std::vector<double> gathered(const Tree& t) {
    std::vector<double> g(t.parent.size());
    std::vector<std::int32_t> c(t.parent.size());
    gatherLight(t.topo(), t.terminal, t.axillary, g, c);
    return g;
}

void expectRel(double actual, double expected, double rel = 1e-9) {
    EXPECT_NEAR(actual, expected, rel * std::max(1.0, std::fabs(expected)));
}

} // namespace

TEST(SelfOrgAllocation, GatherLightHandComputed) {
    // 0 ─main─ 1 (terminal 1.0, axillary 0.5)
    //  └lateral─ 2 ─main─ 3 (terminal 0.25, axillary 0)
    //             (2: axillary 0.125)
    Tree t;
    t.add(-1, false);
    t.add(0, false);
    t.add(0, true);
    t.add(2, false);
    t.terminal = {0, 1.0, 0, 0.25};
    t.axillary = {0, 0.5, 0.125, 0};
    std::vector<double> g(4);
    std::vector<std::int32_t> c(4);
    gatherLight(t.topo(), t.terminal, t.axillary, g, c);
    EXPECT_DOUBLE_EQ(g[0], 1.875);
    EXPECT_DOUBLE_EQ(g[1], 1.5);
    EXPECT_DOUBLE_EQ(g[2], 0.375);
    EXPECT_DOUBLE_EQ(g[3], 0.25);
    EXPECT_EQ(c[0], 4);
    EXPECT_EQ(c[2], 2);

    // Borchert–Honda by hand, α = 2, λ = 0.6: v0 = 3.75; at 0: Qm = 1.5, Ql = 0.375,
    // v1 = 3.75·0.9/(0.9+0.15), v2 = 3.75·0.15/1.05.
    const AllocationParams p{2.0, 0.6};
    const Vigour v = allocateBorchertHonda(t.topo(), g, t.terminal, t.axillary, {&p, 1});
    EXPECT_DOUBLE_EQ(v.metamer[0], 3.75);
    EXPECT_NEAR(v.metamer[1], 3.75 * 0.9 / 1.05, 1e-12);
    EXPECT_NEAR(v.metamer[2], 3.75 * 0.15 / 1.05, 1e-12);
    // At 1: Qm = 1 (terminal), Ql = 0.5: terminal gets 0.6/(0.6+0.2).
    EXPECT_NEAR(v.terminal[1], v.metamer[1] * 0.75, 1e-12);
    EXPECT_NEAR(v.axillary[1], v.metamer[1] * 0.25, 1e-12);
    // At 3: the axillary bud has no light, so the terminal bud gets everything.
    EXPECT_DOUBLE_EQ(v.terminal[3], v.metamer[3]);
    EXPECT_EQ(v.axillary[3], 0.0);
}

TEST(SelfOrgAllocation, BorchertHondaConservesAtEveryFork) {
    for (std::uint64_t seed = 1; seed <= 5; ++seed) {
        const Tree t = randomTree(seed, 3000, 3);
        const std::vector<double> g = gathered(t);
        const std::vector<AllocationParams> p = {{2.0, 0.5}, {1.3, 0.8}, {3.0, 0.2}};
        const Vigour v = allocateBorchertHonda(t.topo(), g, t.terminal, t.axillary, p);
        for (std::size_t i = 0; i < t.parent.size(); ++i) {
            const double m = t.mainChild[i] >= 0
                                 ? v.metamer[static_cast<std::size_t>(t.mainChild[i])]
                                 : v.terminal[i];
            const double l = t.lateralChild[i] >= 0
                                 ? v.metamer[static_cast<std::size_t>(t.lateralChild[i])]
                                 : v.axillary[i];
            if (g[i] > 0) expectRel(m + l, v.metamer[i]);
            if (t.parent[i] < 0) expectRel(v.metamer[i], p[t.tree[i]].alpha * g[i]);
        }
    }
}

TEST(SelfOrgAllocation, LinearPassEqualsPathProductOracle) {
    const Tree t = randomTree(42, 2000, 2);
    const std::vector<double> g = gathered(t);
    const std::vector<AllocationParams> p = {{2.0, 0.65}, {1.5, 0.35}};
    const Vigour fast = allocateBorchertHonda(t.topo(), g, t.terminal, t.axillary, p);
    const Vigour slow = allocateBorchertHondaNaive(t.topo(), t.terminal, t.axillary, p);
    for (std::size_t i = 0; i < t.parent.size(); ++i) {
        expectRel(fast.metamer[i], slow.metamer[i]);
        expectRel(fast.terminal[i], slow.terminal[i]);
        expectRel(fast.axillary[i], slow.axillary[i]);
    }
}

TEST(SelfOrgAllocation, LambdaLimits) {
    const Tree t = randomTree(7, 500);
    const std::vector<double> g = gathered(t);
    // λ = 1: a lateral side gets nothing whenever the axis side has light.
    AllocationParams one{2.0, 1.0};
    Vigour v = allocateBorchertHonda(t.topo(), g, t.terminal, t.axillary, {&one, 1});
    for (std::size_t i = 0; i < t.parent.size(); ++i) {
        const double qm =
            t.mainChild[i] >= 0 ? g[static_cast<std::size_t>(t.mainChild[i])] : t.terminal[i];
        if (qm <= 0) continue;
        const double l = t.lateralChild[i] >= 0
                             ? v.metamer[static_cast<std::size_t>(t.lateralChild[i])]
                             : v.axillary[i];
        EXPECT_EQ(l, 0.0) << i;
    }
    // λ = 0: the axis gets nothing whenever the lateral side has light.
    AllocationParams zero{2.0, 0.0};
    v = allocateBorchertHonda(t.topo(), g, t.terminal, t.axillary, {&zero, 1});
    for (std::size_t i = 0; i < t.parent.size(); ++i) {
        const double ql =
            t.lateralChild[i] >= 0 ? g[static_cast<std::size_t>(t.lateralChild[i])] : t.axillary[i];
        if (ql <= 0) continue;
        const double m = t.mainChild[i] >= 0 ? v.metamer[static_cast<std::size_t>(t.mainChild[i])]
                                             : v.terminal[i];
        EXPECT_EQ(m, 0.0) << i;
    }
    // λ → 1 continuously: the lateral share of the root fork goes to 0 like (1−λ).
    Tree chain;
    chain.add(-1, false);
    chain.terminal = {1.0};
    chain.axillary = {1.0};
    const std::vector<double> gc = gathered(chain);
    for (double lambda : {0.9, 0.99, 0.999999}) {
        AllocationParams p{1.0, lambda};
        const Vigour c =
            allocateBorchertHonda(chain.topo(), gc, chain.terminal, chain.axillary, {&p, 1});
        EXPECT_NEAR(c.axillary[0], 2.0 * (1 - lambda), 1e-12);
        EXPECT_NEAR(c.terminal[0], 2.0 * lambda, 1e-12);
    }
}

TEST(SelfOrgAllocation, PriorityRanksAndConserves) {
    // One metamer: terminal Q = 1, axillary Q = 0.5; w_max = 1, w_min = 0.2, κ = 1:
    // ranks 0, 1 → weights 1 and 1 − 0.8·(1/2) = 0.6; v_base = 2·1.5 = 3;
    // v_t = 3·1/(1 + 0.3), v_a = 3·0.3/1.3.
    Tree t;
    t.add(-1, false);
    t.terminal = {1.0};
    t.axillary = {0.5};
    AllocationParams p{2.0, 0.5, 0.2, 1.0, 1.0};
    const std::vector<double> g = gathered(t);
    const Vigour v = allocatePriority(t.topo(), g, t.terminal, t.axillary, {&p, 1});
    EXPECT_NEAR(v.terminal[0], 3.0 / 1.3, 1e-12);
    EXPECT_NEAR(v.axillary[0], 0.9 / 1.3, 1e-12);

    const Tree r = randomTree(9, 2000, 2);
    const std::vector<double> gr = gathered(r);
    const std::vector<AllocationParams> pr = {{2.0, 0.5, 0.06, 1.0, 0.5},
                                              {1.0, 0.5, 0.5, 2.0, 0.2}};
    const Vigour vr = allocatePriority(r.topo(), gr, r.terminal, r.axillary, pr);
    for (std::size_t i = 0; i < r.parent.size(); ++i) {
        const double m = r.mainChild[i] >= 0 ? vr.metamer[static_cast<std::size_t>(r.mainChild[i])]
                                             : vr.terminal[i];
        const double l = r.lateralChild[i] >= 0
                             ? vr.metamer[static_cast<std::size_t>(r.lateralChild[i])]
                             : vr.axillary[i];
        expectRel(m + l, vr.metamer[i]);
        if (r.parent[i] < 0) expectRel(vr.metamer[i], pr[r.tree[i]].alpha * gr[i]);
    }
    // Per unit of light, a brighter bud never gets less than a darker one of the same tree.
    double lastRatio = 1e300, lastQ = 2.0;
    std::vector<std::pair<double, double>> qv;
    for (std::size_t i = 0; i < r.parent.size(); ++i)
        if (r.tree[i] == 0) {
            if (r.mainChild[i] < 0 && r.terminal[i] > 0)
                qv.push_back({r.terminal[i], vr.terminal[i]});
            if (r.lateralChild[i] < 0 && r.axillary[i] > 0)
                qv.push_back({r.axillary[i], vr.axillary[i]});
        }
    std::sort(qv.begin(), qv.end(), [](auto& a, auto& b) { return a.first > b.first; });
    for (const auto& [q, vig] : qv) {
        ASSERT_LE(q, lastQ);
        if (q < lastQ) {
            EXPECT_LE(vig / q, lastRatio * (1 + 1e-12));
        }
        lastRatio = vig / q;
        lastQ = q;
    }
}

TEST(SelfOrgAllocation, ShedMarksExactlyTheDimBranches) {
    for (std::uint64_t seed = 1; seed <= 4; ++seed) {
        const Tree t = randomTree(seed * 31, 1500, 2);
        const std::size_t n = t.parent.size();
        // Oracle: recursive subtree sums, independent of gatherLight.
        std::function<void(std::int32_t, double&, int&)> sub = [&](std::int32_t i, double& q,
                                                                   int& c) {
            const auto u = static_cast<std::size_t>(i);
            q += (t.mainChild[u] < 0 ? t.terminal[u] : 0) +
                 (t.lateralChild[u] < 0 ? t.axillary[u] : 0);
            ++c;
            if (t.mainChild[u] >= 0) sub(t.mainChild[u], q, c);
            if (t.lateralChild[u] >= 0) sub(t.lateralChild[u], q, c);
        };
        const std::vector<double> thr = {0.3, 0.45};
        std::vector<std::uint8_t> dim(n, 0);
        for (std::size_t i = 0; i < n; ++i) {
            const std::int32_t p = t.parent[i];
            if (p < 0 ||
                t.lateralChild[static_cast<std::size_t>(p)] != static_cast<std::int32_t>(i))
                continue;
            double q = 0;
            int c = 0;
            sub(static_cast<std::int32_t>(i), q, c);
            dim[i] = q / c < thr[t.tree[i]];
        }
        std::vector<double> g(n);
        std::vector<std::int32_t> c(n);
        gatherLight(t.topo(), t.terminal, t.axillary, g, c);
        const std::vector<std::uint8_t> removed = markShed(t.topo(), g, c, thr);
        std::size_t count = 0;
        for (std::size_t i = 0; i < n; ++i) {
            bool expected = false;
            for (std::int32_t j = static_cast<std::int32_t>(i); j >= 0;
                 j = t.parent[static_cast<std::size_t>(j)])
                expected = expected || dim[static_cast<std::size_t>(j)];
            EXPECT_EQ(removed[i] != 0, expected) << "seed " << seed << " metamer " << i;
            count += removed[i];
        }
        EXPECT_GT(count, 0u);
        EXPECT_LT(count, n);
        for (std::size_t i = 0; i < n; ++i)
            if (t.parent[i] < 0) {
                EXPECT_EQ(removed[i], 0);
            }
    }
}

TEST(SelfOrgAllocation, OnePassShedEqualsGatherMarkAndRegather) {
    for (std::uint64_t seed = 1; seed <= 6; ++seed) {
        const Tree t = randomTree(seed * 97, 3000, 2);
        const std::size_t n = t.parent.size();
        const std::vector<double> thr = {0.3, 0.45};
        // The separate steps: gather, mark, then gather again over the tree that remains.
        std::vector<double> g(n);
        std::vector<std::int32_t> c(n);
        gatherLight(t.topo(), t.terminal, t.axillary, g, c);
        const std::vector<std::uint8_t> removed = markShed(t.topo(), g, c, thr);
        Tree kept;
        std::vector<std::int32_t> remap(n, -1);
        for (std::size_t i = 0; i < n; ++i) {
            if (removed[i]) continue;
            const std::int32_t p = t.parent[i];
            const bool lateral = p >= 0 && t.lateralChild[static_cast<std::size_t>(p)] ==
                                               static_cast<std::int32_t>(i);
            remap[i] =
                kept.add(p < 0 ? -1 : remap[static_cast<std::size_t>(p)], lateral, t.tree[i]);
            kept.terminal.back() = t.terminal[i];
            kept.axillary.back() = t.axillary[i];
        }
        std::vector<double> gk(kept.parent.size());
        std::vector<std::int32_t> ck(kept.parent.size());
        gatherLight(kept.topo(), kept.terminal, kept.axillary, gk, ck);

        std::vector<double> g1(n);
        std::vector<std::int32_t> c1(n);
        std::vector<std::uint8_t> marks(n);
        std::vector<ShedSums> scratch;
        const bool any =
            gatherLightAndMarkShed(t.topo(), t.terminal, t.axillary, thr, g1, c1, marks, scratch);
        std::size_t shed = 0;
        std::vector<std::uint8_t> gone(n, 0);
        for (std::size_t i = 0; i < n; ++i) {
            const std::int32_t p = t.parent[i];
            const bool lateral = p >= 0 && t.lateralChild[static_cast<std::size_t>(p)] ==
                                               static_cast<std::int32_t>(i);
            EXPECT_EQ((marks[i] & 2u) != 0, lateral) << "seed " << seed << " metamer " << i;
            gone[i] = (marks[i] & 1u) || (p >= 0 && gone[static_cast<std::size_t>(p)]);
            EXPECT_EQ(gone[i] != 0, removed[i] != 0) << "seed " << seed << " metamer " << i;
            shed += gone[i];
            if (!removed[i]) {
                // Bit for bit: the same additions in the same order.
                EXPECT_EQ(g1[i], gk[static_cast<std::size_t>(remap[i])]) << "metamer " << i;
                EXPECT_EQ(c1[i], ck[static_cast<std::size_t>(remap[i])]) << "metamer " << i;
            }
        }
        EXPECT_EQ(any, shed > 0);
        EXPECT_GT(shed, 0u);
        EXPECT_LT(shed, n);
    }
}
