#include "engine/mesh/leafcellhash.h"

#include "engine/util/x86intrinsics.h"

namespace sylva::mesh {

void leafCellsHashedPlain(const glm::dvec3* mids, std::size_t n, double cell, std::uint64_t mask,
                          LeafCell* cells, std::uint32_t* hashes) {
    for (std::size_t i = 0; i < n; ++i) {
        cells[i] = leafCell(mids[i], cell);
        hashes[i] = static_cast<std::uint32_t>(leafCellHash(cells[i]) & mask);
    }
}

#if defined(SYLVA_X86_INTRINSICS)
namespace {

#define SYLVA_CELLS512 __attribute__((target("avx512f,avx512dq"), always_inline)) inline

SYLVA_CELLS512 __m512i idx(long long i0, long long i1, long long i2, long long i3, long long i4,
                           long long i5, long long i6, long long i7) {
    return _mm512_setr_epi64(i0, i1, i2, i3, i4, i5, i6, i7);
}
// floor, exact for quotients under 2^51, then its (exact) integer.
SYLVA_CELLS512 __m512i floors(__m512d q) {
    return _mm512_cvttpd_epi64(_mm512_roundscale_pd(q, _MM_FROUND_TO_NEG_INF | _MM_FROUND_NO_EXC));
}
// h ^= v * k + (h << 6) + (h >> 2), leafCellHash's step.
SYLVA_CELLS512 __m512i mix(__m512i h, __m512i v, long long k) {
    const __m512i sum = _mm512_add_epi64(
        _mm512_add_epi64(_mm512_mullo_epi64(v, _mm512_set1_epi64(k)), _mm512_slli_epi64(h, 6)),
        _mm512_srli_epi64(h, 2));
    return _mm512_xor_si512(h, sum);
}

// Eight middles' cells and hashes (false, nothing written, where a quotient is 2^51 or more or
// NaN). The three axes gathered from the 24-byte middles by two permutes each, and the cells
// written back as 24-byte LeafCells the same way.
__attribute__((target("avx512f,avx512dq"))) bool cellsHashed8(const glm::dvec3* mids, double cell,
                                                              std::uint64_t mask, LeafCell* cells,
                                                              std::uint32_t* hashes) {
    const auto* p = reinterpret_cast<const double*>(mids);
    const __m512d a = _mm512_loadu_pd(p), b = _mm512_loadu_pd(p + 8), c = _mm512_loadu_pd(p + 16);
    // x: 0 3 6 9 12 15 | 18 21 (c's 2 and 5); y: 1 4 7 10 13 | 16 19 22; z: 2 5 8 11 14 | 17 20 23.
    const __m512d x =
        _mm512_permutex2var_pd(_mm512_permutex2var_pd(a, idx(0, 3, 6, 9, 12, 15, 0, 0), b),
                               idx(0, 1, 2, 3, 4, 5, 10, 13), c);
    const __m512d y =
        _mm512_permutex2var_pd(_mm512_permutex2var_pd(a, idx(1, 4, 7, 10, 13, 0, 0, 0), b),
                               idx(0, 1, 2, 3, 4, 8, 11, 14), c);
    const __m512d z =
        _mm512_permutex2var_pd(_mm512_permutex2var_pd(a, idx(2, 5, 8, 11, 14, 0, 0, 0), b),
                               idx(0, 1, 2, 3, 4, 9, 12, 15), c);
    const __m512d edge = _mm512_set1_pd(cell), bound = _mm512_set1_pd(0x1p51);
    const __m512d qx = _mm512_div_pd(x, edge), qy = _mm512_div_pd(y, edge),
                  qz = _mm512_div_pd(z, edge);
    const __mmask8 in = _mm512_cmp_pd_mask(_mm512_abs_pd(qx), bound, _CMP_LT_OQ) &
                        _mm512_cmp_pd_mask(_mm512_abs_pd(qy), bound, _CMP_LT_OQ) &
                        _mm512_cmp_pd_mask(_mm512_abs_pd(qz), bound, _CMP_LT_OQ);
    if (in != 0xff) return false;
    const __m512i ix = floors(qx), iy = floors(qy), iz = floors(qz);
    __m512i h =
        _mm512_mullo_epi64(ix, _mm512_set1_epi64(static_cast<long long>(0x9E3779B97F4A7C15ull)));
    h = mix(h, iy, static_cast<long long>(0xC2B2AE3D27D4EB4Full));
    h = mix(h, iz, static_cast<long long>(0x165667B19E3779F9ull));
    h = _mm512_and_si512(h, _mm512_set1_epi64(static_cast<long long>(mask)));
    _mm256_storeu_si256(reinterpret_cast<__m256i*>(hashes), _mm512_cvtepi64_epi32(h));
    // Back to x y z x y z ...: out0 = x0 y0 z0 x1 y1 z1 x2 y2, out1 = z2 x3 y3 z3 x4 y4 z4 x5,
    // out2 = y5 z5 x6 y6 z6 x7 y7 z7.
    const __m512i o0 =
        _mm512_permutex2var_epi64(_mm512_permutex2var_epi64(ix, idx(0, 8, 0, 1, 9, 0, 2, 10), iy),
                                  idx(0, 1, 8, 3, 4, 9, 6, 7), iz);
    const __m512i o1 =
        _mm512_permutex2var_epi64(_mm512_permutex2var_epi64(ix, idx(0, 3, 11, 0, 4, 12, 0, 5), iy),
                                  idx(10, 1, 2, 11, 4, 5, 12, 7), iz);
    const __m512i o2 =
        _mm512_permutex2var_epi64(_mm512_permutex2var_epi64(ix, idx(13, 0, 6, 14, 0, 7, 15, 0), iy),
                                  idx(0, 13, 2, 3, 14, 5, 6, 15), iz);
    auto* out = reinterpret_cast<__m512i*>(cells);
    _mm512_storeu_si512(out, o0);
    _mm512_storeu_si512(out + 1, o1);
    _mm512_storeu_si512(out + 2, o2);
    return true;
}

// SYLVA_NO_AVX512=1 (or SYLVA_NO_AVX=1) takes the plain cells on any processor.
const bool kCellsAvx512 = simd::useAvx512Dq();

} // namespace
#endif

void leafCellsHashed(const glm::dvec3* mids, std::size_t n, double cell, std::uint64_t mask,
                     LeafCell* cells, std::uint32_t* hashes) {
    std::size_t i = 0;
#if defined(SYLVA_X86_INTRINSICS)
    static_assert(sizeof(glm::dvec3) == 24 && sizeof(LeafCell) == 24);
    if (kCellsAvx512) {
        for (; i + 8 <= n; i += 8)
            if (!cellsHashed8(mids + i, cell, mask, cells + i, hashes + i))
                leafCellsHashedPlain(mids + i, 8, cell, mask, cells + i, hashes + i);
    }
#endif
    leafCellsHashedPlain(mids + i, n - i, cell, mask, cells + i, hashes + i);
}

} // namespace sylva::mesh
