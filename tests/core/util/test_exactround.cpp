#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

#include "engine/util/exactround.h"
#include "engine/util/random.h"

using namespace sylva;

namespace {

// The same value, bit for bit (-0.0 and NaN included).
void expectSameBits(double a, double b, double x) {
    EXPECT_EQ(std::bit_cast<std::uint64_t>(a), std::bit_cast<std::uint64_t>(b)) << x;
}
void expectSameBits(float a, float b, float x) {
    EXPECT_EQ(std::bit_cast<std::uint32_t>(a), std::bit_cast<std::uint32_t>(b)) << x;
}

std::vector<double> doubles() {
    const double inf = std::numeric_limits<double>::infinity();
    std::vector<double> v = {0.0,
                             -0.0,
                             0.5,
                             -0.5,
                             1.5,
                             -1.5,
                             2.5,
                             -2.5,
                             1.0,
                             -1.0,
                             0.49999999999999994,
                             -0.49999999999999994,
                             0x1p52,
                             -0x1p52,
                             0x1p52 - 0.5,
                             -(0x1p52 - 0.5),
                             0x1p53,
                             1e300,
                             -1e300,
                             inf,
                             -inf,
                             std::nextafter(1.0, 0.0),
                             std::nextafter(-1.0, 0.0),
                             4e-320,
                             -4e-320};
    Rng rng(5);
    for (int i = 0; i < 20000; ++i) {
        const double scale = std::ldexp(1.0, static_cast<int>(rng.below(70)) - 10);
        v.push_back(rng.uniform(-1.0, 1.0) * scale);
        v.push_back(std::round(v.back()) + (rng.below(2) ? 0.5 : -0.5)); // halves
    }
    return v;
}

} // namespace

// floorExact and llroundExact are std::floor and std::llround without a libm call: the same
// values everywhere, including halves, signed zeros, infinities and values past 2^52.
TEST(ExactRound, FloorAndRoundMatchTheStandardFunctions) {
    for (double x : doubles()) {
        expectSameBits(floorExact(x), std::floor(x), x);
        const auto f = static_cast<float>(x);
        expectSameBits(floorExact(f), std::floor(f), f);
        if (std::abs(x) < 0x1p62) {
            EXPECT_EQ(llroundExact(x), std::llround(x)) << x;
        }
    }
    const double nan = std::numeric_limits<double>::quiet_NaN();
    EXPECT_TRUE(std::isnan(floorExact(nan)));
    EXPECT_TRUE(std::isnan(floorExact(static_cast<float>(nan))));
}
