#include "engine/growth/colonizationsearch.h"

#include <algorithm>
#include <cstdlib>
#include <limits>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif
#include "engine/util/x86intrinsics.h"
#if defined(SYLVA_X86_INTRINSICS)
#define SYLVA_OFFER_AVX 1
#endif

#include "engine/growth/spatialgrid.h"
#include "engine/util/parallelfor.h"

namespace sylva::growth {

namespace {

#if SYLVA_OFFER_AVX
/// better ? node : n a lane, by its sign bit, in one instruction: GCC expands the intrinsic
/// _mm256_blendv_ps of a comparison lane by lane in a target("avx") function.
__attribute__((target("avx"), always_inline)) inline __m256 blendAvx(__m256 n, __m256 node,
                                                                     __m256 better) {
    asm("vblendvps %2, %1, %0, %0" : "+x"(n) : "x"(node), "x"(better));
    return n;
}

/// Offers \p count nodes (coordinates \p cx, \p cy, \p cz, indices \p cn, in index order)
/// to every lane of a cell, eight lanes at a time where the processor has AVX (built for it
/// alone, dispatched at run time), the lanes' distances and nodes held in registers across the
/// nodes instead of loaded and stored again for every node. Each lane sees the nodes in the
/// same order through the same float subtractions, products, sums, comparison and min as the
/// SSE2 loop (no fused multiply-add: AVX alone has none), so the same distances, closest nodes
/// and largest distance. \p lanes is a multiple of 4. Returns the largest cached distance.
__attribute__((target("avx"), noinline)) float
offerChunkAvx(const float* X, const float* Y, const float* Z, float* B, std::int32_t* N,
              std::uint32_t lanes, const float* cx, const float* cy, const float* cz,
              const std::int32_t* cn, std::size_t count) {
    const auto* cnf = reinterpret_cast<const float*>(cn);
    __m256 vm = _mm256_setzero_ps();
    std::uint32_t i = 0;
    for (; i + 16 <= lanes; i += 16) {
        __m256 b0 = _mm256_loadu_ps(B + i), b1 = _mm256_loadu_ps(B + i + 8);
        auto* np = reinterpret_cast<float*>(N + i);
        __m256 n0 = _mm256_loadu_ps(np), n1 = _mm256_loadu_ps(np + 8);
        for (std::size_t k = 0; k < count; ++k) {
            const __m256 px = _mm256_broadcast_ss(cx + k);
            const __m256 py = _mm256_broadcast_ss(cy + k);
            const __m256 pz = _mm256_broadcast_ss(cz + k);
            const __m256 node = _mm256_broadcast_ss(cnf + k);
            const __m256 dx0 = _mm256_sub_ps(_mm256_loadu_ps(X + i), px);
            const __m256 dy0 = _mm256_sub_ps(_mm256_loadu_ps(Y + i), py);
            const __m256 dz0 = _mm256_sub_ps(_mm256_loadu_ps(Z + i), pz);
            const __m256 dx1 = _mm256_sub_ps(_mm256_loadu_ps(X + i + 8), px);
            const __m256 dy1 = _mm256_sub_ps(_mm256_loadu_ps(Y + i + 8), py);
            const __m256 dz1 = _mm256_sub_ps(_mm256_loadu_ps(Z + i + 8), pz);
            const __m256 d20 =
                _mm256_add_ps(_mm256_add_ps(_mm256_mul_ps(dx0, dx0), _mm256_mul_ps(dy0, dy0)),
                              _mm256_mul_ps(dz0, dz0));
            const __m256 d21 =
                _mm256_add_ps(_mm256_add_ps(_mm256_mul_ps(dx1, dx1), _mm256_mul_ps(dy1, dy1)),
                              _mm256_mul_ps(dz1, dz1));
            const __m256 better0 = _mm256_cmp_ps(d20, b0, _CMP_LT_OQ);
            const __m256 better1 = _mm256_cmp_ps(d21, b1, _CMP_LT_OQ);
            b0 = _mm256_min_ps(d20, b0);
            b1 = _mm256_min_ps(d21, b1);
            n0 = blendAvx(n0, node, better0);
            n1 = blendAvx(n1, node, better1);
        }
        _mm256_storeu_ps(B + i, b0);
        _mm256_storeu_ps(B + i + 8, b1);
        _mm256_storeu_ps(np, n0);
        _mm256_storeu_ps(np + 8, n1);
        vm = _mm256_max_ps(vm, _mm256_max_ps(b0, b1));
    }
    for (; i + 8 <= lanes; i += 8) {
        __m256 b = _mm256_loadu_ps(B + i);
        auto* np = reinterpret_cast<float*>(N + i);
        __m256 n = _mm256_loadu_ps(np);
        for (std::size_t k = 0; k < count; ++k) {
            const __m256 node = _mm256_broadcast_ss(cnf + k);
            const __m256 dx = _mm256_sub_ps(_mm256_loadu_ps(X + i), _mm256_broadcast_ss(cx + k));
            const __m256 dy = _mm256_sub_ps(_mm256_loadu_ps(Y + i), _mm256_broadcast_ss(cy + k));
            const __m256 dz = _mm256_sub_ps(_mm256_loadu_ps(Z + i), _mm256_broadcast_ss(cz + k));
            const __m256 d2 = _mm256_add_ps(
                _mm256_add_ps(_mm256_mul_ps(dx, dx), _mm256_mul_ps(dy, dy)), _mm256_mul_ps(dz, dz));
            const __m256 better = _mm256_cmp_ps(d2, b, _CMP_LT_OQ);
            b = _mm256_min_ps(d2, b);
            n = blendAvx(n, node, better);
        }
        _mm256_storeu_ps(B + i, b);
        _mm256_storeu_ps(np, n);
        vm = _mm256_max_ps(vm, b);
    }
    __m128 m = _mm_max_ps(_mm256_castps256_ps128(vm), _mm256_extractf128_ps(vm, 1));
    if (i < lanes) {
        __m128 b = _mm_loadu_ps(B + i);
        auto* np = reinterpret_cast<float*>(N + i);
        __m128 n = _mm_loadu_ps(np);
        for (std::size_t k = 0; k < count; ++k) {
            const __m128 node = _mm_broadcast_ss(cnf + k);
            const __m128 dx = _mm_sub_ps(_mm_loadu_ps(X + i), _mm_broadcast_ss(cx + k));
            const __m128 dy = _mm_sub_ps(_mm_loadu_ps(Y + i), _mm_broadcast_ss(cy + k));
            const __m128 dz = _mm_sub_ps(_mm_loadu_ps(Z + i), _mm_broadcast_ss(cz + k));
            const __m128 d2 =
                _mm_add_ps(_mm_add_ps(_mm_mul_ps(dx, dx), _mm_mul_ps(dy, dy)), _mm_mul_ps(dz, dz));
            const __m128 better = _mm_cmplt_ps(d2, b);
            b = _mm_min_ps(d2, b);
            n = _mm_or_ps(_mm_and_ps(better, node), _mm_andnot_ps(better, n));
        }
        _mm_storeu_ps(B + i, b);
        _mm_storeu_ps(np, n);
        m = _mm_max_ps(m, b);
    }
    alignas(16) float m4[4];
    _mm_store_ps(m4, m);
    return std::max(std::max(m4[0], m4[1]), std::max(m4[2], m4[3]));
}

using simd::add; // unfused (util/x86intrinsics)

/// d2 < b and min(d2, b) for the offers' non-negative distances, by the integer order of their
/// bits: for floats with a clear sign bit (a sum of squares, +0 included, +inf, the padding's
/// 0 and a positive NaN past every finite one) the signed 32-bit order of the bits is the float
/// order, so each lane chooses and keeps the same float. The float compare and minimum share
/// the adders' pipes with the offers' subtractions and sums (their bound); the integer ones were
/// measured faster (docs/perf/geometry.md, thirteenth pass).
__attribute__((target("avx512f"))) inline __mmask16 lessBits(__m512 d2, __m512 b) {
    return _mm512_cmplt_epi32_mask(_mm512_castps_si512(d2), _mm512_castps_si512(b));
}
__attribute__((target("avx512f"))) inline __m512 minBits(__m512 d2, __m512 b) {
    return _mm512_castsi512_ps(_mm512_min_epi32(_mm512_castps_si512(d2), _mm512_castps_si512(b)));
}

/// offerChunkAvx with sixteen lanes a register where the processor has AVX-512 (built for it
/// alone, dispatched at run time; SYLVA_NO_AVX512=1 takes the AVX offers): each lane the same
/// subtractions, products, sums (add: none fused), comparison and min, the node taken by
/// a masked move. The offers were ~45 % of the oak's colonization; a 16-lane block costs the same
/// instructions as an 8-lane one.
__attribute__((target("avx512f"))) float
offerChunkAvx512(const float* X, const float* Y, const float* Z, float* B, std::int32_t* N,
                 std::uint32_t lanes, const float* cx, const float* cy, const float* cz,
                 const std::int32_t* cn, std::size_t count) {
    const auto* cnf = reinterpret_cast<const float*>(cn);
    __m512 vm = _mm512_setzero_ps();
    std::uint32_t i = 0;
    for (; i + 32 <= lanes; i += 32) {
        __m512 b0 = _mm512_loadu_ps(B + i), b1 = _mm512_loadu_ps(B + i + 16);
        auto* np = reinterpret_cast<float*>(N + i);
        __m512 n0 = _mm512_loadu_ps(np), n1 = _mm512_loadu_ps(np + 16);
        for (std::size_t k = 0; k < count; ++k) {
            const __m512 px = _mm512_set1_ps(cx[k]);
            const __m512 py = _mm512_set1_ps(cy[k]);
            const __m512 pz = _mm512_set1_ps(cz[k]);
            const __m512 node = _mm512_set1_ps(cnf[k]);
            const __m512 dx0 = _mm512_sub_ps(_mm512_loadu_ps(X + i), px);
            const __m512 dy0 = _mm512_sub_ps(_mm512_loadu_ps(Y + i), py);
            const __m512 dz0 = _mm512_sub_ps(_mm512_loadu_ps(Z + i), pz);
            const __m512 dx1 = _mm512_sub_ps(_mm512_loadu_ps(X + i + 16), px);
            const __m512 dy1 = _mm512_sub_ps(_mm512_loadu_ps(Y + i + 16), py);
            const __m512 dz1 = _mm512_sub_ps(_mm512_loadu_ps(Z + i + 16), pz);
            const __m512 d20 =
                add(add(_mm512_mul_ps(dx0, dx0), _mm512_mul_ps(dy0, dy0)), _mm512_mul_ps(dz0, dz0));
            const __m512 d21 =
                add(add(_mm512_mul_ps(dx1, dx1), _mm512_mul_ps(dy1, dy1)), _mm512_mul_ps(dz1, dz1));
            const __mmask16 better0 = lessBits(d20, b0);
            const __mmask16 better1 = lessBits(d21, b1);
            b0 = minBits(d20, b0); // d2 < b ? d2 : b
            b1 = minBits(d21, b1);
            n0 = _mm512_mask_mov_ps(n0, better0, node);
            n1 = _mm512_mask_mov_ps(n1, better1, node);
        }
        _mm512_storeu_ps(B + i, b0);
        _mm512_storeu_ps(B + i + 16, b1);
        _mm512_storeu_ps(np, n0);
        _mm512_storeu_ps(np + 16, n1);
        vm = _mm512_max_ps(vm, _mm512_max_ps(b0, b1));
    }
    if (i + 16 <= lanes) {
        __m512 b = _mm512_loadu_ps(B + i);
        auto* np = reinterpret_cast<float*>(N + i);
        __m512 n = _mm512_loadu_ps(np);
        for (std::size_t k = 0; k < count; ++k) {
            const __m512 dx = _mm512_sub_ps(_mm512_loadu_ps(X + i), _mm512_set1_ps(cx[k]));
            const __m512 dy = _mm512_sub_ps(_mm512_loadu_ps(Y + i), _mm512_set1_ps(cy[k]));
            const __m512 dz = _mm512_sub_ps(_mm512_loadu_ps(Z + i), _mm512_set1_ps(cz[k]));
            const __m512 d2 =
                add(add(_mm512_mul_ps(dx, dx), _mm512_mul_ps(dy, dy)), _mm512_mul_ps(dz, dz));
            const __mmask16 better = lessBits(d2, b);
            b = minBits(d2, b);
            n = _mm512_mask_mov_ps(n, better, _mm512_set1_ps(cnf[k]));
        }
        _mm512_storeu_ps(B + i, b);
        _mm512_storeu_ps(np, n);
        vm = _mm512_max_ps(vm, b);
        i += 16;
    }
    // The last 4 to 12 lanes (a multiple of 4) by the same block under a mask: the lanes past
    // them are neither read nor written (their B read as 0 raises no maximum).
    if (i < lanes) {
        const auto in = static_cast<__mmask16>((1u << (lanes - i)) - 1u);
        __m512 b = _mm512_maskz_loadu_ps(in, B + i);
        auto* np = reinterpret_cast<float*>(N + i);
        __m512 n = _mm512_maskz_loadu_ps(in, np);
        const __m512 x = _mm512_maskz_loadu_ps(in, X + i);
        const __m512 y = _mm512_maskz_loadu_ps(in, Y + i);
        const __m512 z = _mm512_maskz_loadu_ps(in, Z + i);
        for (std::size_t k = 0; k < count; ++k) {
            const __m512 dx = _mm512_sub_ps(x, _mm512_set1_ps(cx[k]));
            const __m512 dy = _mm512_sub_ps(y, _mm512_set1_ps(cy[k]));
            const __m512 dz = _mm512_sub_ps(z, _mm512_set1_ps(cz[k]));
            const __m512 d2 =
                add(add(_mm512_mul_ps(dx, dx), _mm512_mul_ps(dy, dy)), _mm512_mul_ps(dz, dz));
            const __mmask16 better = lessBits(d2, b);
            b = minBits(d2, b);
            n = _mm512_mask_mov_ps(n, better, _mm512_set1_ps(cnf[k]));
        }
        _mm512_mask_storeu_ps(B + i, in, b);
        _mm512_mask_storeu_ps(np, in, n);
        vm = _mm512_max_ps(vm, b);
    }
    const __m256 m8 =
        _mm256_max_ps(_mm512_castps512_ps256(vm),
                      _mm256_castpd_ps(_mm512_extractf64x4_pd(_mm512_castps_pd(vm), 1)));
    __m128 m = _mm_max_ps(_mm256_castps256_ps128(m8), _mm256_extractf128_ps(m8, 1));
    alignas(16) float m4[4];
    _mm_store_ps(m4, m);
    return std::max(std::max(m4[0], m4[1]), std::max(m4[2], m4[3]));
}

/// The node-to-cell bound of every new node, eight nodes at a time (the SSE2 loop's
/// subtractions, maxima, products and sums in each lane); the nodes that pass it are gathered,
/// in index order, kChunk at a time and offered together by offerChunkAvx. The cell's max2
/// only shrinks, so a node tested against the max2 of its chunk's start, or of its block's,
/// is at most offered for nothing (it improves no lane: changes no result), as the SSE2 loop
/// offers a block of four. Returns the cell's new max2; \p touched when a node was offered.
__attribute__((target("avx"))) float
scanNodesAvx(const float* nx, const float* ny, const float* nz, std::size_t newNodes,
             std::size_t firstNew, const glm::vec3& lo, const glm::vec3& hi, float* X, float* Y,
             float* Z, float* B, std::int32_t* N, std::uint32_t lanes, float max2, bool& touched) {
    constexpr std::size_t kChunk = 64;
    float cx[kChunk], cy[kChunk], cz[kChunk];
    std::int32_t cn[kChunk];
    std::size_t count = 0;
    auto take = [&](std::size_t k) {
        cx[count] = nx[k];
        cy[count] = ny[k];
        cz[count] = nz[k];
        cn[count] = static_cast<std::int32_t>(firstNew + k);
        if (++count == kChunk) {
            max2 = offerChunkAvx(X, Y, Z, B, N, lanes, cx, cy, cz, cn, count);
            touched = true;
            count = 0;
        }
    };
    const __m256 vlx = _mm256_set1_ps(lo.x), vly = _mm256_set1_ps(lo.y), vlz = _mm256_set1_ps(lo.z);
    const __m256 vhx = _mm256_set1_ps(hi.x), vhy = _mm256_set1_ps(hi.y), vhz = _mm256_set1_ps(hi.z);
    const __m256 zero = _mm256_setzero_ps();
    std::size_t j = 0;
    for (; j + 8 <= newNodes; j += 8) {
        const __m256 x = _mm256_loadu_ps(nx + j);
        const __m256 y = _mm256_loadu_ps(ny + j);
        const __m256 z = _mm256_loadu_ps(nz + j);
        const __m256 dx =
            _mm256_max_ps(_mm256_max_ps(_mm256_sub_ps(vlx, x), _mm256_sub_ps(x, vhx)), zero);
        const __m256 dy =
            _mm256_max_ps(_mm256_max_ps(_mm256_sub_ps(vly, y), _mm256_sub_ps(y, vhy)), zero);
        const __m256 dz =
            _mm256_max_ps(_mm256_max_ps(_mm256_sub_ps(vlz, z), _mm256_sub_ps(z, vhz)), zero);
        const __m256 d2 = _mm256_add_ps(_mm256_add_ps(_mm256_mul_ps(dx, dx), _mm256_mul_ps(dy, dy)),
                                        _mm256_mul_ps(dz, dz));
        int mask = _mm256_movemask_ps(_mm256_cmp_ps(d2, _mm256_set1_ps(max2), _CMP_LT_OQ));
        for (; mask != 0; mask &= mask - 1)
            take(j + static_cast<std::size_t>(__builtin_ctz(static_cast<unsigned>(mask))));
    }
    for (; j < newNodes; ++j) {
        const float dx = std::max(std::max(lo.x - nx[j], nx[j] - hi.x), 0.0f);
        const float dy = std::max(std::max(lo.y - ny[j], ny[j] - hi.y), 0.0f);
        const float dz = std::max(std::max(lo.z - nz[j], nz[j] - hi.z), 0.0f);
        if ((dx * dx + dy * dy) + dz * dz < max2) take(j);
    }
    if (count > 0) {
        max2 = offerChunkAvx(X, Y, Z, B, N, lanes, cx, cy, cz, cn, count);
        touched = true;
    }
    return max2;
}

/// Moves the lanes of the \p live points not killed (B < \p dk2) down, in order, sixteen at a
/// time: each block's kept lanes compressed into a register and stored at the count so far
/// (before any lane not yet read), its killed points flagged. What the scalar loop of
/// updateCell does, without its store of every lane one by one. Returns the lanes kept.
__attribute__((target("avx512f"))) std::uint32_t
compactAvx512(float* X, float* Y, float* Z, float* B, std::int32_t* N, std::uint32_t* ids,
              std::uint32_t live, float dk2, std::uint8_t* killed, std::int32_t* bestNode) {
    const __m512 vdk2 = _mm512_set1_ps(dk2);
    std::uint32_t kept = 0;
    for (std::uint32_t i = 0; i < live; i += 16) {
        const auto in = static_cast<__mmask16>(live - i >= 16 ? 0xFFFFu : (1u << (live - i)) - 1u);
        const __m512 b = _mm512_maskz_loadu_ps(in, B + i);
        const __mmask16 kill = _mm512_mask_cmp_ps_mask(in, b, vdk2, _CMP_LT_OQ);
        const auto keep = static_cast<__mmask16>(in & ~kill);
        const auto n = static_cast<std::uint32_t>(__builtin_popcount(keep));
        if (kill == 0 && kept == i) { // nothing killed so far: the lanes stay where they are
            kept += n;
            continue;
        }
        for (unsigned m = kill; m != 0; m &= m - 1) {
            const std::uint32_t id = ids[i + static_cast<std::uint32_t>(__builtin_ctz(m))];
            killed[id] = 1;
            bestNode[id] = -1;
        }
        const auto out = static_cast<__mmask16>((1u << n) - 1u);
        _mm512_mask_storeu_ps(X + kept, out,
                              _mm512_maskz_compress_ps(keep, _mm512_maskz_loadu_ps(in, X + i)));
        _mm512_mask_storeu_ps(Y + kept, out,
                              _mm512_maskz_compress_ps(keep, _mm512_maskz_loadu_ps(in, Y + i)));
        _mm512_mask_storeu_ps(Z + kept, out,
                              _mm512_maskz_compress_ps(keep, _mm512_maskz_loadu_ps(in, Z + i)));
        _mm512_mask_storeu_ps(B + kept, out, _mm512_maskz_compress_ps(keep, b));
        _mm512_mask_storeu_epi32(
            N + kept, out, _mm512_maskz_compress_epi32(keep, _mm512_maskz_loadu_epi32(in, N + i)));
        _mm512_mask_storeu_epi32(
            ids + kept, out,
            _mm512_maskz_compress_epi32(keep, _mm512_maskz_loadu_epi32(in, ids + i)));
        kept += n;
    }
    return kept;
}

/// scanNodesAvx with AVX-512: sixteen nodes tested at a time (the same subtractions, maxima,
/// products and unfused sums a lane), the nodes that pass compressed into the chunk (their
/// coordinates and indices, in index order) without a branch a node, the last group by a
/// masked load; a chunk of 49 to 64 nodes offered by offerChunkAvx512 (any chunking offers
/// each lane the same nodes in the same order).
__attribute__((target("avx512f"))) float
scanNodesAvx512(const float* nx, const float* ny, const float* nz, std::size_t newNodes,
                std::size_t firstNew, const glm::vec3& lo, const glm::vec3& hi, float* X, float* Y,
                float* Z, float* B, std::int32_t* N, std::uint32_t lanes, float max2,
                bool& touched) {
    constexpr std::size_t kChunk = 64;
    alignas(64) float cx[kChunk + 16], cy[kChunk + 16], cz[kChunk + 16];
    alignas(64) std::int32_t cn[kChunk + 16];
    std::size_t count = 0;
    const __m512 vlx = _mm512_set1_ps(lo.x), vly = _mm512_set1_ps(lo.y), vlz = _mm512_set1_ps(lo.z);
    const __m512 vhx = _mm512_set1_ps(hi.x), vhy = _mm512_set1_ps(hi.y), vhz = _mm512_set1_ps(hi.z);
    const __m512 zero = _mm512_setzero_ps();
    const __m512i lane = _mm512_setr_epi32(0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15);
    for (std::size_t j = 0; j < newNodes; j += 16) {
        const auto in =
            static_cast<__mmask16>(newNodes - j >= 16 ? 0xFFFFu : (1u << (newNodes - j)) - 1u);
        const __m512 x = _mm512_maskz_loadu_ps(in, nx + j);
        const __m512 y = _mm512_maskz_loadu_ps(in, ny + j);
        const __m512 z = _mm512_maskz_loadu_ps(in, nz + j);
        const __m512 dx =
            _mm512_max_ps(_mm512_max_ps(_mm512_sub_ps(vlx, x), _mm512_sub_ps(x, vhx)), zero);
        const __m512 dy =
            _mm512_max_ps(_mm512_max_ps(_mm512_sub_ps(vly, y), _mm512_sub_ps(y, vhy)), zero);
        const __m512 dz =
            _mm512_max_ps(_mm512_max_ps(_mm512_sub_ps(vlz, z), _mm512_sub_ps(z, vhz)), zero);
        const __m512 d2 =
            add(add(_mm512_mul_ps(dx, dx), _mm512_mul_ps(dy, dy)), _mm512_mul_ps(dz, dz));
        const __mmask16 pass = _mm512_mask_cmp_ps_mask(in, d2, _mm512_set1_ps(max2), _CMP_LT_OQ);
        _mm512_storeu_ps(cx + count, _mm512_maskz_compress_ps(pass, x));
        _mm512_storeu_ps(cy + count, _mm512_maskz_compress_ps(pass, y));
        _mm512_storeu_ps(cz + count, _mm512_maskz_compress_ps(pass, z));
        const __m512i index =
            _mm512_add_epi32(_mm512_set1_epi32(static_cast<std::int32_t>(firstNew + j)), lane);
        _mm512_storeu_si512(cn + count, _mm512_maskz_compress_epi32(pass, index));
        count += static_cast<std::size_t>(__builtin_popcount(pass));
        if (count > kChunk - 16) {
            max2 = offerChunkAvx512(X, Y, Z, B, N, lanes, cx, cy, cz, cn, count);
            touched = true;
            count = 0;
        }
    }
    if (count > 0) {
        max2 = offerChunkAvx512(X, Y, Z, B, N, lanes, cx, cy, cz, cn, count);
        touched = true;
    }
    return max2;
}

/// dropKilled's AVX-512 pass over the \p n ids of \p live (increasing) with the flags of
/// \p points points: each block's flags gathered (four bytes from a flag: blocks whose last id
/// is within three of the end go one by one), its live ids compressed and stored at the count
/// so far. Returns the count.
__attribute__((target("avx512f"))) std::size_t dropKilledAvx512(std::uint32_t* live, std::size_t n,
                                                                const std::uint8_t* killed,
                                                                std::size_t points) {
    const __m512i low = _mm512_set1_epi32(0xFF);
    std::size_t out = 0, i = 0;
    for (; i + 16 <= n && live[i + 15] + std::size_t{3} < points; i += 16) {
        const __m512i ids = _mm512_loadu_si512(live + i);
        const __m512i flags = _mm512_and_si512(_mm512_i32gather_epi32(ids, killed, 1), low);
        const __mmask16 keep = _mm512_cmpeq_epi32_mask(flags, _mm512_setzero_si512());
        _mm512_storeu_si512(live + out, _mm512_maskz_compress_epi32(keep, ids));
        out += static_cast<std::size_t>(__builtin_popcount(keep));
    }
    for (; i < n; ++i) {
        live[out] = live[i];
        out += killed[live[i]] == 0 ? 1 : 0;
    }
    return out;
}

// Read once (util/x86intrinsics).
// SYLVA_NO_AVX=1 takes the SSE2 offers on any processor (its tests run them on one with AVX).
const bool kHasAvx = simd::useAvx();
// SYLVA_NO_AVX512=1 takes the AVX offers on a processor with AVX-512 (their tests run them).
const bool kHasAvx512 = simd::useAvx512();
#endif

} // namespace

void dropKilled(PointState& s) {
#if SYLVA_OFFER_AVX
    if (kHasAvx512) {
        s.live.resize(
            dropKilledAvx512(s.live.data(), s.live.size(), s.killed.data(), s.killed.size()));
        return;
    }
#endif
    std::erase_if(s.live, [&s](std::uint32_t a) { return s.killed[a] != 0; });
}

void updateNaive(PointState& s, const std::vector<glm::vec3>& nodes, float di2, float dk2) {
    for (std::uint32_t a : s.live) {
        float b2 = di2;
        std::int32_t bn = -1;
        const glm::vec3 p = s.points[a];
        for (std::size_t j = 0; j < nodes.size(); ++j) {
            const float d2 = distance2(p, nodes[j]);
            if (d2 < b2) {
                b2 = d2;
                bn = static_cast<std::int32_t>(j);
            }
        }
        s.best2[a] = b2;
        s.bestNode[a] = bn;
        if (b2 < dk2) s.killed[a] = 1;
    }
}

struct AcceleratedSearch::Impl {
    // The points sorted into cells by a counting sort straight into the lanes: PointGrid's
    // cells (its cell size, its cap on the table), each cell's points in increasing index
    // order, without its copies of the points, its per-point divisions by floor and its
    // vectors (it was a third of the search's setup, ~3 % of the oak's grow stage). Which cell
    // a point falls in changes what is pruned, never a result: any partition gives the same.
    Impl(const std::vector<glm::vec3>& points, float di) {
        const std::size_t n = points.size();
        glm::vec3 lo = points[0], hi = lo;
        for (const glm::vec3& p : points) {
            lo = glm::min(lo, p);
            hi = glm::max(hi, p);
        }
        // PointGrid's table: at most four entries a point (or 4,096), the cell enlarged if not.
        const double maxCells = std::max(4096.0, 4.0 * static_cast<double>(n));
        const glm::dvec3 extent = glm::dvec3(hi - lo);
        double h = cellSizeFor(lo, hi, n, di);
        for (;;) {
            const double cells = (std::floor(extent.x / h) + 1) * (std::floor(extent.y / h) + 1) *
                                 (std::floor(extent.z / h) + 1);
            if (cells <= maxCells) break;
            h *= 1.25;
        }
        const glm::ivec3 dims(static_cast<int>(std::floor(extent.x / h)) + 1,
                              static_cast<int>(std::floor(extent.y / h)) + 1,
                              static_cast<int>(std::floor(extent.z / h)) + 1);
        const auto inv = static_cast<float>(1.0 / h);
        const auto tableSize = static_cast<std::size_t>(dims.x) * static_cast<std::size_t>(dims.y) *
                               static_cast<std::size_t>(dims.z);
        std::vector<std::uint32_t> cellOf(n);
        std::vector<std::uint32_t> count(tableSize, 0);
        // p - lo >= 0, so truncation is the floor; the last cell takes what rounds past it.
        auto axis = [inv](float p, float l, int dim) {
            return static_cast<std::size_t>(std::min(static_cast<int>((p - l) * inv), dim - 1));
        };
        for (std::size_t i = 0; i < n; ++i) {
            const glm::vec3& p = points[i];
            const std::size_t c = (axis(p.z, lo.z, dims.z) * static_cast<std::size_t>(dims.y) +
                                   axis(p.y, lo.y, dims.y)) *
                                      static_cast<std::size_t>(dims.x) +
                                  axis(p.x, lo.x, dims.x);
            cellOf[i] = static_cast<std::uint32_t>(c);
            ++count[c];
        }
        // Each non-empty cell's first lane (the cursor of the sort), cells in table order.
        std::vector<std::uint32_t> cursor(tableSize);
        std::uint32_t total = 0;
        std::size_t cellCount = 0;
        for (std::size_t t = 0; t < tableSize; ++t) {
            cursor[t] = total;
            total += padded(count[t]);
            cellCount += count[t] > 0 ? 1 : 0;
        }
        mX.resize(total);
        mY.resize(total);
        mZ.resize(total);
        mBest2.resize(total);
        mNode.resize(total);
        mId.resize(total);
        for (std::size_t i = 0; i < n; ++i) {
            const std::uint32_t k = cursor[cellOf[i]]++;
            mX[k] = points[i].x;
            mY[k] = points[i].y;
            mZ[k] = points[i].z;
            mBest2[k] = di * di;
            mNode[k] = -1;
            mId[k] = static_cast<std::uint32_t>(i);
        }
        mCells.reserve(cellCount);
        mActive.reserve(cellCount);
        for (std::size_t t = 0; t < tableSize; ++t) {
            const std::uint32_t live = count[t];
            if (live == 0) continue;
            Cell cell{cursor[t] - live, live, 0.0f, {}, {}};
            boundLive(mX.data() + cell.begin, mY.data() + cell.begin, mZ.data() + cell.begin,
                      mBest2.data() + cell.begin, live, cell);
            clearPadding(cell.begin, live);
            mActive.push_back(static_cast<std::uint32_t>(mCells.size()));
            mCells.push_back(cell);
        }
    }

