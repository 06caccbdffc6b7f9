#pragma once

#include <cmath>
#include <cstdint>

namespace sylva {

// std::floor and std::llround without a call into libm (below SSE4.1 they are not inlined:
// calls on the hot paths of the leaf tints). The same value as the std:: function for every
// argument, -0.0, infinities and NaN included (test_exactround).

/// std::floor(x).
inline double floorExact(double x) {
    if (!(std::abs(x) < 0x1p52)) return x; // an integer already, an infinity or NaN
    const auto t = static_cast<double>(static_cast<std::int64_t>(x));
    if (t == x) return x; // keeps -0.0
    return t > x ? t - 1.0 : t;
}

/// std::floor(x).
inline float floorExact(float x) {
    if (!(std::abs(x) < 0x1p23f)) return x;
    const auto t = static_cast<float>(static_cast<std::int32_t>(x));
    if (t == x) return x;
    return t > x ? t - 1.0f : t;
}

/// std::llround(x) (halves away from zero); out of the long long range as std::llround.
inline long long llroundExact(double x) {
    if (!(std::abs(x) < 0x1p52)) return std::llround(x);
    const auto i = static_cast<std::int64_t>(x);
    const double fraction = x - static_cast<double>(i); // exact below 2^52
    return i + (fraction >= 0.5 ? 1 : 0) - (fraction <= -0.5 ? 1 : 0);
}

} // namespace sylva
