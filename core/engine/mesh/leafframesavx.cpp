#include "engine/mesh/leafframesavx.h"

#include <cstdlib>

#include "engine/util/x86intrinsics.h"
#if defined(SYLVA_X86_INTRINSICS)
#define SYLVA_LEAF_FRAMES_AVX 1
#endif

namespace sylva::mesh {

#if SYLVA_LEAF_FRAMES_AVX
namespace {

// Sixteen floats as two AVX registers, each operation made on both in turn (two chains of
// square roots and divisions interleaved, as the SSE2 path's four registers). Built for AVX
// alone (no fused multiply-add: each product and sum rounds as the scalar ones), every helper
// with the target so that it inlines into leafFramesAvx16.
#define SYLVA_AVX __attribute__((target("avx"), always_inline)) inline
struct V {
    __m256 a, b;
};
SYLVA_AVX V all(float v) {
    return {_mm256_set1_ps(v), _mm256_set1_ps(v)};
}
SYLVA_AVX V load(const float* f) {
    return {_mm256_loadu_ps(f), _mm256_loadu_ps(f + 8)};
}
SYLVA_AVX void store(float* f, V x) {
    _mm256_storeu_ps(f, x.a);
    _mm256_storeu_ps(f + 8, x.b);
}
SYLVA_AVX V operator+(V x, V y) {
    return {_mm256_add_ps(x.a, y.a), _mm256_add_ps(x.b, y.b)};
}
SYLVA_AVX V operator-(V x, V y) {
    return {_mm256_sub_ps(x.a, y.a), _mm256_sub_ps(x.b, y.b)};
}
SYLVA_AVX V operator*(V x, V y) {
    return {_mm256_mul_ps(x.a, y.a), _mm256_mul_ps(x.b, y.b)};
}
SYLVA_AVX V operator/(V x, V y) {
    return {_mm256_div_ps(x.a, y.a), _mm256_div_ps(x.b, y.b)};
}
SYLVA_AVX V negate(V x) { // the sign bit flipped, as glm's unary minus on floats
    const __m256 sign = _mm256_set1_ps(-0.0f);
    return {_mm256_xor_ps(x.a, sign), _mm256_xor_ps(x.b, sign)};
}
// b where the comparison's mask is set, else a (and / and-not / or: GCC lowers blendv on AVX
// without AVX2 to a lane at a time).
SYLVA_AVX __m256 select(__m256 a, __m256 b, __m256 mask) {
    return _mm256_or_ps(_mm256_and_ps(mask, b), _mm256_andnot_ps(mask, a));
}
SYLVA_AVX V root(V x) {
    return {_mm256_sqrt_ps(x.a), _mm256_sqrt_ps(x.b)};
}
SYLVA_AVX V dot(V ax, V ay, V az, V bx, V by, V bz) {
    return ax * bx + ay * by + az * bz;
}
template <int kPredicate> SYLVA_AVX unsigned mask(V x, V y) {
    return static_cast<unsigned>(_mm256_movemask_ps(_mm256_cmp_ps(x.a, y.a, kPredicate)) |
                                 _mm256_movemask_ps(_mm256_cmp_ps(x.b, y.b, kPredicate)) << 8);
}
// quatOfFrame's running choice: where f is larger than big, big becomes f and index i (the
// index a float: AVX has no integer lanes).
SYLVA_AVX void take(V f, float i, V& big, V& index) {
    const __m256 ii = _mm256_set1_ps(i);
    const __m256 moreA = _mm256_cmp_ps(f.a, big.a, _CMP_GT_OQ);
    const __m256 moreB = _mm256_cmp_ps(f.b, big.b, _CMP_GT_OQ);
    big = {select(big.a, f.a, moreA), select(big.b, f.b, moreB)};
    index = {select(index.a, ii, moreA), select(index.b, ii, moreB)};
}
// Each lane's c_i for its index i (0..3): the value's bits unchanged.
SYLVA_AVX __m256 pick(__m256 ix, __m256 c0, __m256 c1, __m256 c2, __m256 c3) {
    const __m256 c01 = select(c0, c1, _mm256_cmp_ps(ix, _mm256_set1_ps(1.0f), _CMP_EQ_OQ));
    const __m256 c23 = select(c2, c3, _mm256_cmp_ps(ix, _mm256_set1_ps(3.0f), _CMP_EQ_OQ));
    return select(c01, c23, _mm256_cmp_ps(ix, _mm256_set1_ps(2.0f), _CMP_GE_OQ));
}
SYLVA_AVX V pick(V index, V a0, V a1, V a2, V a3) {
    return {pick(index.a, a0.a, a1.a, a2.a, a3.a), pick(index.b, a0.b, a1.b, a2.b, a3.b)};
}
#undef SYLVA_AVX

// Read once (util/x86intrinsics).
const bool kHasAvx = simd::useAvx();
// SYLVA_NO_AVX512=1 takes the AVX lanes on a processor with AVX-512 (their tests run them).
const bool kHasAvx512 = simd::useAvx512();

// Sixty-four floats as four AVX-512 registers, each operation made on all four in turn. The
// AVX path's sixteen lanes were bound by their chain (three square roots and divisions, the
// pick, the normalisation: ~250 cycles by the latencies) more than by their instructions; four
// 16-lane chains a call interleave, in as many instructions as one AVX call. The sums and
// differences by the _round forms with the current rounding: GCC contracts a product into the
// generic vector sum _mm512_add_ps is written as (a fused multiply-add rounds once, not twice);
// the builtins it does not. Each lane's operations the AVX ones in order: the same bits.
#define SYLVA_AVX512 __attribute__((target("avx512f"), always_inline)) inline
constexpr int kZmm = 4;
struct W {
    __m512 r[kZmm];
};
// Each operation a register at a time, written out (a lambda would lack the target).
#define SYLVA_W_OP(expr)                                                                           \
    W p;                                                                                           \
    for (int i = 0; i < kZmm; ++i)                                                                 \
        p.r[i] = expr;                                                                             \
    return p
SYLVA_AVX512 W all512(float v) {
    SYLVA_W_OP(_mm512_set1_ps(v));
}
SYLVA_AVX512 W load512(const float* f) {
    SYLVA_W_OP(_mm512_loadu_ps(f + 16 * i));
}
SYLVA_AVX512 void store512(float* f, const W& x) {
    for (int i = 0; i < kZmm; ++i)
        _mm512_storeu_ps(f + 16 * i, x.r[i]);
}
SYLVA_AVX512 W operator+(const W& x, const W& y) {
    SYLVA_W_OP(_mm512_add_round_ps(x.r[i], y.r[i], _MM_FROUND_CUR_DIRECTION));
}
SYLVA_AVX512 W operator-(const W& x, const W& y) {
    SYLVA_W_OP(_mm512_sub_round_ps(x.r[i], y.r[i], _MM_FROUND_CUR_DIRECTION));
}
SYLVA_AVX512 W operator*(const W& x, const W& y) {
    SYLVA_W_OP(_mm512_mul_ps(x.r[i], y.r[i]));
}
SYLVA_AVX512 W operator/(const W& x, const W& y) {
    SYLVA_W_OP(_mm512_div_ps(x.r[i], y.r[i]));
}
SYLVA_AVX512 W negate(const W& x) { // the sign bit flipped, as glm's unary minus on floats
    const __m512i sign = _mm512_set1_epi32(static_cast<int>(0x80000000u));
    SYLVA_W_OP(_mm512_castsi512_ps(_mm512_xor_si512(_mm512_castps_si512(x.r[i]), sign)));
}
SYLVA_AVX512 W root(const W& x) {
    SYLVA_W_OP(_mm512_sqrt_ps(x.r[i]));
}
#undef SYLVA_W_OP
SYLVA_AVX512 W dot(const W& ax, const W& ay, const W& az, const W& bx, const W& by, const W& bz) {
    return ax * bx + ay * by + az * bz;
}
template <int kPredicate> SYLVA_AVX512 std::uint64_t mask(const W& x, const W& y) {
    std::uint64_t m = 0;
    for (int i = 0; i < kZmm; ++i)
        m |= static_cast<std::uint64_t>(_mm512_cmp_ps_mask(x.r[i], y.r[i], kPredicate)) << (16 * i);
    return m;
}
// quatOfFrame's running choice, kept as the three "larger" masks: where f_i is larger than the
// running biggest, big becomes f_i; the index is the last i whose mask is set (0 if none).
struct Choice {
    __mmask16 more[3][kZmm];
};
SYLVA_AVX512 void take(const W& f, int i, W& big, Choice& c) {
    for (int k = 0; k < kZmm; ++k) {
        c.more[i][k] = _mm512_cmp_ps_mask(f.r[k], big.r[k], _CMP_GT_OQ);
        big.r[k] = _mm512_mask_mov_ps(big.r[k], c.more[i][k], f.r[k]);
    }
}
// Each lane's a_i for its index i: a0, then a1, a2, a3 moved in where their masks are set
// (a later mask overrides an earlier one, as a later index does): the value's bits unchanged.
SYLVA_AVX512 W pick(const Choice& c, const W& a0, const W& a1, const W& a2, const W& a3) {
    W p;
    for (int k = 0; k < kZmm; ++k) {
        __m512 v = _mm512_mask_mov_ps(a0.r[k], c.more[0][k], a1.r[k]);
        v = _mm512_mask_mov_ps(v, c.more[1][k], a2.r[k]);
        p.r[k] = _mm512_mask_mov_ps(v, c.more[2][k], a3.r[k]);
    }
    return p;
}
#undef SYLVA_AVX512

} // namespace

bool leafFramesAvx() {
    return kHasAvx;
}

bool leafFramesAvx512() {
    return kHasAvx512;
}

__attribute__((target("avx512f"))) std::uint64_t
leafFramesAvx512x64(const LeafFrameWeights& w, const float* const in[7], float q[4][64]) {
    const W sp = all512(w.sinPetiole), cp = all512(w.cosPetiole);
    const W nw = all512(w.normal), uw = all512(w.up), lw = all512(w.light);
    const W zero = all512(0.0f), one = all512(1.0f);
    const W upX = uw * zero, upY = uw * one, upZ = upX;
    const W lwX = lw * all512(w.lightX), lwY = lw * all512(w.lightY), lwZ = lw * all512(w.lightZ);
    const W tx = load512(in[0]), ty = load512(in[1]), tz = load512(in[2]);
    const W rx = load512(in[3]), ry = load512(in[4]), rz = load512(in[5]);
    const W fw = load512(in[6]);
    W hx = sp * rx + cp * tx + fw * tx;
    W hy = sp * ry + cp * ty + fw * ty;
    W hz = sp * rz + cp * tz + fw * tz;
    W inv = one / root(dot(hx, hy, hz, hx, hy, hz));
    hx = hx * inv;
    hy = hy * inv;
    hz = hz * inv;
    W nx = nw * rx + upX + lwX;
    W ny = nw * ry + upY + lwY;
    W nz = nw * rz + upZ + lwZ;
    const W nh = dot(nx, ny, nz, hx, hy, hz);
    nx = nx - nh * hx;
    ny = ny - nh * hy;
    nz = nz - nh * hz;
    const W nn = dot(nx, ny, nz, nx, ny, nz);
    // A lane whose normal is (nearly) along its heading takes the scalar frame's other branch.
    const std::uint64_t odd = mask<_CMP_LT_OQ>(nn, all512(1e-8f));
    inv = one / root(nn);
    nx = nx * inv;
    ny = ny * inv;
    nz = nz * inv;
    // l = cross(n, h); the frame's matrix is (-l, h, n) by columns.
    const W lx = ny * hz - hy * nz;
    const W ly = nz * hx - hz * nx;
    const W lz = nx * hy - hx * ny;
    const W m00 = negate(lx), m01 = negate(ly), m02 = negate(lz);
    const W m10 = hx, m11 = hy, m12 = hz, m20 = nx, m21 = ny, m22 = nz;
    // quatOfFrame.
    const W fx = m00 - m11 - m22;
    const W fy = m11 - m00 - m22;
    const W fz = m22 - m00 - m11;
    W big = m00 + m11 + m22;
    Choice c;
    take(fx, 0, big, c);
    take(fy, 1, big, c);
    take(fz, 2, big, c);
    const W bv = root(big + one) * all512(0.5f);
    const W mult = all512(0.25f) / bv;
    const W v1 = (m12 - m21) * mult, v2 = (m20 - m02) * mult, v3 = (m01 - m10) * mult;
    const W v4 = (m01 + m10) * mult, v5 = (m20 + m02) * mult, v6 = (m12 + m21) * mult;
    const W qw = pick(c, bv, v1, v2, v3), qx = pick(c, v1, bv, v4, v5);
    const W qy = pick(c, v2, v4, bv, v6), qz = pick(c, v3, v5, v6, bv);
    // glm::normalize(quat): (w w + x x) + (y y + z z), one over its root.
    const W len = root((qw * qw + qx * qx) + (qy * qy + qz * qz));
    const std::uint64_t flat = mask<_CMP_LE_OQ>(len, zero);
    const W over = one / len;
    store512(q[0], qw * over);
    store512(q[1], qx * over);
    store512(q[2], qy * over);
    store512(q[3], qz * over);
    return odd | flat;
}

__attribute__((target("avx"))) unsigned leafFramesAvx16(const LeafFrameWeights& w,
                                                        const float* const in[7], float q[4][16]) {
    const V sp = all(w.sinPetiole), cp = all(w.cosPetiole);
    const V nw = all(w.normal), uw = all(w.up), lw = all(w.light);
    const V zero = all(0.0f), one = all(1.0f);
    const V upX = uw * zero, upY = uw * one, upZ = upX;
    const V lwX = lw * all(w.lightX), lwY = lw * all(w.lightY), lwZ = lw * all(w.lightZ);
    const V tx = load(in[0]), ty = load(in[1]), tz = load(in[2]);
    const V rx = load(in[3]), ry = load(in[4]), rz = load(in[5]);
    const V fw = load(in[6]);
    V hx = sp * rx + cp * tx + fw * tx;
    V hy = sp * ry + cp * ty + fw * ty;
    V hz = sp * rz + cp * tz + fw * tz;
    V inv = one / root(dot(hx, hy, hz, hx, hy, hz));
    hx = hx * inv;
    hy = hy * inv;
    hz = hz * inv;
    V nx = nw * rx + upX + lwX;
    V ny = nw * ry + upY + lwY;
    V nz = nw * rz + upZ + lwZ;
    const V nh = dot(nx, ny, nz, hx, hy, hz);
    nx = nx - nh * hx;
    ny = ny - nh * hy;
    nz = nz - nh * hz;
    const V nn = dot(nx, ny, nz, nx, ny, nz);
    // A lane whose normal is (nearly) along its heading takes the scalar frame's other branch.
    const unsigned odd = mask<_CMP_LT_OQ>(nn, all(1e-8f));
    inv = one / root(nn);
    nx = nx * inv;
    ny = ny * inv;
    nz = nz * inv;
    // l = cross(n, h); the frame's matrix is (-l, h, n) by columns.
    const V lx = ny * hz - hy * nz;
    const V ly = nz * hx - hz * nx;
    const V lz = nx * hy - hx * ny;
    const V m00 = negate(lx), m01 = negate(ly), m02 = negate(lz);
    const V m10 = hx, m11 = hy, m12 = hz, m20 = nx, m21 = ny, m22 = nz;
    // quatOfFrame.
    const V fx = m00 - m11 - m22;
    const V fy = m11 - m00 - m22;
    const V fz = m22 - m00 - m11;
    V big = m00 + m11 + m22;
    V index = zero;
    take(fx, 1.0f, big, index);
    take(fy, 2.0f, big, index);
    take(fz, 3.0f, big, index);
    const V bv = root(big + one) * all(0.5f);
    const V mult = all(0.25f) / bv;
    const V v1 = (m12 - m21) * mult, v2 = (m20 - m02) * mult, v3 = (m01 - m10) * mult;
    const V v4 = (m01 + m10) * mult, v5 = (m20 + m02) * mult, v6 = (m12 + m21) * mult;
    const V qw = pick(index, bv, v1, v2, v3), qx = pick(index, v1, bv, v4, v5);
    const V qy = pick(index, v2, v4, bv, v6), qz = pick(index, v3, v5, v6, bv);
    // glm::normalize(quat): (w w + x x) + (y y + z z), one over its root.
    const V len = root((qw * qw + qx * qx) + (qy * qy + qz * qz));
    const unsigned flat = mask<_CMP_LE_OQ>(len, zero);
    const V over = one / len;
    store(q[0], qw * over);
    store(q[1], qx * over);
    store(q[2], qy * over);
    store(q[3], qz * over);
    return odd | flat;
}

#else

bool leafFramesAvx() {
    return false;
}

unsigned leafFramesAvx16(const LeafFrameWeights&, const float* const[7], float[4][16]) {
    return 0xffffu; // never called: every lane to the scalar path
}

bool leafFramesAvx512() {
    return false;
}

std::uint64_t leafFramesAvx512x64(const LeafFrameWeights&, const float* const[7], float[4][64]) {
    return ~std::uint64_t{0}; // never called: every lane to the scalar path
}

#endif

} // namespace sylva::mesh
