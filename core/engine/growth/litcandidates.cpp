#include "engine/growth/litcandidates.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <new>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif
#include "engine/util/x86intrinsics.h"
#if defined(SYLVA_X86_INTRINSICS)
#define SYLVA_CANDIDATES_AVX 1
#endif

namespace sylva::growth {

namespace {

/// The first of the highest scores offered in index order (strict '>' from -1).
struct Best {
    float score = -1.0f;
    std::size_t at = std::numeric_limits<std::size_t>::max();
    void offer(float s, std::size_t k) {
        if (s > score) {
            score = s;
            at = k;
        }
    }
    /// A lane's best of candidates interleaved with the other lanes': a tie goes to the lower
    /// index.
    void offerLane(float s, std::size_t k) {
        if (s > score || (s == score && k < at)) {
            score = s;
            at = k;
        }
    }
    std::size_t index(std::size_t none) const { return score > -1.0f ? at : none; }
};

/// The arrays a visit reads and writes.
struct Arrays {
    const float *x, *y, *z, *weight, *jitter;
    float* nearest;
    std::uint32_t* lit;
};

constexpr bool scores(CandidateVisit what) {
    return what == CandidateVisit::Spread || what == CandidateVisit::WeightedSpread;
}

/// f.template operator()<what>() for the value of \p what: the lane loops are made once per
/// kind of visit, without its tests inside them.
template <class F> std::size_t dispatch(CandidateVisit what, F&& f) {
    switch (what) {
    case CandidateVisit::Lit:
        return f.template operator()<CandidateVisit::Lit>();
    case CandidateVisit::Nearest:
        return f.template operator()<CandidateVisit::Nearest>();
    case CandidateVisit::Spread:
        return f.template operator()<CandidateVisit::Spread>();
    case CandidateVisit::WeightedSpread:
        return f.template operator()<CandidateVisit::WeightedSpread>();
    }
    return 0;
}

#if defined(__SSE2__)
/// The visit four candidates at a time from \p k, up to the last whole four; returns where it
/// stopped. Each lane: the scalar tail's operations in its order.
template <CandidateVisit what>
std::size_t visitSse2(const Arrays& arrays, std::size_t n, const glm::vec3& centre, float r2,
                      Best& b) {
    const Arrays a = arrays; // locals: the stores cannot make the compiler reload them
    const __m128 cx = _mm_set1_ps(centre.x), cy = _mm_set1_ps(centre.y), cz = _mm_set1_ps(centre.z),
                 vr2 = _mm_set1_ps(r2);
    __m128 top = _mm_set1_ps(-1.0f);
    __m128i topIndex = _mm_set1_epi32(-1), index = _mm_setr_epi32(0, 1, 2, 3);
    const __m128i four = _mm_set1_epi32(4);
    constexpr bool score = scores(what);
    std::size_t k = 0;
    for (; k + 4 <= n; k += 4) {
        const __m128 dx = _mm_sub_ps(_mm_loadu_ps(a.x + k), cx);
        const __m128 dy = _mm_sub_ps(_mm_loadu_ps(a.y + k), cy);
        const __m128 dz = _mm_sub_ps(_mm_loadu_ps(a.z + k), cz);
        const __m128 d2 =
            _mm_add_ps(_mm_add_ps(_mm_mul_ps(dx, dx), _mm_mul_ps(dy, dy)), _mm_mul_ps(dz, dz));
        auto* litAt = reinterpret_cast<__m128i*>(a.lit + k);
        _mm_storeu_si128(
            litAt, _mm_or_si128(_mm_loadu_si128(litAt), _mm_castps_si128(_mm_cmple_ps(d2, vr2))));
        if constexpr (what == CandidateVisit::Lit) continue;
        // minps(d2, nearest) = d2 < nearest ? d2 : nearest, std::min(nearest, d2) exactly.
        const __m128 nearest = _mm_min_ps(d2, _mm_loadu_ps(a.nearest + k));
        _mm_storeu_ps(a.nearest + k, nearest);
        if constexpr (!score) continue;
        const __m128 s = _mm_sqrt_ps(nearest);
        const __m128 w =
            what == CandidateVisit::WeightedSpread ? _mm_mul_ps(_mm_loadu_ps(a.weight + k), s) : s;
        const __m128 v = _mm_mul_ps(w, _mm_loadu_ps(a.jitter + k));
        // Strictly greater: within a lane the earlier candidate keeps a tie.
        const __m128 greater = _mm_cmpgt_ps(v, top);
        top = _mm_or_ps(_mm_and_ps(greater, v), _mm_andnot_ps(greater, top));
        const __m128i g = _mm_castps_si128(greater);
        topIndex = _mm_or_si128(_mm_and_si128(g, index), _mm_andnot_si128(g, topIndex));
        index = _mm_add_epi32(index, four);
    }
    if constexpr (score) {
        alignas(16) float tops[4];
        alignas(16) std::int32_t indices[4];
        _mm_store_ps(tops, top);
        _mm_store_si128(reinterpret_cast<__m128i*>(indices), topIndex);
        for (int l = 0; l < 4; ++l)
            if (indices[l] >= 0) b.offerLane(tops[l], static_cast<std::size_t>(indices[l]));
    }
    return k;
}
#endif

#if SYLVA_CANDIDATES_AVX
/// visitSse2 eight lanes at a time, built for AVX alone (chosen at run time). AVX has no
/// integer lanes: the indices are floats, exact below 2^24 candidates (the caller's limit).
template <CandidateVisit what>
__attribute__((target("avx"))) std::size_t visitAvx(const Arrays& arrays, std::size_t n,
                                                    const glm::vec3& centre, float r2, Best& b) {
    const Arrays a = arrays;
    const __m256 cx = _mm256_set1_ps(centre.x), cy = _mm256_set1_ps(centre.y),
                 cz = _mm256_set1_ps(centre.z), vr2 = _mm256_set1_ps(r2);
    __m256 top = _mm256_set1_ps(-1.0f), topIndex = _mm256_set1_ps(-1.0f);
    __m256 index = _mm256_setr_ps(0, 1, 2, 3, 4, 5, 6, 7);
    const __m256 eight = _mm256_set1_ps(8.0f);
    constexpr bool score = scores(what);
    std::size_t k = 0;
    for (; k + 8 <= n; k += 8) {
        const __m256 dx = _mm256_sub_ps(_mm256_loadu_ps(a.x + k), cx);
        const __m256 dy = _mm256_sub_ps(_mm256_loadu_ps(a.y + k), cy);
        const __m256 dz = _mm256_sub_ps(_mm256_loadu_ps(a.z + k), cz);
        const __m256 d2 = _mm256_add_ps(_mm256_add_ps(_mm256_mul_ps(dx, dx), _mm256_mul_ps(dy, dy)),
                                        _mm256_mul_ps(dz, dz));
        auto* litAt = reinterpret_cast<float*>(a.lit + k);
        _mm256_storeu_ps(litAt,
                         _mm256_or_ps(_mm256_loadu_ps(litAt), _mm256_cmp_ps(d2, vr2, _CMP_LE_OQ)));
        if constexpr (what == CandidateVisit::Lit) continue;
        const __m256 nearest = _mm256_min_ps(d2, _mm256_loadu_ps(a.nearest + k));
        _mm256_storeu_ps(a.nearest + k, nearest);
        if constexpr (!score) continue;
        const __m256 s = _mm256_sqrt_ps(nearest);
        const __m256 w = what == CandidateVisit::WeightedSpread
                             ? _mm256_mul_ps(_mm256_loadu_ps(a.weight + k), s)
                             : s;
        const __m256 v = _mm256_mul_ps(w, _mm256_loadu_ps(a.jitter + k));
        const __m256 greater = _mm256_cmp_ps(v, top, _CMP_GT_OQ);
        top = _mm256_or_ps(_mm256_and_ps(greater, v), _mm256_andnot_ps(greater, top));
        topIndex = _mm256_or_ps(_mm256_and_ps(greater, index), _mm256_andnot_ps(greater, topIndex));
        index = _mm256_add_ps(index, eight);
    }
    if constexpr (score) {
        alignas(32) float tops[8], indices[8];
        _mm256_store_ps(tops, top);
        _mm256_store_ps(indices, topIndex);
        for (int l = 0; l < 8; ++l)
            if (indices[l] >= 0.0f) b.offerLane(tops[l], static_cast<std::size_t>(indices[l]));
    }
    return k;
}

/// visitAvx sixteen lanes at a time, built for AVX-512F alone (chosen at run time): the sums
/// by the builtin with the current rounding (_mm512_add_ps is a generic vector sum, which GCC
/// would fuse with the products into multiply-adds here), the selections by masks, the
/// indices as integers.
template <CandidateVisit what>
__attribute__((target("avx512f"))) std::size_t
visitAvx512(const Arrays& arrays, std::size_t n, const glm::vec3& centre, float r2, Best& b) {
    const Arrays a = arrays;
    const __m512 cx = _mm512_set1_ps(centre.x), cy = _mm512_set1_ps(centre.y),
                 cz = _mm512_set1_ps(centre.z), vr2 = _mm512_set1_ps(r2);
    const __m512i allSet = _mm512_set1_epi32(-1);
    __m512 top = _mm512_set1_ps(-1.0f);
    __m512i topIndex = _mm512_set1_epi32(-1);
    __m512i index = _mm512_setr_epi32(0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15);
    const __m512i sixteen = _mm512_set1_epi32(16);
    constexpr bool score = scores(what);
    constexpr int kRound = _MM_FROUND_CUR_DIRECTION;
    std::size_t k = 0;
    for (; k + 16 <= n; k += 16) {
        const __m512 dx = _mm512_sub_ps(_mm512_loadu_ps(a.x + k), cx);
        const __m512 dy = _mm512_sub_ps(_mm512_loadu_ps(a.y + k), cy);
        const __m512 dz = _mm512_sub_ps(_mm512_loadu_ps(a.z + k), cz);
        const __m512 d2 = _mm512_add_round_ps(
            _mm512_add_round_ps(_mm512_mul_ps(dx, dx), _mm512_mul_ps(dy, dy), kRound),
            _mm512_mul_ps(dz, dz), kRound);
        // lit |= (d2 <= r2 ? ~0 : 0): all ones stored where it holds.
        _mm512_mask_storeu_epi32(a.lit + k, _mm512_cmp_ps_mask(d2, vr2, _CMP_LE_OQ), allSet);
        if constexpr (what == CandidateVisit::Lit) continue;
        const __m512 nearest = _mm512_min_ps(d2, _mm512_loadu_ps(a.nearest + k));
        _mm512_storeu_ps(a.nearest + k, nearest);
        if constexpr (!score) continue;
        const __m512 s = _mm512_sqrt_ps(nearest);
        const __m512 w = what == CandidateVisit::WeightedSpread
                             ? _mm512_mul_ps(_mm512_loadu_ps(a.weight + k), s)
                             : s;
        const __m512 v = _mm512_mul_ps(w, _mm512_loadu_ps(a.jitter + k));
        const __mmask16 greater = _mm512_cmp_ps_mask(v, top, _CMP_GT_OQ);
        top = _mm512_mask_mov_ps(top, greater, v);
        topIndex = _mm512_mask_mov_epi32(topIndex, greater, index);
        index = _mm512_add_epi32(index, sixteen);
    }
    if constexpr (score) {
        alignas(64) float tops[16];
        alignas(64) std::int32_t indices[16];
        _mm512_store_ps(tops, top);
        _mm512_store_si512(indices, topIndex);
        for (int l = 0; l < 16; ++l)
            if (indices[l] >= 0) b.offerLane(tops[l], static_cast<std::size_t>(indices[l]));
    }
    return k;
}

// Read once (util/x86intrinsics).
// SYLVA_NO_AVX=1 takes the SSE2 lanes on any processor, as the colonization search does;
// SYLVA_NO_AVX512=1 the AVX lanes.
const bool kHasAvx = simd::useAvx();
const bool kHasAvx512 = simd::useAvx512();
#endif

} // namespace

LitCandidates::LitCandidates(std::size_t capacity) {
    // Each array on a cache line of its own (slots a multiple of 16 floats, the block aligned
    // to 64 bytes): a lane load that straddles two lines costs twice.
    const std::size_t slots = (capacity + 1 + 15) / 16 * 16;
    mFloats.reset(new (std::align_val_t{64}) float[6 * slots]);
    mInts.reset(new (std::align_val_t{64}) std::uint32_t[2 * slots]);
    mX = mFloats.get();
    mY = mX + slots;
    mZ = mY + slots;
    mWeight = mZ + slots;
    mJitter = mWeight + slots;
    mNearest = mJitter + slots;
    std::fill_n(mNearest, slots, std::numeric_limits<float>::max());
    mLit = mInts.get();
    mIndex = mLit + slots;
    std::fill_n(mLit, slots, 0u);
}

bool LitCandidates::hasAvx() {
#if SYLVA_CANDIDATES_AVX
    return kHasAvx;
#else
    return false;
#endif
}

bool LitCandidates::hasAvx512() {
#if SYLVA_CANDIDATES_AVX
    return kHasAvx512;
#else
    return false;
#endif
}

float LitCandidates::scoreOf(std::size_t k, CandidateScore score) const {
    const float s = score == CandidateScore::Weight ? 1.0f : std::sqrt(mNearest[k]);
    return (score == CandidateScore::Spread ? s : mWeight[k] * s) * mJitter[k];
}

std::size_t LitCandidates::best(CandidateScore score) const {
    Best b;
    for (std::size_t k = 0; k < mCount; ++k)
        b.offer(scoreOf(k, score), k);
    return b.index(mCount);
}

std::size_t LitCandidates::visit(const glm::vec3& centre, float r2, CandidateVisit what,
                                 CandidateLanes lanes) {
    const std::size_t n = mCount;
    const Arrays a{mX, mY, mZ, mWeight, mJitter, mNearest, mLit};
    Best b;
    std::size_t k = 0;
#if SYLVA_CANDIDATES_AVX
    // Float lane indices are exact below 2^24 candidates (the node's limit is 2 million).
    const bool avx512 =
        lanes == CandidateLanes::Avx512 || (lanes == CandidateLanes::Widest && kHasAvx512);
    const bool avx =
        avx512 || ((lanes == CandidateLanes::Avx || (lanes == CandidateLanes::Widest && kHasAvx)) &&
                   n < (std::size_t{1} << 24));
    if (avx512)
        k = dispatch(what, [&]<CandidateVisit W>() { return visitAvx512<W>(a, n, centre, r2, b); });
    else if (avx)
        k = dispatch(what, [&]<CandidateVisit W>() { return visitAvx<W>(a, n, centre, r2, b); });
#else
    const bool avx = false;
#endif
#if defined(__SSE2__)
    if (!avx && lanes != CandidateLanes::Scalar)
        k = dispatch(what, [&]<CandidateVisit W>() { return visitSse2<W>(a, n, centre, r2, b); });
#endif
    const CandidateScore score =
        what == CandidateVisit::Spread ? CandidateScore::Spread : CandidateScore::WeightedSpread;
    for (; k < n; ++k) {
        const float dx = mX[k] - centre.x, dy = mY[k] - centre.y, dz = mZ[k] - centre.z;
        const float d2 = (dx * dx + dy * dy) + dz * dz;
        if (d2 <= r2) mLit[k] = ~0u;
        if (what == CandidateVisit::Lit) continue;
        mNearest[k] = std::min(mNearest[k], d2);
        if (scores(what)) b.offer(scoreOf(k, score), k);
    }
    return scores(what) ? b.index(n) : n;
}

void LitCandidates::markLit(std::vector<std::uint8_t>& lit) const {
    for (std::size_t k = 0; k < mCount; ++k)
        lit[mIndex[k]] = static_cast<std::uint8_t>(lit[mIndex[k]] | (mLit[k] & 1u));
}

} // namespace sylva::growth
