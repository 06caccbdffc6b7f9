#include "engine/mesh/cardfitlanes.h"

#include <algorithm>
#include <cstdlib>
#include <stdexcept>

#include "engine/util/x86intrinsics.h"

#if defined(SYLVA_X86_INTRINSICS) && defined(__SSE2__)
#include "engine/mesh/cardaxes4.h"
#include "engine/mesh/cardfitlanes512.h"
#define SYLVA_CARD_LANES 1
#else
#define SYLVA_CARD_LANES 0
#endif

namespace sylva::mesh {

#if SYLVA_CARD_LANES

namespace {

// SYLVA_NO_AVX=1 takes the one-group-at-a-time fits (their tests run them on one with AVX);
// SYLVA_NO_AVX512=1 the four-lane ones.
const bool kHasAvx = simd::useAvx();
const bool kHasAvx512 = simd::useAvx512();

// AVX has no fused multiply-add: every product and sum below rounds on its own, as the scalar
// code's. A lane whose group has no leaf at a step adds +0 (its mask's and): a sum that starts
// at +0 is never -0 (x + -x is +0 when rounding to nearest), and adding +0 to anything else
// leaves it as it is.
__attribute__((target("avx"), always_inline)) inline __m256d addOn(__m256d sum, __m256d on,
                                                                   __m256d v) {
    return _mm256_add_pd(sum, _mm256_and_pd(on, v));
}
__attribute__((target("avx"), always_inline)) inline __m256d wide(const float* p) {
    return _mm256_cvtps_pd(_mm_loadu_ps(p));
}

// Which lanes have a leaf at step j (leaf j of their group).
__attribute__((target("avx"), always_inline)) inline __m256d onAt(std::size_t j, __m256d sizes) {
    return _mm256_cmp_pd(_mm256_set1_pd(static_cast<double>(j)), sizes, _CMP_LT_OQ);
}

__attribute__((target("avx"))) void prepareAvx(const std::vector<skel::Leaf>& leaves,
                                               const std::span<const std::uint32_t>* groups,
                                               std::size_t n, float aspect, float scale,
                                               CardFitInput* in, CardFitLanes& lanes) {
    static_assert(offsetof(glm::quat, w) == 3 * sizeof(float), "a quaternion is x, y, z, w");
    std::span<const std::uint32_t> g[4];
    std::size_t most = 0;
    for (std::size_t k = 0; k < 4; ++k) {
        g[k] = groups[k < n ? k : 0];
        lanes.sizes[k] = g[k].size();
        most = std::max(most, g[k].size());
    }
    lanes.steps = 4 * most;
    lanes.width = 4;
    lanes.x.resize(4 * lanes.steps);
    lanes.y.resize(4 * lanes.steps);
    lanes.z.resize(4 * lanes.steps);
    const __m256d sizes =
        _mm256_set_pd(static_cast<double>(g[3].size()), static_cast<double>(g[2].size()),
                      static_cast<double>(g[1].size()), static_cast<double>(g[0].size()));
    const float halfAspect = 0.5f * aspect; // leafCorners' 0.5f * aspect * len
    const __m128 scale4 = _mm_set1_ps(scale);
    const __m256d zero = _mm256_setzero_pd();
    __m256d sx = zero, sy = zero, sz = zero, hx = zero, hy = zero, hz = zero;
    __m256d ux = zero, uy = zero, uz = zero, lx = zero, ly = zero, lz = zero;
    float* const X = lanes.x.data();
    float* const Y = lanes.y.data();
    float* const Z = lanes.z.data();
    for (std::size_t j = 0; j < most; ++j) {
        const skel::Leaf* leaf[4];
        for (std::size_t k = 0; k < 4; ++k)
            leaf[k] = &leaves[g[k][std::min(j, g[k].size() - 1)]];
        // leafCorners' arithmetic, lane by lane (as prepareCardFit's).
        const LeafCards4 cards = leafCards4(leaf, halfAspect, scale4);
        const Vec4x3 &h = cards.axes.h, &l = cards.axes.l, &u = cards.axes.u;
        const Vec4x3* const corner = cards.corner;
        const __m256d on = onAt(j, sizes);
        for (std::size_t c = 0; c < 4; ++c) {
            const std::size_t at = 4 * (4 * j + c);
            _mm_storeu_ps(X + at, corner[c].x);
            _mm_storeu_ps(Y + at, corner[c].y);
            _mm_storeu_ps(Z + at, corner[c].z);
            sx = addOn(sx, on, _mm256_cvtps_pd(corner[c].x));
            sy = addOn(sy, on, _mm256_cvtps_pd(corner[c].y));
            sz = addOn(sz, on, _mm256_cvtps_pd(corner[c].z));
        }
        hx = addOn(hx, on, _mm256_cvtps_pd(h.x));
        hy = addOn(hy, on, _mm256_cvtps_pd(h.y));
        hz = addOn(hz, on, _mm256_cvtps_pd(h.z));
        ux = addOn(ux, on, _mm256_cvtps_pd(u.x));
        uy = addOn(uy, on, _mm256_cvtps_pd(u.y));
        uz = addOn(uz, on, _mm256_cvtps_pd(u.z));
        lx = addOn(lx, on, _mm256_cvtps_pd(l.x));
        ly = addOn(ly, on, _mm256_cvtps_pd(l.y));
        lz = addOn(lz, on, _mm256_cvtps_pd(l.z));
    }
    // The mean: the corners' sum over their count (exact: four times the leaves).
    const __m256d count = _mm256_mul_pd(sizes, _mm256_set1_pd(4.0));
    const __m256d mx = _mm256_div_pd(sx, count), my = _mm256_div_pd(sy, count),
                  mz = _mm256_div_pd(sz, count);
    // The covariance's six distinct sums, each in corner order from +0 (a product is the same
    // double either way round).
    __m256d xx = zero, yy = zero, zz = zero, xy = zero, xz = zero, yz = zero;
    for (std::size_t s = 0; s < lanes.steps; ++s) {
        const __m256d on = onAt(s / 4, sizes);
        const __m256d dx = _mm256_sub_pd(wide(X + 4 * s), mx);
        const __m256d dy = _mm256_sub_pd(wide(Y + 4 * s), my);
        const __m256d dz = _mm256_sub_pd(wide(Z + 4 * s), mz);
        xx = addOn(xx, on, _mm256_mul_pd(dx, dx));
        yy = addOn(yy, on, _mm256_mul_pd(dy, dy));
        zz = addOn(zz, on, _mm256_mul_pd(dz, dz));
        xy = addOn(xy, on, _mm256_mul_pd(dx, dy));
        xz = addOn(xz, on, _mm256_mul_pd(dx, dz));
        yz = addOn(yz, on, _mm256_mul_pd(dy, dz));
    }
    alignas(32) double v[18][4];
    _mm256_store_pd(v[0], hx);
    _mm256_store_pd(v[1], hy);
    _mm256_store_pd(v[2], hz);
    _mm256_store_pd(v[3], ux);
    _mm256_store_pd(v[4], uy);
    _mm256_store_pd(v[5], uz);
    _mm256_store_pd(v[6], lx);
    _mm256_store_pd(v[7], ly);
    _mm256_store_pd(v[8], lz);
    _mm256_store_pd(v[9], mx);
    _mm256_store_pd(v[10], my);
    _mm256_store_pd(v[11], mz);
    _mm256_store_pd(v[12], xx);
    _mm256_store_pd(v[13], yy);
    _mm256_store_pd(v[14], zz);
    _mm256_store_pd(v[15], xy);
    _mm256_store_pd(v[16], xz);
    _mm256_store_pd(v[17], yz);
    for (std::size_t k = 0; k < n; ++k) {
        in[k].heading = glm::dvec3(v[0][k], v[1][k], v[2][k]);
        in[k].up = glm::dvec3(v[3][k], v[4][k], v[5][k]);
        in[k].left = glm::dvec3(v[6][k], v[7][k], v[8][k]);
        in[k].m = glm::dvec3(v[9][k], v[10][k], v[11][k]);
        in[k].cov = glm::dmat3(v[12][k], v[15][k], v[16][k], v[15][k], v[13][k], v[17][k], v[16][k],
                               v[17][k], v[14][k]);
    }
}

__attribute__((target("avx"))) void extentAvx(const CardFitLanes& lanes, const CardFitInput* in,
                                              const glm::dvec3* along, const glm::dvec3* across,
                                              std::size_t n, double (*extent)[4]) {
    // Lanes past n repeat the first group. Each vector made from its four doubles (through an
    // array, each vector's load waited on four scalar stores: perf annotate, ~40 % of the
    // extent's samples).
    const std::size_t l1 = n > 1 ? 1 : 0, l2 = n > 2 ? 2 : 0, l3 = n > 3 ? 3 : 0;
#define SYLVA_LANES_OF(v, e) _mm256_set_pd(v[l3].e, v[l2].e, v[l1].e, v[0].e)
    const __m256d mx = SYLVA_LANES_OF(in, m.x), my = SYLVA_LANES_OF(in, m.y),
                  mz = SYLVA_LANES_OF(in, m.z);
    const __m256d ax = SYLVA_LANES_OF(along, x), ay = SYLVA_LANES_OF(along, y),
                  az = SYLVA_LANES_OF(along, z);
    const __m256d cx = SYLVA_LANES_OF(across, x), cy = SYLVA_LANES_OF(across, y),
                  cz = SYLVA_LANES_OF(across, z);
#undef SYLVA_LANES_OF
    __m256d a0 = _mm256_set1_pd(1e300), a1 = _mm256_set1_pd(-1e300);
    __m256d c0 = a0, c1 = a1;
    const float* const X = lanes.x.data();
    const float* const Y = lanes.y.data();
    const float* const Z = lanes.z.data();
    for (std::size_t s = 0; s < lanes.steps; ++s) {
        const __m256d dx = _mm256_sub_pd(wide(X + 4 * s), mx);
        const __m256d dy = _mm256_sub_pd(wide(Y + 4 * s), my);
        const __m256d dz = _mm256_sub_pd(wide(Z + 4 * s), mz);
        // glm::dot: (x + y) + z.
        const __m256d a = _mm256_add_pd(_mm256_add_pd(_mm256_mul_pd(dx, ax), _mm256_mul_pd(dy, ay)),
                                        _mm256_mul_pd(dz, az));
        const __m256d c = _mm256_add_pd(_mm256_add_pd(_mm256_mul_pd(dx, cx), _mm256_mul_pd(dy, cy)),
                                        _mm256_mul_pd(dz, cz));
        // std::min(lo, a) is a < lo ? a : lo, as minpd(a, lo); max alike. A lane whose group
        // has ended takes its last leaf's corners again (prepareAvx repeats that leaf), the same
        // values as before: a minimum or a maximum of a value already taken is unchanged.
        a0 = _mm256_min_pd(a, a0);
        a1 = _mm256_max_pd(a, a1);
        c0 = _mm256_min_pd(c, c0);
        c1 = _mm256_max_pd(c, c1);
    }
    alignas(32) double v[4][4];
    _mm256_store_pd(v[0], a0);
    _mm256_store_pd(v[1], a1);
    _mm256_store_pd(v[2], c0);
    _mm256_store_pd(v[3], c1);
    for (std::size_t k = 0; k < n; ++k)
        for (int e = 0; e < 4; ++e)
            extent[k][e] = v[e][k];
}

} // namespace

bool cardFitLanesAvailable() {
    return kHasAvx;
}

std::size_t cardFitLanesWidth() {
    return kHasAvx512 ? 8 : kHasAvx ? 4 : 0;
}

void prepareCardFitLanes(const std::vector<skel::Leaf>& leaves,
                         const std::span<const std::uint32_t>* groups, std::size_t n, float aspect,
                         float scale, CardFitInput* in, CardFitLanes& lanes) {
    if (!kHasAvx) throw std::logic_error("prepareCardFitLanes: no AVX lanes here");
    if (n < 1 || n > cardFitLanesWidth())
        throw std::logic_error("prepareCardFitLanes: 1 to cardFitLanesWidth() groups");
    if (kHasAvx512)
        lanes512::prepareAvx512(leaves, groups, n, aspect, scale, in, lanes);
    else
        prepareAvx(leaves, groups, n, aspect, scale, in, lanes);
}

void cardExtentLanes(const CardFitLanes& lanes, const CardFitInput* in, const glm::dvec3* along,
                     const glm::dvec3* across, std::size_t n, double (*extent)[4]) {
    if (!kHasAvx) throw std::logic_error("cardExtentLanes: no AVX lanes here");
    if (lanes.width == 8)
        lanes512::extentAvx512(lanes, in, along, across, n, extent);
    else
        extentAvx(lanes, in, along, across, n, extent);
}

bool finishCardFitLanes(const CardFitLanes& lanes, const CardFitInput* in,
                        const std::span<const std::uint32_t>* group, const glm::dvec3* e1,
                        const glm::dvec3* e2, std::size_t n, glm::vec3* const* out) {
    if (lanes.width != 8 || !kHasAvx512)
        throw std::logic_error("finishCardFitLanes: eight AVX-512 lanes only");
    return lanes512::finishAvx512(lanes, in, group, e1, e2, n, out);
}

bool secondMatrixLanes(const CardFitInput* in, const glm::dvec3* e1, std::size_t n,
                       glm::dmat3* rest, glm::dvec3* seed2) {
    if (!kHasAvx512 || n < 1 || n > 8)
        throw std::logic_error("secondMatrixLanes: one to eight AVX-512 lanes only");
    return lanes512::secondAvx512(in, e1, n, rest, seed2);
}

#else

bool cardFitLanesAvailable() {
    return false;
}

std::size_t cardFitLanesWidth() {
    return 0;
}

void prepareCardFitLanes(const std::vector<skel::Leaf>&, const std::span<const std::uint32_t>*,
                         std::size_t, float, float, CardFitInput*, CardFitLanes&) {
    throw std::logic_error("prepareCardFitLanes: no AVX lanes on this processor");
}

void cardExtentLanes(const CardFitLanes&, const CardFitInput*, const glm::dvec3*, const glm::dvec3*,
                     std::size_t, double (*)[4]) {
    throw std::logic_error("cardExtentLanes: no AVX lanes on this processor");
}

bool finishCardFitLanes(const CardFitLanes&, const CardFitInput*,
                        const std::span<const std::uint32_t>*, const glm::dvec3*, const glm::dvec3*,
                        std::size_t, glm::vec3* const*) {
    throw std::logic_error("finishCardFitLanes: no AVX-512 lanes on this processor");
}

bool secondMatrixLanes(const CardFitInput*, const glm::dvec3*, std::size_t, glm::dmat3*,
                       glm::dvec3*) {
    throw std::logic_error("secondMatrixLanes: no AVX-512 lanes on this processor");
}

#endif

} // namespace sylva::mesh
