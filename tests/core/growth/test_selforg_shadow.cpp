// The shadow propagation environment: pyramid values by hand, incremental == full.
#include <gtest/gtest.h>

#include <limits>
#include <string>
#include <vector>

#include <omp.h>

#include "engine/growth/selforganizing.h"
#include "engine/growth/shadowgrid.h"
#include "engine/util/error.h"
#include "engine/util/random.h"
#include "selforgparams.h"

using namespace sylva::growth;

namespace {
double s(const ShadowGrid& g, int x, int y, int z) {
    return g.shadow({x, y, z});
}
} // namespace

TEST(SelfOrgShadow, SingleBudPyramid) {
    // a = 1, b = 2, q_max = 3: Δs = 1, 1/2, 1/4, 1/8 at q = 0..3 within |dx|, |dz| <= q.
    ShadowGrid g(1.0f, -100.0f, 3);
    g.addPyramid({0, 10, 0}, ShadowKernel::make(1.0, 2.0, 3));
    EXPECT_DOUBLE_EQ(s(g, 0, 10, 0), 1.0);
    EXPECT_DOUBLE_EQ(s(g, 0, 9, 0), 0.5);
    EXPECT_DOUBLE_EQ(s(g, 1, 9, -1), 0.5);
    EXPECT_DOUBLE_EQ(s(g, 2, 8, 2), 0.25);
    EXPECT_DOUBLE_EQ(s(g, -3, 7, 3), 0.125);
    EXPECT_DOUBLE_EQ(s(g, 0, 7, 0), 0.125);
    // Outside the pyramid.
    EXPECT_EQ(s(g, 1, 10, 0), 0.0); // beside the bud
    EXPECT_EQ(s(g, 0, 11, 0), 0.0); // above
    EXPECT_EQ(s(g, 2, 9, 0), 0.0);  // p > q
    EXPECT_EQ(s(g, 0, 6, 0), 0.0);  // below q_max
    EXPECT_EQ(s(g, -4, 7, 0), 0.0);
    // a = 0.5, b = 3, q_max = 2.
    ShadowGrid h(0.5f, -100.0f, 2);
    h.addPyramid({3, 3, 3}, ShadowKernel::make(0.5, 3.0, 2));
    EXPECT_NEAR(s(h, 3, 3, 3), 0.5, 1e-4);
    EXPECT_NEAR(s(h, 4, 2, 2), 0.5 / 3, 1e-4);
    EXPECT_NEAR(s(h, 1, 1, 5), 0.5 / 9, 1e-4);
    // Voxel coordinates of points: floor(p / h).
    EXPECT_EQ(h.voxelOf({1.2f, -0.2f, 0.0f}), glm::ivec3(2, -1, 0));
}

TEST(SelfOrgShadow, TwoOverlappingBuds) {
    const ShadowKernel k = ShadowKernel::make(1.0, 2.0, 3);
    ShadowGrid g(1.0f, -100.0f, 3);
    g.addPyramid({0, 10, 0}, k);
    g.addPyramid({1, 9, 0}, k);
    EXPECT_DOUBLE_EQ(s(g, 1, 9, 0), 0.5 + 1.0);  // first q=1, second q=0
    EXPECT_DOUBLE_EQ(s(g, 0, 9, 0), 0.5);        // only the first
    EXPECT_DOUBLE_EQ(s(g, 1, 8, 0), 0.25 + 0.5); // q=2 and q=1
    EXPECT_DOUBLE_EQ(s(g, 2, 8, 1), 0.25 + 0.5);
    EXPECT_DOUBLE_EQ(s(g, 3, 8, 0), 0.0); // beyond both pyramids' width
    EXPECT_DOUBLE_EQ(s(g, 2, 7, 0), 0.125 + 0.25);
    EXPECT_DOUBLE_EQ(s(g, -2, 7, 0), 0.125);
    EXPECT_DOUBLE_EQ(s(g, 4, 6, 0), 0.125);
    EXPECT_DOUBLE_EQ(s(g, 0, 6, 0), 0.125); // below the first's reach, second q=3
    // Light of the lower bud: Q = C − s + a = 1 − 1.5 + 1.
    EXPECT_DOUBLE_EQ(1.0 - s(g, 1, 9, 0) + 1.0, 0.5);
    // Removing both gives zero everywhere, however the grid grew meanwhile.
    g.addPyramid({40, 30, -25}, k);
    EXPECT_DOUBLE_EQ(s(g, 1, 9, 0), 1.5);
    g.addPyramid({0, 10, 0}, k, -1);
    g.addPyramid({40, 30, -25}, k, -1);
    g.addPyramid({1, 9, 0}, k, -1);
    for (std::int32_t v : g.values())
        ASSERT_EQ(v, 0);
}

