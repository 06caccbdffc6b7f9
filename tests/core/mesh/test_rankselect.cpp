#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

#include "engine/mesh/rankselect.h"
#include "engine/util/random.h"

using namespace sylva;

namespace {

void expectEveryRank(const std::vector<float>& values, const char* what) {
    for (std::size_t rank = 0; rank < values.size(); ++rank) {
        float got = -1.0f;
        ASSERT_TRUE(mesh::valueAtRank(values, rank, got)) << what;
        const float want = mesh::valueAtRankPlain(values, rank);
        ASSERT_EQ(std::bit_cast<std::uint32_t>(got), std::bit_cast<std::uint32_t>(want))
            << what << " rank " << rank << " of " << values.size();
    }
}

} // namespace

// The rank by the floats' bits is std::nth_element's bit for bit, at every rank: card lights
// (a few hundred distinct values, many repeated), values that differ only in their last bits
// (every digit of the bits decides), +0 and subnormals, huge values and +infinity, one value.
TEST(RankSelect, EveryRankIsNthElements) {
    Rng rng(8);
    std::vector<float> lights;
    std::vector<float> levels;
    for (int i = 0; i < 300; ++i)
        levels.push_back(rng.uniformf(0.0f, 3.0f));
    for (int i = 0; i < 2000; ++i)
        lights.push_back(levels[rng.below(levels.size())]);
    expectEveryRank(lights, "lights");

    std::vector<float> close;
    for (int i = 0; i < 1500; ++i) {
        const float base = i % 3 ? 0.75f : 1.5f;
        close.push_back(std::bit_cast<float>(std::bit_cast<std::uint32_t>(base) +
                                             static_cast<std::uint32_t>(rng.below(3000))));
    }
    expectEveryRank(close, "close");

    std::vector<float> edges = {0.0f,
                                1e-45f,
                                1e-40f,
                                std::numeric_limits<float>::min(),
                                1.0f,
                                3e38f,
                                std::numeric_limits<float>::infinity(),
                                0.0f,
                                1e-45f,
                                2.0f,
                                1.0f};
    for (int i = 0; i < 200; ++i)
        edges.push_back(
            std::ldexp(rng.uniformf(1.0f, 2.0f), static_cast<int>(rng.below(250)) - 140));
    expectEveryRank(edges, "edges");
    expectEveryRank({0.25f}, "one");
}

// -0, negative values and NaN are refused (their bits do not order as their values), the output
// left as it was.
TEST(RankSelect, RefusesWhatItsBitsDoNotOrder) {
    for (float bad : {-0.0f, -1.0f, std::numeric_limits<float>::quiet_NaN(),
                      -std::numeric_limits<float>::infinity()}) {
        const std::vector<float> values = {1.0f, 2.0f, bad, 0.5f};
        float out = 7.0f;
        EXPECT_FALSE(mesh::valueAtRank(values, 1, out)) << bad;
        EXPECT_EQ(out, 7.0f);
    }
}
