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