TEST(SelfOrgShadow, FloorClipsPyramids) {
    ShadowGrid g(1.0f, 0.0f, 4);
    g.addPyramid({0, 1, 0}, ShadowKernel::make(1.0, 2.0, 4));
    EXPECT_DOUBLE_EQ(s(g, 0, 0, 0), 0.5);
    EXPECT_DOUBLE_EQ(s(g, 0, -3, 0), 0.5); // below the floor reads the floor row
}

TEST(SelfOrgShadow, IncrementalEqualsFullRecomputation) {
    SelfOrganizingParams p;
    p.cycles = 14;
    p.sheddingThreshold = 0.3; // sheds a lot, so removals are exercised
    p.shadowDepth = 4;
    std::vector<StandTree> trees = {{{0, 0, 0}, p, 1}, {{0.8f, 0, 0.3f}, p, 2}};
    trees[1].params.shadowA = 0.7;
    trees[1].params.shadowB = 1.7;
    trees[1].params.shadowDepth = 6;
    trees[1].params.cycles = 9;
    // A small wall casting shadow too.
    std::vector<glm::vec3> wall = {{-1, 0, -1}, {-1, 2, -1}, {-1, 2, 1}};
    SelfOrganizingSimulation sim(trees, wall);
    std::size_t checked = 0;
    while (!sim.done()) {
        sim.step();
        ASSERT_TRUE(sim.shadowGrid()->sameShadow(sim.recomputeShadow())) << sim.cycle();
        ++checked;
    }
    EXPECT_EQ(checked, 14u);
    EXPECT_GT(sim.shedCount(), 0u);
    EXPECT_GT(sim.metamers().size(), 200u);
}

TEST(SelfOrgShadow, NaiveAndIncrementalGrowTheSameTree) {
    // A small tree, and a vigorous one large enough for the parallel loops and the batched
    // difference-array shadow update to take part. The naive run uses one thread, the
    // incremental one two, so this also checks the thread-count independence.
    const SelfOrganizingParams vigorous = test::vigorousParams(13);
    for (const SelfOrganizingParams& p : {SelfOrganizingParams{}, vigorous}) {
        SelfOrganizingSimulation a({{glm::vec3(0), p, 5}}, {});
        SelfOrganizingSimulation b({{glm::vec3(0), p, 5}}, {}, SimulationOptions{true, true});
        const int before = omp_get_max_threads();
        while (!a.done()) {
            omp_set_num_threads(2);
            a.step();
            omp_set_num_threads(1);
            b.step();
        }
        omp_set_num_threads(before);
        ASSERT_EQ(a.metamers().size(), b.metamers().size());
        for (std::size_t i = 0; i < a.metamers().size(); ++i) {
            ASSERT_EQ(a.metamers().end[i], b.metamers().end[i]);
            ASSERT_EQ(a.metamers().parent[i], b.metamers().parent[i]);
            ASSERT_EQ(a.metamers().deadBuds[i], b.metamers().deadBuds[i]);
        }
        EXPECT_EQ(a.shedCount(), b.shedCount());
        EXPECT_TRUE(a.shadowGrid()->sameShadow(*b.shadowGrid()));
        EXPECT_TRUE(a.shadowGrid()->sameShadow(a.recomputeShadow()));
        if (p.alpha == vigorous.alpha) {
            EXPECT_GT(a.metamers().size(), 3000u);
            EXPECT_GT(a.shedCount(), 500u);
        }
    }
}

TEST(SelfOrgShadow, LoneBudSeesFullLight) {
    SelfOrganizingParams p;
    p.fullExposure = 0.8;
    SelfOrganizingSimulation sim({{glm::vec3(0), p, 1}}, {});
    sim.step(); // plants the first metamer and grows
    std::vector<double> t, a;
    sim.evaluateLight(t, a);
    // Every bud's light is C minus the shadow of the others: never above C, and the lone
    // bud of a new tree has exactly C.
    for (std::size_t i = 0; i < t.size(); ++i) {
        EXPECT_LE(t[i], 0.8 + 1e-9);
        EXPECT_LE(a[i], 0.8 + 1e-9);
    }
}

