#include "engine/util/floatsincos.h"

#include <bit>
#include <cmath>
#include <cstdint>

namespace sylva {

namespace {

// π/2 in two parts (fdlibm's pio2_1, pio2_1t): the first 33 bits, so that k · kPio2Hi is exact
// for |k| < 2^20, and the rest.
constexpr double kPio2Hi = 1.57079632673412561417e+00;
constexpr double kPio2Lo = 6.07710050650619224932e-11;
constexpr double kTwoOverPi = 6.36619772367581382433e-01;
// The bracket's half width: far above this file's error (~4e-15: the reduction's rounding
// ~1e-16, the polynomials' truncation < 1e-19 and Horner's rounding < 3e-15 on |y| <= 0.8) and
// the library's (1 ulp, <= 2.3e-16 on [-1, 1]).
constexpr double kBracket = 0x1p-40;

// 1 / n! for the Taylor series, rounded once each.
constexpr double inverseFactorial(int n) {
    double f = 1.0;
    for (int i = 2; i <= n; ++i)
        f *= i;
    return 1.0 / f;
}

// The float of r · c for every c the bracket around \p c holds, or false when they differ.
bool sameFloat(double r, double c, float& out) {
    const auto lo = static_cast<float>(r * (c - kBracket));
    const auto hi = static_cast<float>(r * (c + kBracket));
    out = lo;
    // Bits, not ==: -0 and +0 compare equal but are different floats.
    return std::bit_cast<std::uint32_t>(lo) == std::bit_cast<std::uint32_t>(hi);
}

} // namespace

FloatSinCos floatSinCos(double x, double r) {
    if (std::abs(x) < 0x1p20) {
        // x = k π/2 + y, |y| <= π/4 (a little more where the quotient rounds): x - k · kPio2Hi
        // is exact (Sterbenz: within a factor 2 for k != 0; x itself for k = 0).
        const double t = x * kTwoOverPi;
        const auto k = static_cast<std::int64_t>(t >= 0.0 ? t + 0.5 : t - 0.5);
        const auto kd = static_cast<double>(k);
        const double y = (x - kd * kPio2Hi) - kd * kPio2Lo;
        const double y2 = y * y;
        // Taylor polynomials to y^17 and y^18 (the next terms < 1e-19 for |y| <= 0.8).
        const double s =
            y + y * y2 *
                    (-inverseFactorial(3) +
                     y2 * (inverseFactorial(5) +
                           y2 * (-inverseFactorial(7) +
                                 y2 * (inverseFactorial(9) +
                                       y2 * (-inverseFactorial(11) +
                                             y2 * (inverseFactorial(13) +
                                                   y2 * (-inverseFactorial(15) +
                                                         y2 * inverseFactorial(17))))))));
        const double c =
            1.0 +
            y2 * (-inverseFactorial(2) +
                  y2 * (inverseFactorial(4) +
                        y2 * (-inverseFactorial(6) +
                              y2 * (inverseFactorial(8) +
                                    y2 * (-inverseFactorial(10) +
                                          y2 * (inverseFactorial(12) +
                                                y2 * (-inverseFactorial(14) +
                                                      y2 * (inverseFactorial(16) +
                                                            y2 * -inverseFactorial(18)))))))));
        // The quadrant: sin x, cos x from sin y, cos y.
        const auto q = static_cast<unsigned>(k) & 3u;
        const double sinX = q == 0 ? s : q == 1 ? c : q == 2 ? -s : -c;
        const double cosX = q == 0 ? c : q == 1 ? -s : q == 2 ? -c : s;
        FloatSinCos out;
        if (sameFloat(r, cosX, out.cos) && sameFloat(r, sinX, out.sin)) return out;
    }
    return {static_cast<float>(r * std::cos(x)), static_cast<float>(r * std::sin(x))};
}

} // namespace sylva