    std::size_t update(PointState& s, const std::vector<glm::vec3>& nodes, std::size_t firstNew,
                       float dk2) {
        std::size_t liveBefore = 0;
        for (const std::uint32_t c : mActive)
            liveBefore += mCells[c].live;
        const std::size_t newNodes = nodes.size() - firstNew;
        mNX.resize(newNodes);
        mNY.resize(newNodes);
        mNZ.resize(newNodes);
        for (std::size_t j = 0; j < newNodes; ++j) {
            mNX[j] = nodes[firstNew + j].x;
            mNY[j] = nodes[firstNew + j].y;
            mNZ[j] = nodes[firstNew + j].z;
        }
        const auto cellCount = static_cast<std::int64_t>(mActive.size());
        // Each cell is owned by one thread and its points see the nodes in index order, so the
        // result does not depend on the number of threads. Small updates stay serial: waking
        // a team costs more than they do.
        const bool parallel = cellCount * static_cast<std::int64_t>(newNodes) > 200000;
        auto update = [&](std::int64_t k) {
            if (useAvx())
                updateCell<true>(s, mCells[mActive[static_cast<std::size_t>(k)]], firstNew, dk2);
            else
                updateCell<false>(s, mCells[mActive[static_cast<std::size_t>(k)]], firstNew, dk2);
        };
        forEachIndexDynamic(cellCount, parallel, 32, update);
        std::size_t liveAfter = 0;
        for (const std::uint32_t c : mActive)
            liveAfter += mCells[c].live;
        std::erase_if(mActive, [this](std::uint32_t c) { return mCells[c].live == 0; });
        return liveBefore - liveAfter;
    }