TEST(SelfOrgShadow, BatchEqualsOnePyramidAtATime) {
    // Oracle: addPyramid per source. Mixed kernels, removals, sources below and at the floor,
    // a dense cluster (difference-array path) and scattered sources (direct path), on 1 and 2
    // threads.
    const std::vector<ShadowKernel> kernels = {ShadowKernel::make(1.0, 2.0, 5),
                                               ShadowKernel::make(0.3, 1.5, 2),
                                               ShadowKernel::make(2.0, 3.0, 0)};
    sylva::Rng rng(42);
    std::vector<ShadowSource> sources;
    for (int i = 0; i < 4000; ++i) {
        const bool dense = i < 3000;
        const int w = dense ? 6 : 60;
        const glm::ivec3 v(static_cast<int>(rng.below(static_cast<std::uint64_t>(w))) - w / 2,
                           static_cast<int>(rng.below(12)) - 3,
                           static_cast<int>(rng.below(static_cast<std::uint64_t>(w))) - w / 2);
        sources.push_back(
            {v, rng.uniform() < 0.3 ? -1 : 2, static_cast<std::uint32_t>(rng.below(3))});
    }
    ShadowGrid oracle(1.0f, 0.0f, 5);
    for (const ShadowSource& s : sources)
        oracle.addPyramid(s.voxel, kernels[s.kernel], s.weight);
    for (int threads : {1, 2}) {
        const int before = omp_get_max_threads();
        omp_set_num_threads(threads);
        ShadowGrid batch(1.0f, 0.0f, 5);
        batch.addPyramid({100, 20, 100}, kernels[0]); // grows the grid first
        batch.applyBatch(sources, kernels);
        batch.addPyramid({100, 20, 100}, kernels[0], -1);
        omp_set_num_threads(before);
        EXPECT_TRUE(batch.sameShadow(oracle)) << threads << " threads";
        // Applying the removals of everything returns the grid to zero.
        std::vector<ShadowSource> undo = sources;
        for (ShadowSource& s : undo)
            s.weight = -s.weight;
        batch.applyBatch(undo, kernels);
        for (std::int32_t v : batch.values())
            ASSERT_EQ(v, 0);
    }
    // Called from inside a parallel region (trees grown by a parallel caller): the inner team
    // has fewer threads than omp_get_max_threads() says, and the result is still exact.
    // (Twice the sources: enough for the batch to sort them in parallel.)
    {
        std::vector<ShadowSource> twice = sources;
        twice.insert(twice.end(), sources.begin(), sources.end());
        ShadowGrid twiceOracle(1.0f, 0.0f, 5);
        for (const ShadowSource& s : twice)
            twiceOracle.addPyramid(s.voxel, kernels[s.kernel], s.weight);
        ShadowGrid nested(1.0f, 0.0f, 5);
        const int before = omp_get_max_threads();
        omp_set_num_threads(2);
#pragma omp parallel num_threads(2)
        {
#pragma omp single
            nested.applyBatch(twice, kernels);
        }
        omp_set_num_threads(before);
        EXPECT_TRUE(nested.sameShadow(twiceOracle)) << "inside a parallel region";
    }
    // Scattered sources take the direct path.
    ShadowGrid sparse(1.0f, 0.0f, 5), sparseOracle(1.0f, 0.0f, 5);
    const std::vector<ShadowSource> few = {{{0, 9, 0}, 1, 0}, {{30, 4, -20}, -1, 1}};
    sparse.applyBatch(few, kernels);
    for (const ShadowSource& s : few)
        sparseOracle.addPyramid(s.voxel, kernels[s.kernel], s.weight);
    EXPECT_TRUE(sparse.sameShadow(sparseOracle));
}

