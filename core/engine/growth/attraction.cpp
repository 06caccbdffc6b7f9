#include "engine/growth/attraction.h"

#include <cmath>
#include <cstring>
#include <limits>

#include "engine/util/random.h"

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
// Drop: \p live as the search left it, the points it killed (\p killed) moved out in the same
// pass (written at the kept count, which advances past the live ones, as dropKilled's scalar
// loop does) and summed into the spare node; \p kept their count.
template <bool Drop>
__attribute__((noinline)) std::size_t
sumPointsNoHash(const std::uint32_t* live, std::size_t liveCount, std::uint32_t* liveOut,
                const std::uint8_t* __restrict killed, std::size_t& kept,
                const glm::vec3* __restrict pts, const float* __restrict best2,
                const std::int32_t* __restrict bestNode, const glm::vec3* __restrict pos,
                glm::vec3* __restrict sum, std::uint32_t* __restrict count,
                std::uint32_t* __restrict firstMet, std::uint32_t dummy) {
    std::size_t met = 0, out = 0;
    for (std::size_t k = 0; k < liveCount; ++k) {
        const std::uint32_t a = live[k];
        std::int32_t bn = bestNode[a];
        if constexpr (Drop) {
            // A killed point's node -1 by an or, not a select: GCC made the select a branch,
            // mispredicted at every kill.
            const std::int32_t dead = killed[a] != 0 ? 1 : 0;
            liveOut[out] = a;
            out += static_cast<std::size_t>(1 - dead);
            bn |= -dead;
        }
        const std::uint32_t j = bn < 0 ? dummy : static_cast<std::uint32_t>(bn);
        const std::uint32_t c = count[j];
        count[j] = c + 1;
        firstMet[met] = j;
        met += c == 0 ? 1 : 0;
        const float b2 = best2[a];
        sum[j] += (pts[a] - pos[bn < 0 ? 0 : j]) * (1.0f / std::sqrt(b2));
    }
    kept = Drop ? out : liveCount;
    return met;
}

} // namespace

// liveOut (the same array as live) and killed: sumAttractionDroppingKilled; liveCount then
// becomes the kept count.
static void sumAttractionImpl(Attraction& a, const std::uint32_t* liveData, std::size_t& liveCount,
                              std::uint32_t* liveOut, const std::uint8_t* killed,
                              const glm::vec3* points, const float* best2,
                              const std::int32_t* bestNode, const glm::vec3* nodes,
                              std::size_t nodeCount, bool hashSets) {
    const std::span<const std::uint32_t> live(liveData, liveCount);
    for (const std::uint32_t j : a.attracted)
        if (j < a.sum.size()) a.sum[j] = glm::vec3(0.0f); // as sumPointsNoHash needs them
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
    if (hashSets) {
        sumPoints<true>(live.data(), live.size(), points, best2, bestNode, nodes, a.sum.data(),
                        a.count.data(), a.setHash.data(), a.marks.data());
    } else if (nodeCount > 0) {
        a.firstMet.resize(nodeCount + 2);
        const auto dummy = static_cast<std::uint32_t>(nodeCount);
        const std::size_t met =
            killed != nullptr
                ? sumPointsNoHash<true>(liveData, liveCount, liveOut, killed, liveCount, points,
                                        best2, bestNode, nodes, a.sum.data(), a.count.data(),
                                        a.firstMet.data(), dummy)
                : sumPointsNoHash<false>(liveData, liveCount, nullptr, nullptr, liveCount, points,
                                         best2, bestNode, nodes, a.sum.data(), a.count.data(),
                                         a.firstMet.data(), dummy);
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

void sumAttraction(Attraction& a, std::span<const std::uint32_t> live, const glm::vec3* points,
                   const float* best2, const std::int32_t* bestNode, const glm::vec3* nodes,
                   std::size_t nodeCount, bool hashSets) {
    std::size_t count = live.size();
    sumAttractionImpl(a, live.data(), count, nullptr, nullptr, points, best2, bestNode, nodes,
                      nodeCount, hashSets);
}

void sumAttractionDroppingKilled(Attraction& a, std::vector<std::uint32_t>& live,
                                 const std::uint8_t* killed, const glm::vec3* points,
                                 const float* best2, const std::int32_t* bestNode,
                                 const glm::vec3* nodes, std::size_t nodeCount) {
    std::size_t count = live.size();
    if (nodeCount == 0) {
        std::erase_if(live, [killed](std::uint32_t p) { return killed[p] != 0; });
        count = live.size();
    }
    sumAttractionImpl(a, live.data(), count, live.data(), killed, points, best2, bestNode, nodes,
                      nodeCount, false);
    live.resize(count);
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