    struct Cell {
        std::uint32_t begin; ///< into the point arrays; storage is padded to 4 lanes
        std::uint32_t live;  ///< live points, stored first
        float max2;          ///< largest cached best2 of the live points
        glm::vec3 lo, hi;    ///< bounds of the cell's live points
    };

    static std::uint32_t padded(std::uint32_t n) { return (n + 3u) & ~3u; }

    // Inert lanes: an infinite distance never beats anything and 0 never raises the maximum.
    void clearPadding(std::uint32_t begin, std::uint32_t live) {
        const float inf = std::numeric_limits<float>::infinity();
        for (std::uint32_t k = live; k < padded(live); ++k) {
            mX[begin + k] = mY[begin + k] = mZ[begin + k] = inf;
            mBest2[begin + k] = 0.0f;
            mNode[begin + k] = -1;
            mId[begin + k] = 0;
        }
    }

    static bool useAvx() {
#if SYLVA_OFFER_AVX
        return kHasAvx;
#else
        return false;
#endif
    }

    // Avx: the bound tests and offers by scanNodesAvx (offerAvx inlined in it; one instance a
    // path: a call in the SSE2 loop's lambda cost that loop 6 %, its registers saved round it).
    template <bool Avx>
    void updateCell(PointState& s, Cell& cell, std::size_t firstNew, float dk2) {
        const std::size_t newNodes = mNX.size();
        const float* nx = mNX.data();
        const float* ny = mNY.data();
        const float* nz = mNZ.data();
        const float lx = cell.lo.x, ly = cell.lo.y, lz = cell.lo.z;
        const float hx = cell.hi.x, hy = cell.hi.y, hz = cell.hi.z;
        float* X = mX.data() + cell.begin;
        float* Y = mY.data() + cell.begin;
        float* Z = mZ.data() + cell.begin;
        float* B = mBest2.data() + cell.begin;
        std::int32_t* N = mNode.data() + cell.begin;
        const std::uint32_t* I = mId.data() + cell.begin;
        const std::uint32_t lanes = padded(cell.live);
        float max2 = cell.max2;
        bool touched = false;

        // Offers new node j to every live point of the cell (the oracle's distance2 expression
        // and strict '<') and tightens max2, without a branch on the lanes that improve: what
        // the shared state sees is published once a cell, below (the closest node of a point
        // after all new nodes is all it reads).
        auto process = [&](std::size_t j) {
            const float px = nx[j], py = ny[j], pz = nz[j];
            const auto node = static_cast<std::int32_t>(firstNew + j);
            touched = true;
#if defined(__SSE2__)
            const __m128 vx = _mm_set1_ps(px), vy = _mm_set1_ps(py), vz = _mm_set1_ps(pz);
            const __m128i vnode = _mm_set1_epi32(node);
            __m128 vm = _mm_setzero_ps();
            for (std::uint32_t i = 0; i < lanes; i += 4) {
                const __m128 dx = _mm_sub_ps(_mm_loadu_ps(X + i), vx);
                const __m128 dy = _mm_sub_ps(_mm_loadu_ps(Y + i), vy);
                const __m128 dz = _mm_sub_ps(_mm_loadu_ps(Z + i), vz);
                const __m128 d2 = _mm_add_ps(_mm_add_ps(_mm_mul_ps(dx, dx), _mm_mul_ps(dy, dy)),
                                             _mm_mul_ps(dz, dz));
                const __m128 b0 = _mm_loadu_ps(B + i);
                const __m128 better = _mm_cmplt_ps(d2, b0);
                const __m128 b = _mm_min_ps(d2, b0); // d2 < b0 ? d2 : b0
                _mm_storeu_ps(B + i, b);
                const __m128i m = _mm_castps_si128(better);
                auto* np = reinterpret_cast<__m128i*>(N + i);
                _mm_storeu_si128(np, _mm_or_si128(_mm_and_si128(m, vnode),
                                                  _mm_andnot_si128(m, _mm_loadu_si128(np))));
                vm = _mm_max_ps(vm, b);
            }
            alignas(16) float m4[4];
            _mm_store_ps(m4, vm);
            max2 = std::max(std::max(m4[0], m4[1]), std::max(m4[2], m4[3]));
#else
            float m = 0.0f;
            for (std::uint32_t i = 0; i < lanes; ++i) {
                const float dx = X[i] - px;
                const float dy = Y[i] - py;
                const float dz = Z[i] - pz;
                const float d2 = (dx * dx + dy * dy) + dz * dz;
                if (d2 < B[i]) {
                    B[i] = d2;
                    N[i] = node;
                }
                m = std::max(m, B[i]);
            }
            max2 = m;
#endif
        };

        // The node-to-cell bound is PointGrid::boxDistance2, written branch-free. max2 only
        // shrinks while nodes are processed, so a node that fails the test stays skipped; one
        // tested against a stale max2 is processed for nothing but changes no result.
        std::size_t j = 0;
#if SYLVA_OFFER_AVX
        if constexpr (Avx) {
            max2 = kHasAvx512 ? scanNodesAvx512(nx, ny, nz, newNodes, firstNew, cell.lo, cell.hi, X,
                                                Y, Z, B, N, lanes, max2, touched)
                              : scanNodesAvx(nx, ny, nz, newNodes, firstNew, cell.lo, cell.hi, X, Y,
                                             Z, B, N, lanes, max2, touched);
            j = newNodes;
        }
#endif
#if defined(__SSE2__)
        {
            const __m128 vlx = _mm_set1_ps(lx), vly = _mm_set1_ps(ly), vlz = _mm_set1_ps(lz);
            const __m128 vhx = _mm_set1_ps(hx), vhy = _mm_set1_ps(hy), vhz = _mm_set1_ps(hz);
            const __m128 zero = _mm_setzero_ps();
            for (; j + 4 <= newNodes; j += 4) {
                const __m128 x = _mm_loadu_ps(nx + j);
                const __m128 y = _mm_loadu_ps(ny + j);
                const __m128 z = _mm_loadu_ps(nz + j);
                const __m128 dx =
                    _mm_max_ps(_mm_max_ps(_mm_sub_ps(vlx, x), _mm_sub_ps(x, vhx)), zero);
                const __m128 dy =
                    _mm_max_ps(_mm_max_ps(_mm_sub_ps(vly, y), _mm_sub_ps(y, vhy)), zero);
                const __m128 dz =
                    _mm_max_ps(_mm_max_ps(_mm_sub_ps(vlz, z), _mm_sub_ps(z, vhz)), zero);
                const __m128 d2 = _mm_add_ps(_mm_add_ps(_mm_mul_ps(dx, dx), _mm_mul_ps(dy, dy)),
                                             _mm_mul_ps(dz, dz));
                int mask = _mm_movemask_ps(_mm_cmplt_ps(d2, _mm_set1_ps(max2)));
                for (; mask != 0; mask &= mask - 1)
                    process(j +
                            static_cast<std::size_t>(__builtin_ctz(static_cast<unsigned>(mask))));
            }
        }
#endif
        for (; j < newNodes; ++j) {
            const float dx = std::max(std::max(lx - nx[j], nx[j] - hx), 0.0f);
            const float dy = std::max(std::max(ly - ny[j], ny[j] - hy), 0.0f);
            const float dz = std::max(std::max(lz - nz[j], nz[j] - hz), 0.0f);
            if ((dx * dx + dy * dy) + dz * dz < max2) process(j);
        }
        cell.max2 = max2;
        if (!touched) return;
        bool anyKill = false;
        for (std::uint32_t i = 0; i < cell.live; ++i) {
            s.best2[I[i]] = B[i];
            s.bestNode[I[i]] = N[i];
            anyKill |= B[i] < dk2;
        }
        if (!anyKill) return;

        // Without a branch on the kills (one misprediction or two each): every lane written
        // at kept, kept advanced past the live ones. A live point's flag is 0, so storing the
        // test sets exactly the killed ones.
        std::uint32_t* ids = mId.data() + cell.begin;
        std::uint32_t kept = 0;
#if SYLVA_OFFER_AVX
        if (Avx && kHasAvx512)
            kept = compactAvx512(X, Y, Z, B, N, ids, cell.live, dk2, s.killed.data(),
                                 s.bestNode.data());
        else
#endif
            for (std::uint32_t i = 0; i < cell.live; ++i) {
                const bool kill = B[i] < dk2;
                s.killed[I[i]] = static_cast<std::uint8_t>(kill);
                s.bestNode[I[i]] = kill ? -1 : N[i];
                X[kept] = X[i];
                Y[kept] = Y[i];
                Z[kept] = Z[i];
                B[kept] = B[i];
                N[kept] = N[i];
                ids[kept] = I[i];
                kept += kill ? 0u : 1u;
            }
        cell.live = kept;
        // The bounds of the points left (the dead ones need no node offered any more) and
        // their largest distance: minima and maxima, the same in any order.
        if (kept > 0)
            boundLive(X, Y, Z, B, kept, cell);
        else
            cell.max2 = 0.0f;
        clearPadding(cell.begin, kept);
    }

