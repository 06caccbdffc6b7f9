#pragma once

#include <cstdint>

#include <glm/glm.hpp>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

namespace sylva::mesh {

/// A cell of the leaf grouping (leafclusters): floor(middle / cell) along each axis.
struct LeafCell {
    std::int64_t x, y, z;
    bool operator==(const LeafCell&) const = default;
};

/// floor(v) as an integer, without a call to floor (not inlined below SSE4.1: it was a tenth of
/// the leaf grouping): the same value for every v in the int64 range.
inline std::int64_t floorToInt(double v) {
    const auto i = static_cast<std::int64_t>(v);
    return static_cast<double>(i) > v ? i - 1 : i;
}

/// The cell of \p mid at edge \p cell, one axis at a time.
inline LeafCell leafCellPlain(const glm::dvec3& mid, double cell) {
    return {floorToInt(mid.x / cell), floorToInt(mid.y / cell), floorToInt(mid.z / cell)};
}

/// leafCellPlain, two axes to an SSE2 register: the same quotients, and each floor from the
/// quotient plus 1.5 * 2^52 (its integer, rounded to the nearest, is then the low bits), one
/// less where that integer is above the quotient. Exact for quotients under 2^51; a cell with
/// any other takes leafCellPlain (perf record of the English oak: the cells' floors and their
/// conversions were 0.15 ms of the grouping's 0.35 ms a tree, 0.10 ms so).
inline LeafCell leafCell(const glm::dvec3& mid, double cell) {
#if defined(__SSE2__)
    const __m128d c = _mm_set1_pd(cell);
    const __m128d qxy = _mm_div_pd(_mm_loadu_pd(&mid.x), c);
    const __m128d qz = _mm_div_sd(_mm_load_sd(&mid.z), c); // its high lane 0
    const __m128d sign = _mm_set1_pd(-0.0), bound = _mm_set1_pd(0x1p51);
    const __m128d inRange = _mm_and_pd(_mm_cmplt_pd(_mm_andnot_pd(sign, qxy), bound),
                                       _mm_cmplt_pd(_mm_andnot_pd(sign, qz), bound));
    if (_mm_movemask_pd(inRange) != 3) return leafCellPlain(mid, cell); // NaN included
    const __m128d magic = _mm_set1_pd(0x1.8p52);
    const __m128i magicBits = _mm_castpd_si128(magic);
    const auto floors = [&](__m128d q) {
        const __m128d d = _mm_add_pd(q, magic);
        const __m128d rounded = _mm_sub_pd(d, magic);
        const __m128i i = _mm_sub_epi64(_mm_castpd_si128(d), magicBits);
        return _mm_add_epi64(i, _mm_castpd_si128(_mm_cmpgt_pd(rounded, q))); // -1 where above
    };
    alignas(16) std::int64_t xy[2], z[2];
    _mm_store_si128(reinterpret_cast<__m128i*>(xy), floors(qxy));
    _mm_store_si128(reinterpret_cast<__m128i*>(z), floors(qz));
    return {xy[0], xy[1], z[0]};
#else
    return leafCellPlain(mid, cell);
#endif
}

} // namespace sylva::mesh
