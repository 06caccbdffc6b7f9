#include "engine/mesh/cardfitlanes512.h"

#include "engine/util/x86intrinsics.h"

#if defined(SYLVA_X86_INTRINSICS) && defined(__SSE2__)
#include "engine/mesh/cardfit.h"

namespace sylva::mesh::lanes512 {

namespace {

// Eight groups a zmm register of doubles (AVX-512): prepareAvx's arithmetic lane by lane, the
// float corners and axes eight leaves a ymm register (leafCards8: leafCards4's), the double sums
// unfused (simd::add / sub / mul: GCC contracts the generic AVX-512 sums and products into fused
// multiply-adds). A lane whose group has ended keeps its sums by a masked addition: the same
// bits as prepareAvx's +0 (a sum from +0 is never -0).
using simd::add;
using simd::mul;
using simd::sub;

__attribute__((target("avx512f"), always_inline)) inline __m512d addOn8(__m512d sum, __mmask8 on,
                                                                        __m512d v) {
    return _mm512_mask_add_round_pd(sum, on, sum, v, _MM_FROUND_CUR_DIRECTION);
}
__attribute__((target("avx512f"), always_inline)) inline __m512d wide8(const float* p) {
    return _mm512_cvtps_pd(_mm256_loadu_ps(p));
}

// Eight lanes' x, y and z (lanes 0-3 the low half).
struct Vec8x3 {
    __m256 x, y, z;
};
struct LeafCards8 {
    Vec8x3 h, l, u;
    Vec8x3 corner[4];
};
// leafCards4 of leaves 0-3 and 4-7 in one ymm register a coordinate: the same float operations
// lane by lane (basisAxes', then the corners'), on AVX (no fused multiply-add: AVX-512F alone
// does not contract ymm products and sums, objdump: no vfmadd in prepareAvx512).
__attribute__((target("avx512f"), always_inline)) inline void
transpose8(const float* const p[8], __m256& x, __m256& y, __m256& z, __m256& w) {
    __m256 r[4];
    for (int k = 0; k < 4; ++k)
        r[k] = _mm256_insertf128_ps(_mm256_castps128_ps256(_mm_loadu_ps(p[k])),
                                    _mm_loadu_ps(p[k + 4]), 1);
    const __m256 t0 = _mm256_unpacklo_ps(r[0], r[1]), t1 = _mm256_unpacklo_ps(r[2], r[3]);
    const __m256 t2 = _mm256_unpackhi_ps(r[0], r[1]), t3 = _mm256_unpackhi_ps(r[2], r[3]);
    x = _mm256_shuffle_ps(t0, t1, _MM_SHUFFLE(1, 0, 1, 0));
    y = _mm256_shuffle_ps(t0, t1, _MM_SHUFFLE(3, 2, 3, 2));
    z = _mm256_shuffle_ps(t2, t3, _MM_SHUFFLE(1, 0, 1, 0));
    w = _mm256_shuffle_ps(t2, t3, _MM_SHUFFLE(3, 2, 3, 2));
}
// v + sum * 2 (basisAxes' axis).
__attribute__((target("avx512f"), always_inline)) inline __m256 axis8(__m256 two, __m256 v,
                                                                      __m256 sum) {
    return _mm256_add_ps(v, _mm256_mul_ps(sum, two));
}
__attribute__((target("avx512f"), always_inline)) inline LeafCards8
leafCards8(const skel::Leaf* const leaf[8], float halfAspect, float scale) {
    const float* q[8];
    const float* p[8];
    for (int k = 0; k < 8; ++k) {
        q[k] = &leaf[k]->orientation.x;
        p[k] = &leaf[k]->position.x; // x, y, z and the orientation's x
    }
    __m256 qx, qy, qz, qw, px, py, pz, pw;
    transpose8(q, qx, qy, qz, qw);
    transpose8(p, px, py, pz, pw);
    const __m256 sign = _mm256_set1_ps(-0.0f), two = _mm256_set1_ps(2.0f);
    const __m256 xx = _mm256_mul_ps(qx, qx), yy = _mm256_mul_ps(qy, qy), zz = _mm256_mul_ps(qz, qz);
    const __m256 xy = _mm256_mul_ps(qy, qx), xz = _mm256_mul_ps(qx, qz), yz = _mm256_mul_ps(qz, qy);
    const __m256 xw = _mm256_mul_ps(qx, qw), yw = _mm256_mul_ps(qy, qw), zw = _mm256_mul_ps(qz, qw);
    const __m256 zero = _mm256_setzero_ps(), one = _mm256_set1_ps(1.0f),
                 minusOne = _mm256_set1_ps(-1.0f);
    LeafCards8 out;
    out.h = {axis8(two, zero, _mm256_sub_ps(xy, zw)),
             axis8(two, one, _mm256_sub_ps(_mm256_xor_ps(zz, sign), xx)),
             axis8(two, zero, _mm256_add_ps(xw, yz))};
    out.l = {axis8(two, minusOne, _mm256_add_ps(yy, zz)),
             axis8(two, zero, _mm256_sub_ps(_mm256_xor_ps(zw, sign), xy)),
             axis8(two, zero, _mm256_sub_ps(yw, xz))};
    out.u = {axis8(two, zero, _mm256_add_ps(yw, xz)), axis8(two, zero, _mm256_sub_ps(yz, xw)),
             axis8(two, one, _mm256_sub_ps(_mm256_xor_ps(xx, sign), yy))};
    const Vec8x3 &h = out.h, &l = out.l;
    const __m256 len =
        _mm256_mul_ps(_mm256_set_ps(leaf[7]->size, leaf[6]->size, leaf[5]->size, leaf[4]->size,
                                    leaf[3]->size, leaf[2]->size, leaf[1]->size, leaf[0]->size),
                      _mm256_set1_ps(scale));
    const __m256 across = _mm256_mul_ps(_mm256_set1_ps(halfAspect), len);
    const Vec8x3 hl{_mm256_mul_ps(h.x, len), _mm256_mul_ps(h.y, len), _mm256_mul_ps(h.z, len)};
    const Vec8x3 ll{_mm256_mul_ps(l.x, across), _mm256_mul_ps(l.y, across),
                    _mm256_mul_ps(l.z, across)};
    const Vec8x3 plus{_mm256_add_ps(px, ll.x), _mm256_add_ps(py, ll.y), _mm256_add_ps(pz, ll.z)};
    const Vec8x3 minus{_mm256_sub_ps(px, ll.x), _mm256_sub_ps(py, ll.y), _mm256_sub_ps(pz, ll.z)};
    out.corner[0] = plus;
    out.corner[1] = minus;
    out.corner[2] = {_mm256_add_ps(minus.x, hl.x), _mm256_add_ps(minus.y, hl.y),
                     _mm256_add_ps(minus.z, hl.z)};
    out.corner[3] = {_mm256_add_ps(plus.x, hl.x), _mm256_add_ps(plus.y, hl.y),
                     _mm256_add_ps(plus.z, hl.z)};
    return out;
}
__attribute__((target("avx512f"), always_inline)) inline __m512d wide8(__m256 v) {
    return _mm512_cvtps_pd(v);
}

} // namespace

__attribute__((target("avx512f"))) void prepareAvx512(const std::vector<skel::Leaf>& leaves,
                                                      const std::span<const std::uint32_t>* groups,
                                                      std::size_t n, float aspect, float scale,
                                                      CardFitInput* in, CardFitLanes& lanes) {
    std::span<const std::uint32_t> g[8];
    std::size_t most = 0;
    alignas(64) double size[8];
    for (std::size_t k = 0; k < 8; ++k) {
        g[k] = groups[k < n ? k : 0];
        lanes.sizes[k] = g[k].size();
        size[k] = static_cast<double>(g[k].size());
        most = std::max(most, g[k].size());
    }
    lanes.steps = 4 * most;
    lanes.width = 8;
    lanes.x.resize(8 * lanes.steps);
    lanes.y.resize(8 * lanes.steps);
    lanes.z.resize(8 * lanes.steps);
    const __m512d sizes = _mm512_load_pd(size);
    const float halfAspect = 0.5f * aspect; // leafCorners' 0.5f * aspect * len
    const __m512d zero = _mm512_setzero_pd();
    __m512d sx = zero, sy = zero, sz = zero, hx = zero, hy = zero, hz = zero;
    __m512d ux = zero, uy = zero, uz = zero, lx = zero, ly = zero, lz = zero;
    float* const X = lanes.x.data();
    float* const Y = lanes.y.data();
    float* const Z = lanes.z.data();
    for (std::size_t j = 0; j < most; ++j) {
        const skel::Leaf* leaf[8];
        for (std::size_t k = 0; k < 8; ++k)
            leaf[k] = &leaves[g[k][std::min(j, g[k].size() - 1)]];
        const LeafCards8 cards = leafCards8(leaf, halfAspect, scale);
        const __mmask8 on =
            _mm512_cmp_pd_mask(_mm512_set1_pd(static_cast<double>(j)), sizes, _CMP_LT_OQ);
        for (std::size_t c = 0; c < 4; ++c) {
            const std::size_t at = 8 * (4 * j + c);
            const Vec8x3& corner = cards.corner[c];
            _mm256_storeu_ps(X + at, corner.x);
            _mm256_storeu_ps(Y + at, corner.y);
            _mm256_storeu_ps(Z + at, corner.z);
            sx = addOn8(sx, on, wide8(corner.x));
            sy = addOn8(sy, on, wide8(corner.y));
            sz = addOn8(sz, on, wide8(corner.z));
        }
        hx = addOn8(hx, on, wide8(cards.h.x));
        hy = addOn8(hy, on, wide8(cards.h.y));
        hz = addOn8(hz, on, wide8(cards.h.z));
        ux = addOn8(ux, on, wide8(cards.u.x));
        uy = addOn8(uy, on, wide8(cards.u.y));
        uz = addOn8(uz, on, wide8(cards.u.z));
        lx = addOn8(lx, on, wide8(cards.l.x));
        ly = addOn8(ly, on, wide8(cards.l.y));
        lz = addOn8(lz, on, wide8(cards.l.z));
    }
    // The mean: the corners' sum over their count (exact: four times the leaves).
    const __m512d count = mul(sizes, _mm512_set1_pd(4.0));
    const __m512d mx = _mm512_div_round_pd(sx, count, _MM_FROUND_CUR_DIRECTION);
    const __m512d my = _mm512_div_round_pd(sy, count, _MM_FROUND_CUR_DIRECTION);
    const __m512d mz = _mm512_div_round_pd(sz, count, _MM_FROUND_CUR_DIRECTION);
    // The covariance's six distinct sums, each in corner order from +0.
    __m512d xx = zero, yy = zero, zz = zero, xy = zero, xz = zero, yz = zero;
    for (std::size_t s = 0; s < lanes.steps; ++s) {
        const __mmask8 on =
            _mm512_cmp_pd_mask(_mm512_set1_pd(static_cast<double>(s / 4)), sizes, _CMP_LT_OQ);
        const __m512d dx = sub(wide8(X + 8 * s), mx);
        const __m512d dy = sub(wide8(Y + 8 * s), my);
        const __m512d dz = sub(wide8(Z + 8 * s), mz);
        xx = addOn8(xx, on, mul(dx, dx));
        yy = addOn8(yy, on, mul(dy, dy));
        zz = addOn8(zz, on, mul(dz, dz));
        xy = addOn8(xy, on, mul(dx, dy));
        xz = addOn8(xz, on, mul(dx, dz));
        yz = addOn8(yz, on, mul(dy, dz));
    }
    alignas(64) double v[18][8];
    // Stored one by one (an array of the eighteen registers was copied by rep movsq).
    _mm512_store_pd(v[0], hx);
    _mm512_store_pd(v[1], hy);
    _mm512_store_pd(v[2], hz);
    _mm512_store_pd(v[3], ux);
    _mm512_store_pd(v[4], uy);
    _mm512_store_pd(v[5], uz);
    _mm512_store_pd(v[6], lx);
    _mm512_store_pd(v[7], ly);
    _mm512_store_pd(v[8], lz);
    _mm512_store_pd(v[9], mx);
    _mm512_store_pd(v[10], my);
    _mm512_store_pd(v[11], mz);
    _mm512_store_pd(v[12], xx);
    _mm512_store_pd(v[13], yy);
    _mm512_store_pd(v[14], zz);
    _mm512_store_pd(v[15], xy);
    _mm512_store_pd(v[16], xz);
    _mm512_store_pd(v[17], yz);
    for (std::size_t k = 0; k < n; ++k) {
        in[k].heading = glm::dvec3(v[0][k], v[1][k], v[2][k]);
        in[k].up = glm::dvec3(v[3][k], v[4][k], v[5][k]);
        in[k].left = glm::dvec3(v[6][k], v[7][k], v[8][k]);
        in[k].m = glm::dvec3(v[9][k], v[10][k], v[11][k]);
        in[k].cov = glm::dmat3(v[12][k], v[15][k], v[16][k], v[15][k], v[13][k], v[17][k], v[16][k],
                               v[17][k], v[14][k]);
    }
}

namespace {

// glm::dot: (x + y) + z, the products unfused.
struct Vec8d {
    __m512d x, y, z;
};
__attribute__((target("avx512f"), always_inline)) inline __m512d dot8(const Vec8d& a,
                                                                      const Vec8d& b) {
    return add(add(mul(a.x, b.x), mul(a.y, b.y)), mul(a.z, b.z));
}

// The corners' extent about m along and across, eight cards a register (cardExtentPlain's
// loop): vminpd / vmaxpd as extentAvx's (a < lo ? a : lo); an ended lane's repeated corners
// change nothing. What extentAvx512 and finishAvx512 share.
struct Extent8 {
    __m512d a0, a1, c0, c1;
};
__attribute__((target("avx512f"), always_inline)) inline Extent8
extent8(const CardFitLanes& lanes, const Vec8d& m, const Vec8d& along, const Vec8d& across) {
    Extent8 e{_mm512_set1_pd(1e300), _mm512_set1_pd(-1e300), _mm512_set1_pd(1e300),
              _mm512_set1_pd(-1e300)};
    const float* const X = lanes.x.data();
    const float* const Y = lanes.y.data();
    const float* const Z = lanes.z.data();
    for (std::size_t s = 0; s < lanes.steps; ++s) {
        const Vec8d delta = {sub(wide8(X + 8 * s), m.x), sub(wide8(Y + 8 * s), m.y),
                             sub(wide8(Z + 8 * s), m.z)};
        const __m512d pa = dot8(delta, along);
        const __m512d pc = dot8(delta, across);
        e.a0 = _mm512_min_pd(pa, e.a0);
        e.a1 = _mm512_max_pd(pa, e.a1);
        e.c0 = _mm512_min_pd(pc, e.c0);
        e.c1 = _mm512_max_pd(pc, e.c1);
    }
    return e;
}

} // namespace

__attribute__((target("avx512f"))) void
extentAvx512(const CardFitLanes& lanes, const CardFitInput* in, const glm::dvec3* along,
             const glm::dvec3* across, std::size_t n, double (*extent)[4]) {
    // Lanes past n repeat the first group; each vector gathered from its eight lanes' doubles.
    static_assert(sizeof(CardFitInput) % sizeof(double) == 0 && sizeof(glm::dvec3) == 24);
    constexpr long long kIn = sizeof(CardFitInput) / sizeof(double);
    long long inLane[8], vecLane[8];
    for (std::size_t k = 0; k < 8; ++k) {
        const auto lane = static_cast<long long>(k < n ? k : 0);
        inLane[k] = lane * kIn;
        vecLane[k] = lane * 3;
    }
    const __m512i inAt = _mm512_loadu_si512(inLane);
    const __m512i vecAt = _mm512_loadu_si512(vecLane);
    const double* const m = &in[0].m.x;
    const __m512d mx = _mm512_i64gather_pd(inAt, m, 8), my = _mm512_i64gather_pd(inAt, m + 1, 8),
                  mz = _mm512_i64gather_pd(inAt, m + 2, 8);
    const double* const a = &along[0].x;
    const __m512d ax = _mm512_i64gather_pd(vecAt, a, 8), ay = _mm512_i64gather_pd(vecAt, a + 1, 8),
                  az = _mm512_i64gather_pd(vecAt, a + 2, 8);
    const double* const c = &across[0].x;
    const __m512d cx = _mm512_i64gather_pd(vecAt, c, 8), cy = _mm512_i64gather_pd(vecAt, c + 1, 8),
                  cz = _mm512_i64gather_pd(vecAt, c + 2, 8);
    const Extent8 e = extent8(lanes, {mx, my, mz}, {ax, ay, az}, {cx, cy, cz});
    alignas(64) double v[4][8];
    _mm512_store_pd(v[0], e.a0);
    _mm512_store_pd(v[1], e.a1);
    _mm512_store_pd(v[2], e.c0);
    _mm512_store_pd(v[3], e.c1);
    for (std::size_t k = 0; k < n; ++k)
        for (int e = 0; e < 4; ++e)
            extent[k][e] = v[e][k];
}

namespace {

// glm::cross.
__attribute__((target("avx512f"), always_inline)) inline Vec8d cross8(const Vec8d& a,
                                                                      const Vec8d& b) {
    return {sub(mul(a.y, b.z), mul(b.y, a.z)), sub(mul(a.z, b.x), mul(b.z, a.x)),
            sub(mul(a.x, b.y), mul(b.x, a.y))};
}
__attribute__((target("avx512f"), always_inline)) inline Vec8d scale8(const Vec8d& v, __m512d s) {
    return {mul(v.x, s), mul(v.y, s), mul(v.z, s)};
}
// 1 / x, rounded once (glm's inversesqrt is 1 / sqrt(x); scaledBy's 1.0 / length).
__attribute__((target("avx512f"), always_inline)) inline __m512d inverse8(__m512d x) {
    return _mm512_div_round_pd(_mm512_set1_pd(1.0), x, _MM_FROUND_CUR_DIRECTION);
}
__attribute__((target("avx512f"), always_inline)) inline __m512d sqrt8(__m512d x) {
    return _mm512_sqrt_round_pd(x, _MM_FROUND_CUR_DIRECTION);
}
// -a where \p m is set (the sign flipped, as the scalar negation).
__attribute__((target("avx512f"), always_inline)) inline __m512d flipWhere(__mmask8 m, __m512d a) {
    const __m512i sign = _mm512_set1_epi64(static_cast<long long>(0x8000000000000000ull));
    return _mm512_castsi512_pd(
        _mm512_mask_xor_epi64(_mm512_castpd_si512(a), m, _mm512_castpd_si512(a), sign));
}
// -v where \p m is set.
__attribute__((target("avx512f"), always_inline)) inline Vec8d negateWhere(__mmask8 m,
                                                                           const Vec8d& v) {
    return {flipWhere(m, v.x), flipWhere(m, v.y), flipWhere(m, v.z)};
}
__attribute__((target("avx512f"), always_inline)) inline Vec8d gather8(__m512i at,
                                                                       const double* p) {
    return {_mm512_i64gather_pd(at, p, 8), _mm512_i64gather_pd(at, p + 1, 8),
            _mm512_i64gather_pd(at, p + 2, 8)};
}

// edge + t x across as floats, into three rows of eight.
__attribute__((target("avx512f"), always_inline)) inline void
putCorner(float (*row)[8], const Vec8d& edge, __m512d t, const Vec8d& across) {
    _mm256_store_ps(row[0], _mm512_cvtpd_ps(add(edge.x, mul(t, across.x))));
    _mm256_store_ps(row[1], _mm512_cvtpd_ps(add(edge.y, mul(t, across.y))));
    _mm256_store_ps(row[2], _mm512_cvtpd_ps(add(edge.z, mul(t, across.z))));
}

} // namespace

// cardAxes, extentAvx512 and cardRect / cardCorners of eight cards a zmm register, each lane the
// scalar operations in order (unfused): the axes' four normalisations, the extent over the kept
// corners and the corners as floats. False (nothing written) where a lane's e2 runs along its
// e1 (the scalar path's anyPerpendicular).
__attribute__((target("avx512f"))) bool finishAvx512(const CardFitLanes& lanes,
                                                     const CardFitInput* in,
                                                     const std::span<const std::uint32_t>* group,
                                                     const glm::dvec3* e1p, const glm::dvec3* e2p,
                                                     std::size_t n, glm::vec3* const* out) {
    static_assert(sizeof(CardFitInput) % sizeof(double) == 0 && sizeof(glm::dvec3) == 24);
    constexpr long long kIn = sizeof(CardFitInput) / sizeof(double);
    long long inLane[8], vecLane[8];
    alignas(64) double size[8];
    for (std::size_t k = 0; k < 8; ++k) {
        const std::size_t l = k < n ? k : 0;
        inLane[k] = static_cast<long long>(l) * kIn;
        vecLane[k] = static_cast<long long>(l) * 3;
        size[k] = static_cast<double>(group[l].size());
    }
    const __m512i inAt = _mm512_loadu_si512(inLane);
    const __m512i vecAt = _mm512_loadu_si512(vecLane);
    const Vec8d e1 = gather8(vecAt, &e1p[0].x);
    Vec8d e2 = gather8(vecAt, &e2p[0].x);
    const Vec8d heading = gather8(inAt, &in[0].heading.x);
    const Vec8d up = gather8(inAt, &in[0].up.x);
    const Vec8d m = gather8(inAt, &in[0].m.x);
    const __m512d zero = _mm512_setzero_pd();
    // e2 less its part along e1, normalised (scaledBy).
    const __m512d d = dot8(e2, e1);
    e2 = {sub(e2.x, mul(d, e1.x)), sub(e2.y, mul(d, e1.y)), sub(e2.z, mul(d, e1.z))};
    const __m512d e2Length = sqrt8(dot8(e2, e2));
    if (_mm512_cmp_pd_mask(e2Length, _mm512_set1_pd(1e-9), _CMP_LT_OQ) != 0) return false;
    e2 = scale8(e2, inverse8(e2Length));
    // n: normalize(cross(e1, e2)), turned toward the leaves' up.
    Vec8d c = cross8(e1, e2);
    c = scale8(c, inverse8(sqrt8(dot8(c, c))));
    c = negateWhere(_mm512_cmp_pd_mask(dot8(c, up), zero, _CMP_LT_OQ), c);
    // along: the mean heading in the plane where it is long enough, else +-e1.
    const __m512d h = dot8(heading, c);
    const Vec8d inPlane = {sub(heading.x, mul(h, c.x)), sub(heading.y, mul(h, c.y)),
                           sub(heading.z, mul(h, c.z))};
    const __m512d length = sqrt8(dot8(inPlane, inPlane));
    const Vec8d scaled = scale8(inPlane, inverse8(length));
    const Vec8d e1Turned = negateWhere(_mm512_cmp_pd_mask(dot8(e1, heading), zero, _CMP_LT_OQ), e1);
    const __mmask8 longEnough =
        _mm512_cmp_pd_mask(length, mul(_mm512_set1_pd(0.2), _mm512_load_pd(size)), _CMP_GT_OQ);
    const Vec8d along = {_mm512_mask_blend_pd(longEnough, e1Turned.x, scaled.x),
                         _mm512_mask_blend_pd(longEnough, e1Turned.y, scaled.y),
                         _mm512_mask_blend_pd(longEnough, e1Turned.z, scaled.z)};
    Vec8d across = cross8(c, along);
    across = scale8(across, inverse8(sqrt8(dot8(across, across))));
    // The extent (extent8, as extentAvx512's).
    const Extent8 e = extent8(lanes, m, along, across);
    const __m512d a0 = e.a0, a1 = e.a1, c0 = e.c0, c1 = e.c1;
    // cardRect: shrunk about its middle.
    const __m512d half = _mm512_set1_pd(0.5), shrink = _mm512_set1_pd(kCardShrink);
    const __m512d am = mul(half, add(a0, a1)), cm = mul(half, add(c0, c1));
    const __m512d A0 = add(am, mul(shrink, sub(a0, am))), A1 = add(am, mul(shrink, sub(a1, am)));
    const __m512d C0 = add(cm, mul(shrink, sub(c0, cm))), C1 = add(cm, mul(shrink, sub(c1, cm)));
    const Vec8d lo = {add(m.x, mul(A0, along.x)), add(m.y, mul(A0, along.y)),
                      add(m.z, mul(A0, along.z))};
    const Vec8d hi = {add(m.x, mul(A1, along.x)), add(m.y, mul(A1, along.y)),
                      add(m.z, mul(A1, along.z))};
    // cardCorners: lo + c1, lo + c0, hi + c0, hi + c1 across, then the normal, as floats.
    alignas(32) float f[15][8];
    putCorner(f + 0, lo, C1, across);
    putCorner(f + 3, lo, C0, across);
    putCorner(f + 6, hi, C0, across);
    putCorner(f + 9, hi, C1, across);
    _mm256_store_ps(f[12], _mm512_cvtpd_ps(c.x));
    _mm256_store_ps(f[13], _mm512_cvtpd_ps(c.y));
    _mm256_store_ps(f[14], _mm512_cvtpd_ps(c.z));
    for (std::size_t k = 0; k < n; ++k)
        for (int v = 0; v < 5; ++v)
            out[k][v] = glm::vec3(f[3 * v][k], f[3 * v + 1][k], f[3 * v + 2][k]);
    return true;
}

// secondMatrix of eight cards a zmm register, each lane the scalar operations in order
// (unfused): l1 = dot(e1, cov * e1), rest = cov - l1 x outerProduct(e1, e1), the second seed
// left - dot(left, e1) e1 normalised. False (nothing written) where a lane's seed vanishes (the
// scalar path's anyPerpendicular).
__attribute__((target("avx512f"))) bool secondAvx512(const CardFitInput* in, const glm::dvec3* e1p,
                                                     std::size_t n, glm::dmat3* rest,
                                                     glm::dvec3* seed2) {
    static_assert(sizeof(CardFitInput) % sizeof(double) == 0 && sizeof(glm::dvec3) == 24);
    constexpr long long kIn = sizeof(CardFitInput) / sizeof(double);
    long long inLane[8], vecLane[8];
    for (std::size_t k = 0; k < 8; ++k) {
        const std::size_t l = k < n ? k : 0;
        inLane[k] = static_cast<long long>(l) * kIn;
        vecLane[k] = static_cast<long long>(l) * 3;
    }
    const __m512i inAt = _mm512_loadu_si512(inLane);
    const __m512i vecAt = _mm512_loadu_si512(vecLane);
    const Vec8d e1 = gather8(vecAt, &e1p[0].x);
    const Vec8d left = gather8(inAt, &in[0].left.x);
    __m512d cov[3][3];
    for (int col = 0; col < 3; ++col)
        for (int row = 0; row < 3; ++row)
            cov[col][row] = _mm512_i64gather_pd(inAt, &in[0].cov[col][row], 8);
    // The seed first: a lane whose seed vanishes refuses the register before anything is written.
    const __m512d along = dot8(left, e1);
    const Vec8d s2 = {sub(left.x, mul(along, e1.x)), sub(left.y, mul(along, e1.y)),
                      sub(left.z, mul(along, e1.z))};
    const __m512d length = sqrt8(dot8(s2, s2));
    if (_mm512_cmp_pd_mask(length, _mm512_set1_pd(1e-9), _CMP_LT_OQ) != 0) return false;
    const Vec8d seed = scale8(s2, inverse8(length));
    // cov * e1: row r is (m[0][r] x + m[1][r] y) + m[2][r] z.
    const __m512d e[3] = {e1.x, e1.y, e1.z};
    __m512d ce[3];
    for (int row = 0; row < 3; ++row)
        ce[row] = add(add(mul(cov[0][row], e1.x), mul(cov[1][row], e1.y)), mul(cov[2][row], e1.z));
    const __m512d l1 = add(add(mul(e1.x, ce[0]), mul(e1.y, ce[1])), mul(e1.z, ce[2]));
    alignas(64) double r[9][8], v[3][8];
    for (int col = 0; col < 3; ++col)
        for (int row = 0; row < 3; ++row)
            _mm512_store_pd(r[3 * col + row], sub(cov[col][row], mul(mul(e[row], e[col]), l1)));
    _mm512_store_pd(v[0], seed.x);
    _mm512_store_pd(v[1], seed.y);
    _mm512_store_pd(v[2], seed.z);
    for (std::size_t k = 0; k < n; ++k) {
        rest[k] = glm::dmat3(r[0][k], r[1][k], r[2][k], r[3][k], r[4][k], r[5][k], r[6][k], r[7][k],
                             r[8][k]);
        seed2[k] = glm::dvec3(v[0][k], v[1][k], v[2][k]);
    }
    return true;
}

} // namespace sylva::mesh::lanes512

#endif