    // cell.lo, cell.hi: the bounds of the \p live points; cell.max2 the largest of their B.
    static void boundLive(const float* X, const float* Y, const float* Z, const float* B,
                          std::uint32_t live, Cell& cell) {
        float lox = X[0], loy = Y[0], loz = Z[0];
        float hix = lox, hiy = loy, hiz = loz;
        float m = B[0];
        std::uint32_t i = 0;
#if defined(__SSE2__)
        if (live >= 4) {
            __m128 l[3] = {_mm_loadu_ps(X), _mm_loadu_ps(Y), _mm_loadu_ps(Z)};
            __m128 h[3] = {l[0], l[1], l[2]};
            __m128 vm = _mm_loadu_ps(B);
            for (i = 4; i + 4 <= live; i += 4) {
                const __m128 x = _mm_loadu_ps(X + i), y = _mm_loadu_ps(Y + i),
                             z = _mm_loadu_ps(Z + i);
                l[0] = _mm_min_ps(l[0], x);
                l[1] = _mm_min_ps(l[1], y);
                l[2] = _mm_min_ps(l[2], z);
                h[0] = _mm_max_ps(h[0], x);
                h[1] = _mm_max_ps(h[1], y);
                h[2] = _mm_max_ps(h[2], z);
                vm = _mm_max_ps(vm, _mm_loadu_ps(B + i));
            }
            alignas(16) float a[7][4];
            _mm_store_ps(a[0], l[0]);
            _mm_store_ps(a[1], l[1]);
            _mm_store_ps(a[2], l[2]);
            _mm_store_ps(a[3], h[0]);
            _mm_store_ps(a[4], h[1]);
            _mm_store_ps(a[5], h[2]);
            _mm_store_ps(a[6], vm);
            for (int k = 0; k < 4; ++k) {
                lox = std::min(lox, a[0][k]);
                loy = std::min(loy, a[1][k]);
                loz = std::min(loz, a[2][k]);
                hix = std::max(hix, a[3][k]);
                hiy = std::max(hiy, a[4][k]);
                hiz = std::max(hiz, a[5][k]);
                m = std::max(m, a[6][k]);
            }
        }
#endif
        for (; i < live; ++i) {
            lox = std::min(lox, X[i]);
            loy = std::min(loy, Y[i]);
            loz = std::min(loz, Z[i]);
            hix = std::max(hix, X[i]);
            hiy = std::max(hiy, Y[i]);
            hiz = std::max(hiz, Z[i]);
            m = std::max(m, B[i]);
        }
        cell.lo = {lox, loy, loz};
        cell.hi = {hix, hiy, hiz};
        cell.max2 = m;
    }

