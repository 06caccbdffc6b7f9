#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>

#include <glm/glm.hpp>

#include "engine/util/random.h"

namespace sylva {

/// A uniformly distributed unit vector from one 64-bit draw, without rejection (a rejection
/// loop's unpredictable branch cost more than the rest of a growing metamer): z uniform in
/// [−1, 1) from 24 bits and the azimuth from 24 bits, its cosine and sine from a quarter-turn
/// reduction and Taylor series on [0, π/2) (|error| < 4e-6), so the result is the same on every
/// platform (no libm).
inline glm::vec3 randomUnitVector(Rng& rng) {
    constexpr float kHalfPi = 1.57079632679490f;
    const std::uint64_t bits = rng.next();
    const float z = static_cast<float>(bits >> 40) * 0x1.0p-23f - 1.0f;
    const auto turn = static_cast<std::uint32_t>(bits & 0xffffffu); // [0, 1) turn in 2^-24
    const std::uint32_t quarter = turn >> 22;                       // 0..3
    const float t = static_cast<float>(turn & 0x3fffffu) * (kHalfPi * 0x1.0p-22f);
    const float t2 = t * t;
    const float c =
        1.0f +
        t2 * (-1.0f / 2 +
              t2 * (1.0f / 24 + t2 * (-1.0f / 720 + t2 * (1.0f / 40320 + t2 * (-1.0f / 3628800)))));
    const float s =
        t *
        (1.0f + t2 * (-1.0f / 6 + t2 * (1.0f / 120 + t2 * (-1.0f / 5040 + t2 * (1.0f / 362880)))));
    // (c, s) turned by the quarter turns: 0: (c, s), 1: (−s, c), 2: (−c, −s), 3: (s, −c).
    const bool odd = (quarter & 1u) != 0;
    float x = odd ? -s : c;
    float y = odd ? c : s;
    if (quarter & 2u) {
        x = -x;
        y = -y;
    }
    const float r = std::sqrt(std::max(0.0f, 1.0f - z * z));
    return {r * x, r * y, z};
}

} // namespace sylva
