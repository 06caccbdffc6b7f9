#include "engine/growth/shadowcounts.h"

#include <algorithm>
#include <cstddef>

namespace sylva::growth {

namespace {

// The table's counts and their sums wrap around at T's width; a square's count, at most the
// number of sources, is exact when T holds it (its four entries' sum taken modulo T's range).
template <class T>
void countAndRead(std::span<const glm::ivec3> voxels, const ShadowKernel& kernel,
                  const glm::ivec3& lo, const glm::dvec3& box, std::vector<std::int32_t>& raw) {
    const std::size_t n = voxels.size();
    const int depth = kernel.depth;
    // sat[y][x][z]: sources in layer y with x' <= x and z' <= z, over the box grown by the depth
    // on each side in x and z and above it, so that no square is clipped: each voxel reads four
    // entries a depth, one step apart each (the empty margins count nothing).
    const auto d = static_cast<std::size_t>(depth);
    const std::size_t dx = static_cast<std::size_t>(box.x) + 2 * d + 1;
    const std::size_t dz = static_cast<std::size_t>(box.z) + 2 * d + 1;
    const std::size_t dy = static_cast<std::size_t>(box.y) + d;
    const std::size_t sx = dz, sy = dx * dz;
    std::vector<T> sat(dy * sy, 0);
    auto at = [&](const glm::ivec3& v) {
        return static_cast<std::size_t>(v.y - lo.y) * sy +
               (static_cast<std::size_t>(v.x - lo.x) + d + 1) * sx +
               static_cast<std::size_t>(v.z - lo.z) + d + 1;
    };
    for (const glm::ivec3& v : voxels)
        ++sat[at(v)];
    // Rows before the box hold no source (they stay zero), rows after it repeat its last.
    const std::size_t rowsEnd = static_cast<std::size_t>(box.x) + d + 1;
    for (std::size_t y = 0; y < static_cast<std::size_t>(box.y); ++y) {
        T* layer = sat.data() + y * sy;
        for (std::size_t x = d + 1; x < rowsEnd; ++x) {
            T run = 0;
            for (std::size_t z = 1; z < dz; ++z) {
                run = static_cast<T>(run + layer[x * sx + z]);
                layer[x * sx + z] = static_cast<T>(run + layer[(x - 1) * sx + z]);
            }
        }
        for (std::size_t x = rowsEnd; x < dx; ++x)
            std::copy_n(layer + (x - 1) * sx, sx, layer + x * sx);
    }
    const std::vector<std::int32_t>& delta = kernel.delta;
    raw.resize(n);
    const T* const t = sat.data();
    for (std::size_t i = 0; i < n; ++i) {
        const glm::ivec3 v = voxels[i];
        // The corners of the square q around the voxel's column at layer y + q.
        std::size_t hh = at(v), ll = hh - sx - 1, lh = hh - sx, hl = hh - 1;
        std::uint32_t sum = 0;
        for (std::size_t q = 0; q <= d; ++q) {
            const auto count = static_cast<T>(t[hh] - t[lh] - t[hl] + t[ll]);
            sum += static_cast<std::uint32_t>(delta[q]) * count;
            hh += sy + sx + 1;
            ll += sy - sx - 1;
            lh += sy - sx + 1;
            hl += sy + sx - 1;
        }
        raw[i] = static_cast<std::int32_t>(sum);
    }
}

} // namespace

bool shadowAtSources(std::span<const glm::ivec3> voxels, const ShadowKernel& kernel,
                     std::vector<std::int32_t>& raw) {
    const std::size_t n = voxels.size();
    if (n == 0) {
        raw.clear();
        return true;
    }
    const int depth = kernel.depth;
    glm::ivec3 lo = voxels[0], hi = lo;
    for (const glm::ivec3& v : voxels) {
        lo = glm::min(lo, v);
        hi = glm::max(hi, v);
    }
    // The grid path's voxels are at most the box, its margin and half its first size again on
    // each axis: where that could reach ShadowGrid's limit, the grid decides (and throws).
    const glm::dvec3 box = glm::dvec3(hi) - glm::dvec3(lo) + 1.0;
    const double m = depth;
    if ((box.x + 3 * m + 8) * (1.5 * box.y + 8) * (box.z + 3 * m + 8) >=
            static_cast<double>(kMaxShadowVoxels) ||
        box.x * box.y * box.z > static_cast<double>(std::size_t{1} << 24))
        return false;
    // Counts in 16 bits where they fit (fewer sources than 2^16): half the table to clear, sum
    // and read, so more of it in the first-level cache.
    if (n < (std::size_t{1} << 16))
        countAndRead<std::uint16_t>(voxels, kernel, lo, box, raw);
    else
        countAndRead<std::uint32_t>(voxels, kernel, lo, box, raw);
    return true;
}

} // namespace sylva::growth