    // About pointsPerCell() points per cell, never finer than d_i / 8 (the pruning works on
    // cells: smaller cells prune more points but cost more node-to-cell tests; 16 against 8:
    // bench_spacecolonization 3k-100k points 14-20 % faster, the English oak 2-5 %, since the
    // point loop went branch-free; 32 against 16: 3k-100k points 9-13 % faster, perf_gate
    // spacecol 11 %, the oak 2 %, as the nodes were offered to whole cells four at a time;
    // 64 no better than 32 then; 64 against 32 once the offers took eight lanes (offerAvx):
    // perf_gate spacecol 6 %, the oak 1 %).
    static float cellSizeFor(const glm::vec3& lo, const glm::vec3& hi, std::size_t points,
                             float di) {
        const glm::dvec3 e = glm::max(glm::dvec3(hi - lo), glm::dvec3(1e-3));
        const double h = std::cbrt(e.x * e.y * e.z * pointsPerCell() / static_cast<double>(points));
        return static_cast<float>(std::max(h, static_cast<double>(di) / 8.0));
    }
    // 64 with the eight-lane offers, 32 with SSE2's four (64 there: perf_gate spacecol 0.379
    // -> 0.40); then, once a cell's bounds shrank to its live points, 192 and 64 (the oak's grow
    // stage 3.5 % faster than 64, perf_gate spacecol 0.286-0.287 -> 0.278-0.280; 128 and 256 in
    // between; SSE2 spacecol 0.356-0.359 -> 0.344-0.357, the oak without AVX the same).
    static double pointsPerCell() {
        return useAvx() ? 192.0 : 64.0;
    }

    std::vector<float> mX, mY, mZ, mBest2; ///< per point, grouped by cell, padded
    std::vector<std::int32_t> mNode;
    std::vector<std::uint32_t> mId;
    std::vector<Cell> mCells;
    std::vector<std::uint32_t> mActive; ///< cells with live points
    std::vector<float> mNX, mNY, mNZ;   ///< the nodes added since the last update
};

AcceleratedSearch::AcceleratedSearch(const std::vector<glm::vec3>& points, float di)
    : mImpl(std::make_unique<Impl>(points, di)) {}

AcceleratedSearch::~AcceleratedSearch() = default;

std::size_t AcceleratedSearch::update(PointState& s, const std::vector<glm::vec3>& nodes,
                                      std::size_t firstNew, float dk2) {
    return mImpl->update(s, nodes, firstNew, dk2);
}

} // namespace sylva::growth
