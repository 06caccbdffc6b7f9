#pragma once
// <immintrin.h> for the files with AVX-512 kernels (chosen at run time): SYLVA_X86_INTRINSICS is
// defined where it is included. GCC 12's AVX-512 intrinsics pass _mm512_undefined_ps() as their
// unused merge operand, which -Wuninitialized reports where they are inlined (GCC bug 105593):
// those warnings are off for the header alone.
#if defined(__x86_64__) && defined(__GNUC__)
#if !defined(__clang__)
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wuninitialized"
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
#endif
#include <immintrin.h>
#if !defined(__clang__)
#pragma GCC diagnostic pop
#endif
#define SYLVA_X86_INTRINSICS 1
#endif

#if defined(SYLVA_X86_INTRINSICS)
#include <cstdlib>

namespace sylva::simd {

/// Whether the AVX kernels run: the processor has AVX and SYLVA_NO_AVX is unset. Read once, on
/// first use (the processor's features first: a static initializer may run before libgcc's).
inline bool useAvx() {
    static const bool use = (__builtin_cpu_init(), __builtin_cpu_supports("avx")) &&
                            std::getenv("SYLVA_NO_AVX") == nullptr;
    return use;
}
/// Whether the AVX-512 (avx512f) kernels run: useAvx(), the processor has AVX-512 and
/// SYLVA_NO_AVX512 is unset (the AVX or SSE2 paths then run, with the same bytes).
inline bool useAvx512() {
    static const bool use =
        useAvx() && __builtin_cpu_supports("avx512f") && std::getenv("SYLVA_NO_AVX512") == nullptr;
    return use;
}
/// useAvx512() and the processor has AVX-512DQ (the 64-bit integer products and conversions
/// of the tints' hashes and the leaf cells' kernels).
inline bool useAvx512Dq() {
    static const bool use = useAvx512() && __builtin_cpu_supports("avx512dq");
    return use;
}

// AVX-512 sums, differences and products by the _round forms with the current rounding: each
// rounds on its own, as the scalar operation. GCC contracts a product into the generic vector
// sum _mm512_add_ps / _pd are written as (a fused multiply-add rounds once, where the target has
// FMA: AVX-512 does); the builtins it does not. For the kernels that must give the scalar bits.
#define SYLVA_AVX512_UNFUSED __attribute__((target("avx512f"), always_inline)) inline
SYLVA_AVX512_UNFUSED __m512 add(__m512 a, __m512 b) {
    return _mm512_add_round_ps(a, b, _MM_FROUND_CUR_DIRECTION);
}
SYLVA_AVX512_UNFUSED __m512 sub(__m512 a, __m512 b) {
    return _mm512_sub_round_ps(a, b, _MM_FROUND_CUR_DIRECTION);
}
SYLVA_AVX512_UNFUSED __m512 mul(__m512 a, __m512 b) {
    return _mm512_mul_round_ps(a, b, _MM_FROUND_CUR_DIRECTION);
}
SYLVA_AVX512_UNFUSED __m512d add(__m512d a, __m512d b) {
    return _mm512_add_round_pd(a, b, _MM_FROUND_CUR_DIRECTION);
}
SYLVA_AVX512_UNFUSED __m512d sub(__m512d a, __m512d b) {
    return _mm512_sub_round_pd(a, b, _MM_FROUND_CUR_DIRECTION);
}
SYLVA_AVX512_UNFUSED __m512d mul(__m512d a, __m512d b) {
    return _mm512_mul_round_pd(a, b, _MM_FROUND_CUR_DIRECTION);
}
#undef SYLVA_AVX512_UNFUSED

} // namespace sylva::simd
#endif
