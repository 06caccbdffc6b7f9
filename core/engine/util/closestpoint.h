#pragma once

#include <cmath>

#include <glm/glm.hpp>

namespace sylva {

/// The point of triangle abc closest to p (Ericson, Real-Time Collision Detection, 5.1.5), in
/// the precision of \p V (glm::vec3 or glm::dvec3). A degenerate triangle answers a.
template <typename V> V closestPointOnTriangle(const V& p, const V& a, const V& b, const V& c) {
    using T = typename V::value_type;
    constexpr T kDegenerate = sizeof(T) == sizeof(float) ? T(1e-30) : T(1e-300);
    const V ab = b - a, ac = c - a, ap = p - a;
    const T d1 = glm::dot(ab, ap), d2 = glm::dot(ac, ap);
    if (d1 <= 0 && d2 <= 0) return a;
    const V bp = p - b;
    const T d3 = glm::dot(ab, bp), d4 = glm::dot(ac, bp);
    if (d3 >= 0 && d4 <= d3) return b;
    const T vc = d1 * d4 - d3 * d2;
    if (vc <= 0 && d1 >= 0 && d3 <= 0) return a + ab * (d1 / (d1 - d3));
    const V cp = p - c;
    const T d5 = glm::dot(ab, cp), d6 = glm::dot(ac, cp);
    if (d6 >= 0 && d5 <= d6) return c;
    const T vb = d5 * d2 - d1 * d6;
    if (vb <= 0 && d2 >= 0 && d6 <= 0) return a + ac * (d2 / (d2 - d6));
    const T va = d3 * d6 - d5 * d4;
    if (va <= 0 && (d4 - d3) >= 0 && (d5 - d6) >= 0)
        return b + (c - b) * ((d4 - d3) / ((d4 - d3) + (d5 - d6)));
    const T denom = va + vb + vc;
    if (std::abs(denom) < kDegenerate) return a;
    const T v = vb / denom, w = vc / denom;
    return a + ab * v + ac * w;
}

} // namespace sylva
