#include "engine/mesh/rankselect.h"

#include <algorithm>
#include <bit>
#include <cstdint>
#include <vector>

namespace sylva::mesh {

namespace {

// The bits of a float +0 or above (+infinity included) order as its value; above this, NaN.
constexpr std::uint32_t kInfinityBits = 0x7f800000u;

// The digit of the value's bits that decides among \p n counts \p rank: its index, \p rank then
// the rank among the values with that digit.
std::uint32_t digitOf(const std::uint32_t* counts, std::size_t n, std::size_t& rank) {
    for (std::uint32_t d = 0; d < n; ++d) {
        if (rank < counts[d]) return d;
        rank -= counts[d];
    }
    return static_cast<std::uint32_t>(n - 1); // not reached: the counts add up past rank
}

} // namespace

bool valueAtRank(std::span<const float> values, std::size_t rank, float& out) {
    const std::size_t n = values.size();
    // The top digit: bits 31..20 (the sign 0, the exponent and three bits of the fraction).
    std::uint32_t top[2048] = {};
    std::uint32_t worst = 0;
    for (float v : values) {
        const auto b = std::bit_cast<std::uint32_t>(v);
        worst = std::max(worst, b);
        ++top[(b >> 20) & 2047u]; // a negative value's sign masked off: refused below
    }
    if (worst > kInfinityBits) return false; // NaN, -0 or negative
    std::size_t r = rank;
    const std::uint32_t d1 = digitOf(top, 2048, r);
    // The values that share it, without a branch on each (it is about every other one).
    std::vector<std::uint32_t> kept(n);
    std::size_t count = 0;
    for (float v : values) {
        const auto b = std::bit_cast<std::uint32_t>(v);
        kept[count] = b;
        count += (b >> 20) == d1;
    }
    // Bits 19..10 among them, then bits 9..0 among those that share those too.
    std::uint32_t mid[1024] = {};
    for (std::size_t i = 0; i < count; ++i)
        ++mid[(kept[i] >> 10) & 1023u];
    const std::uint32_t d2 = digitOf(mid, 1024, r);
    const std::uint32_t high = (d1 << 10) | d2;
    std::uint32_t low[1024] = {};
    for (std::size_t i = 0; i < count; ++i)
        low[kept[i] & 1023u] += (kept[i] >> 10) == high;
    const std::uint32_t d3 = digitOf(low, 1024, r);
    out = std::bit_cast<float>((high << 10) | d3);
    return true;
}

float valueAtRankPlain(std::span<const float> values, std::size_t rank) {
    std::vector<float> copy(values.begin(), values.end());
    const auto at = copy.begin() + static_cast<std::ptrdiff_t>(rank);
    std::nth_element(copy.begin(), at, copy.end());
    return *at;
}

} // namespace sylva::mesh