TEST(SelfOrgShadow, NeighbourhoodMatchesVoxelLookups) {
    ShadowGrid g(1.0f, 0.0f, 3);
    const ShadowKernel k = ShadowKernel::make(1.0, 2.0, 3);
    g.addPyramid({0, 6, 0}, k);
    g.addPyramid({2, 4, 1}, k);
    g.setBlocked({1, 3, 1});
    // Inside (fast path), at the floor (clamped reads) and at the grid's edge (fallback).
    for (const glm::ivec3 c :
         {glm::ivec3(1, 4, 0), glm::ivec3(0, 0, 0), glm::ivec3(3, 7, 4), glm::ivec3(-3, 2, -3)}) {
        std::int32_t n[27];
        g.neighbourhood(c, n);
        for (int y = -1; y <= 1; ++y)
            for (int x = -1; x <= 1; ++x)
                for (int z = -1; z <= 1; ++z) {
                    const glm::ivec3 u = c + glm::ivec3(x, y, z);
                    const std::int32_t expect = g.blocked(u) ? ShadowGrid::kOpaque : g.raw(u);
                    ASSERT_EQ(n[(y + 1) * 9 + (x + 1) * 3 + (z + 1)], expect)
                        << c.x << "," << c.y << "," << c.z << " + " << x << "," << y << "," << z;
                }
    }
}

// The shadow grid's limit (2^28 voxels) is checked before the grid grows: two sources 2000
// voxels apart on every axis would need 8·10^9 voxels; 700 apart (3.4·10^8) too, which the old
// limit of 2^31 allowed (1.7 GB and the copy).
TEST(ShadowGrid, GrowingPastTheVoxelLimitThrowsBeforeAllocating) {
    {
        ShadowGrid g(0.01f, 0.0f, 2);
        const ShadowKernel k = ShadowKernel::make(1.0, 2.0, 2);
        g.addPyramid({0, 10, 0}, k);
        EXPECT_THROW(g.addPyramid({700, 700, 700}, k), sylva::LimitExceeded);
    }
    {
        // A batch large enough to be sorted on every thread: the limit is reached inside the
        // parallel region and must come out as the exception, not end the process (finding 17).
        ShadowGrid g(0.01f, 0.0f, 2);
        const std::vector<ShadowKernel> kernels = {ShadowKernel::make(1.0, 2.0, 2)};
        std::vector<ShadowSource> sources(5000);
        for (std::size_t i = 0; i < sources.size(); ++i)
            sources[i].voxel = glm::ivec3(int(i % 700), 10 + int(i % 690), int(i % 701));
        EXPECT_THROW(g.applyBatch(sources, kernels), sylva::LimitExceeded);
    }
    ShadowGrid g(0.01f, 0.0f, 2);
    const ShadowKernel k = ShadowKernel::make(1.0, 2.0, 2);
    g.addPyramid({0, 10, 0}, k);
    try {
        g.addPyramid({2000, 2000, 2000}, k);
        FAIL() << "no limit";
    } catch (const sylva::LimitExceeded& e) {
        const std::string m = e.what();
        EXPECT_NE(m.find("shadow grid would need "), std::string::npos) << m;
        EXPECT_NE(m.find("more than the limit of 268435456 (1.3 GB); use a larger voxel_size"),
                  std::string::npos)
            << m;
    }
}

// voxelsOf (four coordinates at a time) against voxelOf: random points, points on voxel faces
// (exact multiples, where the floor must not step down), negative ones, beyond 2^23 voxels
// (already integers), beyond the int range, infinities and NaN, tails of every length.
TEST(ShadowGrid, VoxelsOfEqualsVoxelOf) {
    for (float size : {0.6f, 0.5f, 1e-3f, 3.0f}) {
        const ShadowGrid grid(size, 0.0f, 4);
        sylva::Rng rng(7);
        std::vector<glm::vec3> pts;
        for (int i = 0; i < 400; ++i)
            pts.push_back(
                glm::vec3(rng.uniformf(-50, 50), rng.uniformf(-5, 30), rng.uniformf(-1e3f, 1e3f)));
        for (int k = -20; k <= 20; ++k)
            pts.push_back(glm::vec3(k * size, -k * size, 0.5f * k * size));
        const float inf = std::numeric_limits<float>::infinity();
        pts.push_back({8388608.0f * size, -8388609.0f * size, 16777216.5f});
        pts.push_back({3e9f, -3e9f, 2147483520.0f * size});
        pts.push_back({inf, -inf, std::numeric_limits<float>::quiet_NaN()});
        pts.push_back({-0.0f, 0.0f, -1e-30f});
        for (std::size_t n = pts.size() - 7; n <= pts.size(); ++n) {
            std::vector<ShadowSource> out(n);
            grid.voxelsOf(std::span<const glm::vec3>(pts.data(), n), out);
            for (std::size_t i = 0; i < n; ++i)
                ASSERT_EQ(out[i].voxel, grid.voxelOf(pts[i])) << size << " " << i;
        }
    }
}
