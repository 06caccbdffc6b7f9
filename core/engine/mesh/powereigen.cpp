#include "engine/mesh/powereigen.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>

#include <cstdlib>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif
#include "engine/util/x86intrinsics.h"
#if defined(SYLVA_X86_INTRINSICS) && defined(__SSE2__)
#define SYLVA_POWER_AVX512 1
#else
#define SYLVA_POWER_AVX512 0
#endif

namespace sylva::mesh {

namespace {

constexpr int kPowerSteps = 24;
// The lanes of the SSE2 pairs (four pairs).
constexpr std::size_t kPairLanes = 8;
constexpr int kBlock = 4;
// A product of kBlock steps of a unit-sum matrix under this vanishes: the matrix's product
// does (1e-18 a step).
constexpr double kVanish = 1e-72;
constexpr double kStepVanish = 1e-18;
// The biased exponent field of 2^(-ceil(e / 2)) for a positive double of biased exponent field
// E (e = E - 1023): 1534 - (E >> 1). A vector of squared length len2 times it is between
// sqrt(1/2) and sqrt(2) long; E = 0 (zero, subnormal) gives 2^511, in range.
constexpr std::uint64_t kHalfExponentBias = 1534;

[[maybe_unused]] double powerOfTwoScale(double len2) {
    const std::uint64_t field = kHalfExponentBias - (std::bit_cast<std::uint64_t>(len2) >> 53);
    return std::bit_cast<double>(field << 52);
}

#if SYLVA_POWER_AVX512
// Read once (util/x86intrinsics).
// SYLVA_NO_AVX512=1 (or SYLVA_NO_AVX=1) takes the SSE2 pairs on a processor with AVX-512.
const bool kHasAvx512 = simd::useAvx512();

using simd::add; // unfused: the SSE2 pairs' bits
using simd::mul;

// Eight lanes an AVX-512 register, R registers side by side (the SSE2 pairs' 48 registers of
// matrices and vectors spilled to the stack, four pairs an operation; one register's chain of
// 24 products waits on each operation before it, two chains overlap): each lane the SSE2 path's
// operations in order, the same bits. The matrices and starts gathered (lanes past n: zeros, as
// there).
template <int R>
__attribute__((target("avx512f"))) void largestEigenvectorsAvx512(const glm::dmat3* c,
                                                                  glm::dvec3* v, std::size_t n) {
    const __m512d zero = _mm512_setzero_pd();
    const __m512d one = _mm512_set1_pd(1.0);
    const __m512i mIndex = _mm512_set_epi64(63, 54, 45, 36, 27, 18, 9, 0);
    const __m512i vIndex = _mm512_set_epi64(21, 18, 15, 12, 9, 6, 3, 0);
    __mmask8 live[R];
    __m512d M[R][9], X[R], Y[R], Z[R], sum[R];
    for (int r = 0; r < R; ++r) {
        const std::size_t first = 8 * static_cast<std::size_t>(r);
        const std::size_t lanes = n > first ? std::min<std::size_t>(8, n - first) : 0;
        live[r] = static_cast<__mmask8>((1u << lanes) - 1u);
        sum[r] = zero;
    }
    for (int e = 0; e < 9; ++e)
        for (int r = 0; r < R; ++r) {
            M[r][e] = _mm512_mask_i64gather_pd(zero, live[r], mIndex, &c[8 * r][0][0] + e, 8);
            sum[r] = add(sum[r], _mm512_abs_pd(M[r][e]));
        }
    for (int r = 0; r < R; ++r) {
        // sum > 0 ? 1 / sum : 0, lane by lane.
        const __m512d scale = _mm512_maskz_div_round_pd(
            _mm512_cmp_pd_mask(sum[r], zero, _CMP_GT_OQ), one, sum[r], _MM_FROUND_CUR_DIRECTION);
        for (int e = 0; e < 9; ++e)
            M[r][e] = mul(M[r][e], scale);
        const double* const vm = &v[8 * r][0];
        X[r] = _mm512_mask_i64gather_pd(zero, live[r], vIndex, vm, 8);
        Y[r] = _mm512_mask_i64gather_pd(zero, live[r], vIndex, vm + 1, 8);
        Z[r] = _mm512_mask_i64gather_pd(zero, live[r], vIndex, vm + 2, 8);
    }
    static_assert(kBlock == 4);
    for (int s = 0; s < 2; ++s)
        for (int r = 0; r < R; ++r) {
            const __m512d* const a = M[r];
            __m512d p[9];
            for (int col = 0; col < 3; ++col)
                for (int row = col; row < 3; ++row)
                    p[3 * col + row] = p[3 * row + col] =
                        add(add(mul(a[row], a[3 * col]), mul(a[3 + row], a[3 * col + 1])),
                            mul(a[6 + row], a[3 * col + 2]));
            for (int e = 0; e < 9; ++e)
                M[r][e] = p[e];
        }
    const __m512d tiny2 = _mm512_set1_pd(kVanish * kVanish);
    const __m512i bias = _mm512_set1_epi64(static_cast<long long>(kHalfExponentBias));
    __mmask8 done[R] = {};
    for (int i = 0; i < kPowerSteps; i += kBlock)
        for (int r = 0; r < R; ++r) {
            const __m512d* const q = M[r];
            const __m512d px = X[r], py = Y[r], pz = Z[r];
            const __m512d nx = add(add(mul(q[0], px), mul(q[3], py)), mul(q[6], pz));
            const __m512d ny = add(add(mul(q[1], px), mul(q[4], py)), mul(q[7], pz));
            const __m512d nz = add(add(mul(q[2], px), mul(q[5], py)), mul(q[8], pz));
            const __m512d len2 = add(add(mul(nx, nx), mul(ny, ny)), mul(nz, nz));
            done[r] |= _mm512_cmp_pd_mask(len2, tiny2, _CMP_LT_OQ);
            __m512d inv;
            if (i + kBlock < kPowerSteps) {
                const __m512i half = _mm512_srli_epi64(_mm512_castpd_si512(len2), 53);
                inv = _mm512_castsi512_pd(_mm512_slli_epi64(_mm512_sub_epi64(bias, half), 52));
            } else {
                // A kept lane's len may be 0: its quotient is discarded.
                inv =
                    _mm512_div_round_pd(one, _mm512_mask_mov_pd(_mm512_sqrt_pd(len2), done[r], one),
                                        _MM_FROUND_CUR_DIRECTION);
            }
            const auto go = static_cast<__mmask8>(~done[r]);
            X[r] = _mm512_mask_mul_round_pd(px, go, nx, inv, _MM_FROUND_CUR_DIRECTION);
            Y[r] = _mm512_mask_mul_round_pd(py, go, ny, inv, _MM_FROUND_CUR_DIRECTION);
            Z[r] = _mm512_mask_mul_round_pd(pz, go, nz, inv, _MM_FROUND_CUR_DIRECTION);
        }
    alignas(64) double x[8 * R], y[8 * R], z[8 * R];
    for (int r = 0; r < R; ++r) {
        _mm512_store_pd(x + 8 * r, X[r]);
        _mm512_store_pd(y + 8 * r, Y[r]);
        _mm512_store_pd(z + 8 * r, Z[r]);
    }
    for (std::size_t k = 0; k < n; ++k)
        v[k] = glm::dvec3(x[k], y[k], z[k]);
}
#endif

} // namespace

void largestEigenvectors(const glm::dmat3* c, glm::dvec3* v, std::size_t n) {
#if SYLVA_POWER_AVX512
    static_assert(kPowerLanes == 16, "two AVX-512 registers a matrix entry");
    if (kHasAvx512 && n > 0) {
        if (n > 8)
            largestEigenvectorsAvx512<2>(c, v, n);
        else
            largestEigenvectorsAvx512<1>(c, v, n);
        return;
    }
#endif
    largestEigenvectorsPairs(c, v, n);
}

namespace {

// largestEigenvectorsPairs of n <= kPairLanes matrices.
void pairs8(const glm::dmat3* c, glm::dvec3* v, std::size_t n) {
    double scale[kPairLanes];
    for (std::size_t k = 0; k < n; ++k) {
        double sum = 0.0;
        for (int col = 0; col < 3; ++col)
            for (int row = 0; row < 3; ++row)
                sum += std::abs(c[k][col][row]);
        scale[k] = sum > 0.0 ? 1.0 / sum : 0.0;
    }
#if defined(__SSE2__)
    // Lanes past n: a zero matrix, whose product vanishes at the first block.
    alignas(16) double m[9][kPairLanes] = {};
    alignas(16) double x[kPairLanes] = {}, y[kPairLanes] = {}, z[kPairLanes] = {};
    for (std::size_t k = 0; k < n; ++k) {
        for (int col = 0; col < 3; ++col)
            for (int row = 0; row < 3; ++row)
                m[3 * col + row][k] = c[k][col][row] * scale[k];
        x[k] = v[k].x;
        y[k] = v[k].y;
        z[k] = v[k].z;
    }
    constexpr int kPairs = static_cast<int>(kPairLanes / 2);
    __m128d M[kPairs][9], X[kPairs], Y[kPairs], Z[kPairs], done[kPairs];
    for (int h = 0; h < kPairs; ++h) {
        for (int e = 0; e < 9; ++e)
            M[h][e] = _mm_load_pd(&m[e][2 * h]);
        X[h] = _mm_load_pd(&x[2 * h]);
        Y[h] = _mm_load_pd(&y[2 * h]);
        Z[h] = _mm_load_pd(&z[2 * h]);
        done[h] = _mm_setzero_pd();
    }
    // Each pair's fourth power, two squarings: a block of kBlock products is one.
    static_assert(kBlock == 4);
    for (int h = 0; h < kPairs; ++h)
        for (int s = 0; s < 2; ++s) {
            const __m128d* a = M[h];
            __m128d p[9];
            // The power of a symmetric matrix is symmetric, bit for bit (entry (c, r) and
            // entry (r, c) multiply the same pairs in the same order): six entries made.
            for (int col = 0; col < 3; ++col)
                for (int row = col; row < 3; ++row)
                    p[3 * col + row] = p[3 * row + col] =
                        _mm_add_pd(_mm_add_pd(_mm_mul_pd(a[row], a[3 * col]),
                                              _mm_mul_pd(a[3 + row], a[3 * col + 1])),
                                   _mm_mul_pd(a[6 + row], a[3 * col + 2]));
            for (int e = 0; e < 9; ++e)
                M[h][e] = p[e];
        }
    const __m128d tiny2 = _mm_set1_pd(kVanish * kVanish);
    const __m128d one = _mm_set1_pd(1.0);
    const __m128i bias = _mm_set1_epi64x(static_cast<long long>(kHalfExponentBias));
    for (int i = 0; i < kPowerSteps; i += kBlock)
        for (int h = 0; h < kPairs; ++h) {
            const __m128d* q = M[h];
            const __m128d px = X[h], py = Y[h], pz = Z[h];
            const __m128d nx = _mm_add_pd(_mm_add_pd(_mm_mul_pd(q[0], px), _mm_mul_pd(q[3], py)),
                                          _mm_mul_pd(q[6], pz));
            const __m128d ny = _mm_add_pd(_mm_add_pd(_mm_mul_pd(q[1], px), _mm_mul_pd(q[4], py)),
                                          _mm_mul_pd(q[7], pz));
            const __m128d nz = _mm_add_pd(_mm_add_pd(_mm_mul_pd(q[2], px), _mm_mul_pd(q[5], py)),
                                          _mm_mul_pd(q[8], pz));
            const __m128d len2 =
                _mm_add_pd(_mm_add_pd(_mm_mul_pd(nx, nx), _mm_mul_pd(ny, ny)), _mm_mul_pd(nz, nz));
            done[h] = _mm_or_pd(done[h], _mm_cmplt_pd(len2, tiny2));
            const __m128d keep = done[h];
            __m128d inv;
            if (i + kBlock < kPowerSteps) {
                // Between blocks: powerOfTwoScale, lane by lane.
                const __m128i half = _mm_srli_epi64(_mm_castpd_si128(len2), 53);
                inv = _mm_castsi128_pd(_mm_slli_epi64(_mm_sub_epi64(bias, half), 52));
            } else {
                // A kept lane's len may be 0: its quotient is discarded.
                inv = _mm_div_pd(one, _mm_or_pd(_mm_sqrt_pd(len2), _mm_and_pd(keep, one)));
            }
            if (_mm_movemask_pd(keep) == 0) { // no lane kept: the usual case
                X[h] = _mm_mul_pd(nx, inv);
                Y[h] = _mm_mul_pd(ny, inv);
                Z[h] = _mm_mul_pd(nz, inv);
                continue;
            }
            X[h] = _mm_or_pd(_mm_and_pd(keep, X[h]), _mm_andnot_pd(keep, _mm_mul_pd(nx, inv)));
            Y[h] = _mm_or_pd(_mm_and_pd(keep, Y[h]), _mm_andnot_pd(keep, _mm_mul_pd(ny, inv)));
            Z[h] = _mm_or_pd(_mm_and_pd(keep, Z[h]), _mm_andnot_pd(keep, _mm_mul_pd(nz, inv)));
        }
    for (int h = 0; h < kPairs; ++h) {
        _mm_store_pd(&x[2 * h], X[h]);
        _mm_store_pd(&y[2 * h], Y[h]);
        _mm_store_pd(&z[2 * h], Z[h]);
    }
    for (std::size_t k = 0; k < n; ++k)
        v[k] = glm::dvec3(x[k], y[k], z[k]);
#else
    for (std::size_t k = 0; k < n; ++k) {
        const glm::dmat3 a = c[k] * scale[k];
        const glm::dmat3 a2 = a * a;
        const glm::dmat3 a4 = a2 * a2;
        for (int i = 0; i < kPowerSteps; i += kBlock) {
            const glm::dvec3 next = a4 * v[k];
            const double len2 = glm::dot(next, next);
            if (len2 < kVanish * kVanish) break;
            v[k] =
                next * (i + kBlock < kPowerSteps ? powerOfTwoScale(len2) : 1.0 / std::sqrt(len2));
        }
    }
#endif
}

} // namespace

void largestEigenvectorsPairs(const glm::dmat3* c, glm::dvec3* v, std::size_t n) {
    for (std::size_t first = 0; first < n; first += kPairLanes)
        pairs8(c + first, v + first, std::min(kPairLanes, n - first));
}

void largestEigenvectorsStepwise(const glm::dmat3* c, glm::dvec3* v, std::size_t n) {
    for (std::size_t k = 0; k < n; ++k) {
        double sum = 0.0;
        for (int col = 0; col < 3; ++col)
            for (int row = 0; row < 3; ++row)
                sum += std::abs(c[k][col][row]);
        const glm::dmat3 a = c[k] * (sum > 0.0 ? 1.0 / sum : 0.0);
        for (int i = 0; i < kPowerSteps; ++i) {
            const glm::dvec3 next = a * v[k];
            const double len = glm::length(next);
            if (len < kStepVanish) break;
            v[k] = next / len;
        }
    }
}

} // namespace sylva::mesh
