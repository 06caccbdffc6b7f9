// floatSinCos: the floats of r cos x and r sin x against the C library's, bit for bit, where
// the float's rounding is closest to a tie (the bracket's fallback) and at random.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <numbers>

#include "engine/util/floatsincos.h"
#include "engine/util/random.h"

using namespace sylva;

namespace {

bool same(float a, float b) {
    return std::memcmp(&a, &b, sizeof a) == 0;
}

// The expressions floatSinCos stands for, as the growth wrote them.
void expectLibrary(double x, double r) {
    const FloatSinCos got = floatSinCos(x, r);
    const auto wantCos = static_cast<float>(r * std::cos(x));
    const auto wantSin = static_cast<float>(r * std::sin(x));
    ASSERT_TRUE(same(got.cos, wantCos) && same(got.sin, wantSin))
        << "x " << x << " r " << r << ": (" << got.cos << ", " << got.sin << ") vs (" << wantCos
        << ", " << wantSin << ")";
}

} // namespace

TEST(FloatSinCos, TheLibrarysFloatsAtRandom) {
    Rng rng(7);
    for (int i = 0; i < 400000; ++i) {
        // The colonization's random units: an angle in [0, 2π), r = √(1 - z²) for z in [-1, 1).
        const double z = rng.uniform(-1.0, 1.0);
        const double phi = rng.uniform(0.0, 2.0 * std::numbers::pi);
        expectLibrary(phi, std::sqrt(std::max(0.0, 1.0 - z * z)));
        // Wider angles, negative ones, r = 1 and r = 0.
        expectLibrary(rng.uniform(-2000.0, 2000.0), 1.0);
        if (i % 64 == 0) expectLibrary(rng.uniform(-10.0, 10.0), 0.0);
    }
}

TEST(FloatSinCos, TheLibrarysFloatsNextToTies) {
    // Angles whose cosine (or sine) is within a few ulp of the midpoint between two floats: the
    // bracket straddles it, so the library decides; the quadrant multiples of π/2, where a value
    // is near 0 and its sign is the float's; and angles past 2^20.
    Rng rng(11);
    for (int i = 0; i < 100000; ++i) {
        const auto f = static_cast<float>(rng.uniform(-1.0, 1.0));
        const double mid =
            (static_cast<double>(f) + static_cast<double>(std::nextafter(f, 2.0f))) / 2.0;
        const double a = std::acos(mid);
        for (double x : {a, -a, std::asin(mid), std::nextafter(a, 0.0), std::nextafter(a, 4.0)})
            expectLibrary(x, 1.0);
    }
    for (int k = -40; k <= 40; ++k) {
        const double x = k * std::numbers::pi / 2.0;
        for (double d : {0.0, 1e-17, -1e-17, 1e-9, -1e-9})
            expectLibrary(x + d, 1.0);
        expectLibrary(x, 0.0);
    }
    for (double x : {0x1p20, -0x1p20, 0x1p20 + 0.5, 1e10, -3e15})
        expectLibrary(x, 0.75);
    expectLibrary(0.0, 1.0);
    expectLibrary(-0.0, 1.0);
}
