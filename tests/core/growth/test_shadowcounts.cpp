// shadowAtSources: the raw shadow at each source's voxel, counted, against a ShadowGrid that
// spreads every pyramid, bit for bit.
#include <vector>

#include <gtest/gtest.h>

#include "engine/growth/shadowcounts.h"
#include "engine/growth/shadowgrid.h"
#include "engine/util/random.h"

using namespace sylva;
using namespace sylva::growth;

namespace {

std::vector<std::int32_t> byGrid(const std::vector<glm::ivec3>& voxels, const ShadowKernel& k) {
    int floorY = voxels[0].y;
    for (const glm::ivec3& v : voxels)
        floorY = std::min(floorY, v.y);
    // Voxel size 1: a voxel's floor corner is its integer coordinates; the floor one below.
    ShadowGrid grid(1.0f, static_cast<float>(floorY - 1), k.depth);
    std::vector<ShadowSource> sources(voxels.size());
    for (std::size_t i = 0; i < voxels.size(); ++i)
        sources[i].voxel = voxels[i];
    grid.applyBatch(sources, std::span<const ShadowKernel>(&k, 1));
    std::vector<std::int32_t> raw(voxels.size());
    for (std::size_t i = 0; i < voxels.size(); ++i)
        raw[i] = grid.raw(voxels[i]);
    return raw;
}

} // namespace

TEST(ShadowCounts, EqualTheGridBitForBit) {
    Rng rng(41);
    for (int trial = 0; trial < 40; ++trial) {
        const int depth = trial % 7;
        const ShadowKernel k = ShadowKernel::make(1.0, trial % 2 ? 2.0 : 1.3, depth);
        // Dense clouds (many sources a voxel) and sparse ones, either side of 0.
        const int extent = 2 + trial % 13;
        const std::size_t count = 1 + rng.below(trial % 3 == 0 ? 40 : 3000);
        std::vector<glm::ivec3> voxels(count);
        const glm::ivec3 origin(static_cast<int>(rng.below(200)) - 100,
                                static_cast<int>(rng.below(200)) - 100,
                                static_cast<int>(rng.below(200)) - 100);
        for (glm::ivec3& v : voxels)
            v = origin +
                glm::ivec3(static_cast<int>(rng.below(static_cast<std::uint64_t>(extent))),
                           static_cast<int>(rng.below(static_cast<std::uint64_t>(extent))),
                           static_cast<int>(rng.below(static_cast<std::uint64_t>(extent))));
        std::vector<std::int32_t> counted;
        ASSERT_TRUE(shadowAtSources(voxels, k, counted));
        const std::vector<std::int32_t> spread = byGrid(voxels, k);
        ASSERT_EQ(counted.size(), spread.size());
        for (std::size_t i = 0; i < counted.size(); ++i)
            ASSERT_EQ(counted[i], spread[i]) << "trial " << trial << " source " << i;
    }
}

TEST(ShadowCounts, ACrossAndAColumn) {
    // Sources stacked in one column and spread along a row: every square's edge is met.
    const ShadowKernel k = ShadowKernel::make(1.0, 2.0, 4);
    std::vector<glm::ivec3> voxels;
    for (int y = 0; y < 6; ++y)
        voxels.emplace_back(0, y, 0);
    for (int x = -6; x <= 6; ++x)
        voxels.emplace_back(x, -5, 0);
    for (int z = -6; z <= 6; ++z)
        voxels.emplace_back(0, -5, z);
    std::vector<std::int32_t> counted;
    ASSERT_TRUE(shadowAtSources(voxels, k, counted));
    EXPECT_EQ(counted, byGrid(voxels, k));
}

TEST(ShadowCounts, LeavesAHugeBoxToTheGrid) {
    const ShadowKernel k = ShadowKernel::make(1.0, 2.0, 4);
    const std::vector<glm::ivec3> voxels{{0, 0, 0}, {5000, 5000, 5000}};
    std::vector<std::int32_t> raw{7};
    EXPECT_FALSE(shadowAtSources(voxels, k, raw));
    EXPECT_EQ(raw, std::vector<std::int32_t>{7}); // untouched
    std::vector<std::int32_t> none{3};
    EXPECT_TRUE(shadowAtSources({}, k, none));
    EXPECT_TRUE(none.empty());
}

// A square holding 2^16 sources or more (70,000 in one layer, sources below them): counted in
// 32 bits, not 16; and 65,535 sources, the most counted in 16 bits, in one layer likewise.
TEST(ShadowCounts, ManySourcesInOneLayer) {
    const ShadowKernel k = ShadowKernel::make(1.0, 2.0, 4);
    for (const std::size_t n : {std::size_t{70000}, std::size_t{65535}}) {
        Rng rng(n);
        std::vector<glm::ivec3> voxels(n);
        for (std::size_t i = 0; i < n; ++i)
            voxels[i] = i < 6 ? glm::ivec3(1, static_cast<int>(i), 1)
                              : glm::ivec3(static_cast<int>(rng.below(3)), 6,
                                           static_cast<int>(rng.below(3)));
        std::vector<std::int32_t> counted;
        ASSERT_TRUE(shadowAtSources(voxels, k, counted));
        EXPECT_EQ(counted, byGrid(voxels, k)) << n;
    }
}
