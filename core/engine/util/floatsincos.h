#pragma once

namespace sylva {

/// static_cast<float>(r * std::cos(x)) and static_cast<float>(r * std::sin(x)).
struct FloatSinCos {
    float cos = 1.0f, sin = 0.0f;
};

/// The floats of r · cos x and r · sin x (\p r >= 0, finite; \p x finite) exactly as the
/// expressions static_cast<float>(r * std::cos(x)) and static_cast<float>(r * std::sin(x))
/// give them with the C library's cos and sin, mostly without calling them: the sine and
/// cosine made here (a Cody–Waite reduction by π/2 and Taylor polynomials, within ~4·10^-15
/// of the true values) bracket the library's (within 1 ulp of the true values, ≤ 2.3·10^-16)
/// by ±2^-40; where the product rounds to the same float at both ends of that bracket,
/// rounding being monotone, it rounds to that float from the library's value too. Where it
/// does not (a float's rounding boundary within r · 2^-40 of the product: about once in 10^5
/// for values near 0.5), or for |x| ≥ 2^20, the library is called. glibc's sincos was ~10 ns a
/// call (the colonization's random directions, the tip leaves' angles); this is ~3.
FloatSinCos floatSinCos(double x, double r);

} // namespace sylva
