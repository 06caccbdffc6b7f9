#include "engine/mesh/cardfit.h"

#include <algorithm>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

namespace sylva::mesh {

void prepareCardFit(const std::vector<skel::Leaf>& leaves, std::span<const std::uint32_t> group,
                    float aspect, float scale, CardFitInput& in) {
    std::vector<glm::vec3>& pts = in.corners;
    pts.resize(4 * group.size());
    glm::dvec3 heading(0.0), up(0.0), left(0.0);
    glm::vec3* out = pts.data();
    for (std::uint32_t i : group) {
        // Each axis made once a leaf (the corners and the sums both need them).
        const glm::vec3 h = skel::headingOf(leaves[i].orientation);
        const glm::vec3 l = skel::leftOf(leaves[i].orientation);
        leafCorners(leaves[i], h, l, aspect, scale, out);
        out += 4;
        heading += glm::dvec3(h);
        up += glm::dvec3(skel::upOf(leaves[i].orientation));
        left += glm::dvec3(l);
    }
    glm::dvec3 m(0.0);
    for (const glm::vec3& q : pts)
        m += glm::dvec3(q);
    m /= static_cast<double>(pts.size());
    glm::dmat3 cov(0.0);
    for (const glm::vec3& q : pts) {
        const glm::dvec3 d = glm::dvec3(q) - m;
        cov += glm::outerProduct(d, d);
    }
    in.heading = heading;
    in.up = up;
    in.left = left;
    in.m = m;
    in.cov = cov;
}

void cardExtentPlain(const CardFitInput& in, const glm::dvec3& along, const glm::dvec3& across,
                     double& a0, double& a1, double& c0, double& c1) {
    a0 = 1e300, a1 = -1e300, c0 = 1e300, c1 = -1e300;
    for (const glm::vec3& p : in.corners) {
        const glm::dvec3 q(p);
        const double a = glm::dot(q - in.m, along), c = glm::dot(q - in.m, across);
        a0 = std::min(a0, a);
        a1 = std::max(a1, a);
        c0 = std::min(c0, c);
        c1 = std::max(c1, c);
    }
}

#if defined(__SSE2__)

namespace {

// A float corner's x and y as two doubles, its z as the low double.
__m128d xyOf(const glm::vec3& p) {
    // __m128i may alias any type: the two floats as one 64-bit load.
    return _mm_cvtps_pd(_mm_castsi128_ps(_mm_loadl_epi64(reinterpret_cast<const __m128i*>(&p.x))));
}
__m128d zOf(const glm::vec3& p) {
    return _mm_cvtss_sd(_mm_setzero_pd(), _mm_load_ss(&p.z));
}

} // namespace

void cardExtent(const CardFitInput& in, const glm::dvec3& along, const glm::dvec3& across,
                double& a0, double& a1, double& c0, double& c1) {
    // Lane 0 the along products, lane 1 the across ones: dot = (x + y) + z, as glm::dot.
    const __m128d mXY = _mm_set_pd(in.m.y, in.m.x), mZ = _mm_set_sd(in.m.z);
    const __m128d alongXY = _mm_set_pd(along.y, along.x);
    const __m128d acrossXY = _mm_set_pd(across.y, across.x);
    const __m128d axesZ = _mm_set_pd(across.z, along.z);
    __m128d lo = _mm_set1_pd(1e300), hi = _mm_set1_pd(-1e300);
    for (const glm::vec3& q : in.corners) {
        const __m128d dXY = _mm_sub_pd(xyOf(q), mXY);
        const __m128d dZ = _mm_sub_sd(zOf(q), mZ);
        const __m128d ta = _mm_mul_pd(dXY, alongXY), tc = _mm_mul_pd(dXY, acrossXY);
        const __m128d xs = _mm_unpacklo_pd(ta, tc), ys = _mm_unpackhi_pd(ta, tc);
        const __m128d zs = _mm_mul_pd(_mm_unpacklo_pd(dZ, dZ), axesZ);
        const __m128d dot = _mm_add_pd(_mm_add_pd(xs, ys), zs);
        // std::min(lo, dot) is dot < lo ? dot : lo, as minpd(dot, lo); max alike.
        lo = _mm_min_pd(dot, lo);
        hi = _mm_max_pd(dot, hi);
    }
    alignas(16) double l[2], h[2];
    _mm_store_pd(l, lo);
    _mm_store_pd(h, hi);
    a0 = l[0];
    c0 = l[1];
    a1 = h[0];
    c1 = h[1];
}

#else

void cardExtent(const CardFitInput& in, const glm::dvec3& along, const glm::dvec3& across,
                double& a0, double& a1, double& c0, double& c1) {
    cardExtentPlain(in, along, across, a0, a1, c0, c1);
}

#endif

} // namespace sylva::mesh
