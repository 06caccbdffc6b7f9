#include "engine/growth/attraction.h"

#include <cmath>
#include <cstring>
#include <limits>

#include "engine/util/random.h"

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

namespace sylva::growth {

namespace {

// The per-point loop on its own, out of line: inlined into colonize() its pointers and the
// live cursor were kept on the stack and loaded again every point (colonize's registers were
// taken by its other loops). Hash: fold each point into its node's setHash.
template <bool Hash>
__attribute__((noinline)) void
sumPoints(const std::uint32_t* live, std::size_t liveCount, const glm::vec3* __restrict pts,
          const float* __restrict best2, const std::int32_t* __restrict bestNode,
          const glm::vec3* __restrict pos, glm::vec3* __restrict sum,
          std::uint32_t* __restrict count, std::uint64_t* __restrict hash,
          std::uint64_t* __restrict marks) {
    for (std::size_t k = 0; k < liveCount; ++k) {
        const std::uint32_t a = live[k];
        const std::int32_t bn = bestNode[a];
        if (bn < 0) continue;
        const auto j = static_cast<std::size_t>(bn);
        if (count[j]++ == 0) {
            marks[j >> 6] |= std::uint64_t{1} << (j & 63);
            sum[j] = glm::vec3(0.0f);
            if constexpr (Hash) hash[j] = 0x243F6A8885A308D3ull;
        }
        const float b2 = best2[a];
        sum[j] += (pts[a] - pos[j]) * (1.0f / std::sqrt(b2));
        if constexpr (Hash) hash[j] = mixSeed(hash[j], a);
    }
}

// Without the hash, no branch on a node's first point (one mispredicted a node an iteration):
// the sums start at zero (sumAttraction clears the last call's), each point's node is stored at
// the first-met cursor, which advances only when the node's count was 0. Points out of reach go
// to the spare node \p dummy (its sum and count are scratch; its position read is node 0's).
__attribute__((noinline)) std::size_t
sumPointsNoHash(const std::uint32_t* live, std::size_t liveCount, const glm::vec3* __restrict pts,
                const float* __restrict best2, const std::int32_t* __restrict bestNode,
                const glm::vec3* __restrict pos, glm::vec3* __restrict sum,
                std::uint32_t* __restrict count, std::uint32_t* __restrict firstMet,
                std::uint32_t dummy) {
    std::size_t met = 0;
    for (std::size_t k = 0; k < liveCount; ++k) {
        const std::uint32_t a = live[k];
        const std::int32_t bn = bestNode[a];
        const std::uint32_t j = bn < 0 ? dummy : static_cast<std::uint32_t>(bn);
        const std::uint32_t c = count[j];
        count[j] = c + 1;
        firstMet[met] = j;
        met += c == 0 ? 1 : 0;
        const float b2 = best2[a];
        sum[j] += (pts[a] - pos[bn < 0 ? 0 : j]) * (1.0f / std::sqrt(b2));
    }
    return met;
}

#if defined(__SSE2__)
// Spare nodes past the last for the points out of reach (node −1: the accelerated search sets
// a killed point's node to −1 too, and colonize drops the killed points from the list now and
// then).
constexpr std::size_t kSpares = 8;

// sumPointsNoHash with each point, node and sum in one register (Attraction::Lanes: the count
// lane first, then x, y, z): the point's difference from its node, times (1, r, r, r) with
// r = 1 / √best2, added to the node's sum, whose count lane so gains exactly 1 (1 − 0, times 1).
// x, y and z the same subtractions, products and sums as glm's, lane by lane (SSE2 has no fused
// multiply-add), so the same bits; one load of the point, the node and the sum each and one
// store, where the vec3s and the separate count took three loads and stores, and the nodes met
// are marked (a byte each, read after the loop) instead of listed as first met: 29 instructions
// a point instead of 43, no pointer spilled but one. Counts are exact below 2^24 points.
// Nodes from \p spare on are the spares.
__attribute__((noinline)) void sumPointsPacked(const std::uint32_t* live, std::size_t liveCount,
                                               const Attraction::Lanes* __restrict pts,
                                               const float* __restrict best2,
                                               const std::int32_t* __restrict bestNode,
                                               Attraction::NodeLanes* __restrict nodes,
                                               std::uint8_t* __restrict met, std::uint32_t spare) {
    const __m128 one = _mm_set1_ps(1.0f);
    const std::uint32_t* in = live;
    const std::uint32_t* const end = in + liveCount;
    // Point a with r4 = (r, r, r, r).
    auto add = [&](std::uint32_t a, __m128 r4) __attribute__((always_inline)) {
        const std::int32_t bn = bestNode[a];
        // Node −1: one of kSpares spare nodes by the point's index, so that their
        // sums' loads and stores do not wait one on another (about half the points in the first
        // iterations are out of reach: one chain through one spare node).
        const std::uint32_t j =
            bn < 0 ? spare + (a & (kSpares - 1)) : static_cast<std::uint32_t>(bn);
        met[j] = 1;
        const __m128 r = _mm_move_ss(r4, one); // (1, r, r, r)
        const __m128 d = _mm_sub_ps(_mm_load_ps(&pts[a].count), _mm_load_ps(&nodes[j].at.count));
        float* s = &nodes[j].sum.count;
        _mm_store_ps(s, _mm_add_ps(_mm_load_ps(s), _mm_mul_ps(d, r)));
    };
    // Four points' 1.0f / std::sqrt(best2) by one sqrtps and one divps: the divider, shared by
    // square roots and divisions, took ~3 ns a point for sqrtss and divss.
    for (; end - in >= 4; in += 4) {
        const std::uint32_t a0 = in[0], a1 = in[1], a2 = in[2], a3 = in[3];
        const __m128 b01 = _mm_unpacklo_ps(_mm_load_ss(best2 + a0), _mm_load_ss(best2 + a1));
        const __m128 b23 = _mm_unpacklo_ps(_mm_load_ss(best2 + a2), _mm_load_ss(best2 + a3));
        const __m128 r = _mm_div_ps(one, _mm_sqrt_ps(_mm_movelh_ps(b01, b23)));
        add(a0, _mm_shuffle_ps(r, r, 0x00));
        add(a1, _mm_shuffle_ps(r, r, 0x55));
        add(a2, _mm_shuffle_ps(r, r, 0xAA));
        add(a3, _mm_shuffle_ps(r, r, 0xFF));
    }
    for (; in != end; ++in) {
        const std::uint32_t a = *in;
        const __m128 r = _mm_div_ss(one, _mm_sqrt_ss(_mm_load_ss(best2 + a))); // 1.0f / std::sqrt
        add(a, _mm_shuffle_ps(r, r, 0x00));
    }
}
#endif

} // namespace

// Where the packed sums run: SSE2, and a count exact in a float.
static bool packedRuns(std::size_t points) {
#if defined(__SSE2__)
    return points < (std::size_t{1} << 24);
#else
    (void)points;
    return false;
#endif
}

// The packed sums (sumPointsPacked) and their bookkeeping: the copies of the points (once) and
// of the nodes new since the last call, then the loop, then the nodes met in index order, their
// sums and counts handed over (a.sum, a.count) and cleared.
static void sumPacked(Attraction& a, std::span<const std::uint32_t> live,
                      std::span<const glm::vec3> points, const float* best2,
                      const std::int32_t* bestNode, const glm::vec3* nodes, std::size_t nodeCount) {
#if defined(__SSE2__)
    if (a.point4Of != points.data() || a.point4.size() != points.size()) {
        a.point4.resize(points.size());
        for (std::size_t i = 0; i < points.size(); ++i)
            a.point4[i] = {1.0f, points[i].x, points[i].y, points[i].z};
        a.point4Of = points.data();
    }
    // The nodes before the last call's count are the same (colonize only appends); another
    // array, or fewer nodes, is copied again. The spare entries past them are zero.
    const std::size_t withSpares = nodeCount + kSpares;
    std::size_t known = a.node4.size() < kSpares ? 0 : a.node4.size() - kSpares;
    if (a.node4Of != nodes || known > nodeCount) known = 0;
    a.node4.resize(withSpares);
    const Attraction::Lanes zero(0.0f, 0.0f, 0.0f, 0.0f);
    for (std::size_t j = known; j < nodeCount; ++j) {
        a.node4[j].at = {0.0f, nodes[j].x, nodes[j].y, nodes[j].z};
        a.node4[j].sum = zero;
    }
    for (std::size_t j = nodeCount; j < withSpares; ++j)
        a.node4[j].at = a.node4[j].sum = zero;
    a.node4Of = nodes;
    // Read eight at a time below: room to a multiple of 8, zero.
    a.met.resize((withSpares + 7) & ~std::size_t{7}, 0);
    const auto spare = static_cast<std::uint32_t>(nodeCount);
    sumPointsPacked(live.data(), live.size(), a.point4.data(), best2, bestNode, a.node4.data(),
                    a.met.data(), spare);
    for (std::size_t j = nodeCount; j < withSpares; ++j) {
        a.met[j] = 0;
        a.node4[j].sum = zero;
    }
    a.attracted.clear();
    const std::uint8_t* met = a.met.data();
    for (std::size_t w = 0; w < nodeCount; w += 8) {
        std::uint64_t m;
        std::memcpy(&m, met + w, 8);
        for (; m != 0; m &= m - 1) {
            const std::size_t j = w + static_cast<std::size_t>(__builtin_ctzll(m)) / 8;
            a.met[j] = 0;
            Attraction::Lanes& s = a.node4[j].sum;
            a.sum[j] = glm::vec3(s.x, s.y, s.z);
            a.count[j] = static_cast<std::uint32_t>(s.count);
            s = zero;
            a.attracted.push_back(static_cast<std::uint32_t>(j));
        }
    }
#else
    (void)a, (void)live, (void)points;
    (void)best2, (void)bestNode, (void)nodes, (void)nodeCount;
#endif
}

void sumAttraction(Attraction& a, std::span<const std::uint32_t> live,
                   std::span<const glm::vec3> pointSpan, const float* best2,
                   const std::int32_t* bestNode, const glm::vec3* nodes, std::size_t nodeCount,
                   bool hashSets, bool packed) {
    const glm::vec3* points = pointSpan.data();
    packed = packed && !hashSets && nodeCount > 0 && packedRuns(pointSpan.size());
    // As sumPointsNoHash needs them (the packed sums write the attracted ones' whole).
    if (!packed)
        for (const std::uint32_t j : a.attracted)
            if (j < a.sum.size()) a.sum[j] = glm::vec3(0.0f);
    // The new nodes' sums zeroed by memset: resize's fill with a vec3 value went through a
    // stack temporary written in two parts and read back whole (a store-forwarding stall an
    // element, ~0.3 % of the oak's samples).
    const std::size_t hadSums = a.sum.size();
    if (nodeCount + 1 > hadSums) {
        a.sum.resize(nodeCount + 1);
        std::memset(static_cast<void*>(a.sum.data() + hadSums), 0,
                    (nodeCount + 1 - hadSums) * sizeof(glm::vec3));
    } else {
        a.sum.resize(nodeCount + 1);
    }
    a.count.resize(nodeCount + 1, 0);
    a.setHash.resize(nodeCount);
    a.marks.resize((nodeCount + 63) / 64, 0);
    if (packed) {
        sumPacked(a, live, pointSpan, best2, bestNode, nodes, nodeCount);
        return;
    }
    if (hashSets) {
        sumPoints<true>(live.data(), live.size(), points, best2, bestNode, nodes, a.sum.data(),
                        a.count.data(), a.setHash.data(), a.marks.data());
    } else if (nodeCount > 0) {
        a.firstMet.resize(nodeCount + 2);
        const auto dummy = static_cast<std::uint32_t>(nodeCount);
        const std::size_t met =
            sumPointsNoHash(live.data(), live.size(), points, best2, bestNode, nodes, a.sum.data(),
                            a.count.data(), a.firstMet.data(), dummy);
        a.count[nodeCount] = 0;
        a.sum[nodeCount] = glm::vec3(0.0f);
        for (std::size_t k = 0; k < met; ++k) {
            const std::uint32_t j = a.firstMet[k];
            if (j != dummy) a.marks[j >> 6] |= std::uint64_t{1} << (j & 63);
        }
    }
    a.attracted.clear();
    for (std::size_t w = 0; w < a.marks.size(); ++w) {
        for (std::uint64_t m = a.marks[w]; m != 0; m &= m - 1)
            a.attracted.push_back(static_cast<std::uint32_t>(w * 64 + __builtin_ctzll(m)));
        a.marks[w] = 0;
    }
}

void nearestPoints(Attraction& a, std::span<const std::uint32_t> nodes,
                   std::span<const std::uint32_t> live, const float* best2,
                   const std::int32_t* bestNode) {
    const std::size_t n = a.sum.size();
    a.wanted.resize(n, 0);
    a.nearest2.resize(n);
    a.nearest.resize(n);
    for (const std::uint32_t j : nodes) {
        a.wanted[j] = 1;
        a.nearest2[j] = std::numeric_limits<float>::infinity();
    }
    for (const std::uint32_t p : live) {
        const std::int32_t bn = bestNode[p];
        if (bn < 0 || a.wanted[static_cast<std::size_t>(bn)] == 0) continue;
        const auto j = static_cast<std::size_t>(bn);
        if (best2[p] < a.nearest2[j]) {
            a.nearest2[j] = best2[p];
            a.nearest[j] = p;
        }
    }
    for (const std::uint32_t j : nodes)
        a.wanted[j] = 0;
}

} // namespace sylva::growth
