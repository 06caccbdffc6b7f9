#include "engine/growth/nodelight.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <span>
#include <vector>

#include "engine/growth/shadowgrid.h"

namespace sylva::growth {

namespace {

// The source's own shadow (subtracted again at its voxel) and the attenuation per voxel down.
// litAttractors' pyramids fade by half a voxel and stop at four; a crown's inside is shaded by
// everything above it, so these reach about 4 m and fade slowly (measured on the oak: with
// litAttractors' kernel the shell's bottom was as dark as the core, which read as a flat crown).
constexpr double kShadowA = 1.0;
constexpr double kShadowB = 1.3;
constexpr double kReachMetres = 4.0;

struct Setup {
    ShadowKernel kernel;
    float floorY = 0.0f;
};

Setup setup(const skel::Skeleton& s, float voxelSize) {
    const int depth = std::clamp(static_cast<int>(std::lround(kReachMetres / voxelSize)), 2, 16);
    Setup out{ShadowKernel::make(kShadowA, kShadowB, depth), std::numeric_limits<float>::max()};
    for (const glm::vec3& p : s.position)
        out.floorY = std::min(out.floorY, p.y);
    return out;
}

// Each node's light from the raw shadow at its voxel; children come after their parents: one
// backward pass sums each subtree.
template <class Raw> void gather(skel::Skeleton& s, Raw&& rawAt) {
    for (std::size_t i = s.size(); i-- > 0;) {
        const double shadow = std::max(rawAt(i) / ShadowGrid::kScale - kShadowA, 0.0);
        s.light[i] += static_cast<float>(1.0 / (1.0 + shadow));
        if (s.parent[i] >= 0) s.light[static_cast<std::size_t>(s.parent[i])] += s.light[i];
    }
}

} // namespace

void recordLightByShadowGrid(skel::Skeleton& s, float voxelSize) {
    const std::size_t n = s.size();
    s.light.assign(n, 0.0f);
    if (n == 0) return;
    const Setup k = setup(s, voxelSize);
    ShadowGrid grid(voxelSize, k.floorY - voxelSize, k.kernel.depth);
    std::vector<ShadowSource> sources(n);
    for (std::size_t i = 0; i < n; ++i)
        sources[i].voxel = grid.voxelOf(s.position[i]);
    grid.applyBatch(sources, std::span<const ShadowKernel>(&k.kernel, 1));
    gather(s, [&](std::size_t i) { return static_cast<double>(grid.raw(sources[i].voxel)); });
}

// Only the nodes' own voxels are read, so instead of spreading every pyramid over a grid, each
// node counts the nodes in the square above it at each depth q (a summed-area table of the
// node counts, layer by layer) and adds Δs(q) times the count: the same integer sum as the
// grid's (every node is above the grid's floor, which clips nothing it reads), in the grid's
// 32-bit wrap-around, so the same raw values bit for bit.
void recordLight(skel::Skeleton& s, float voxelSize) {
    const std::size_t n = s.size();
    s.light.assign(n, 0.0f);
    if (n == 0) return;
    const Setup k = setup(s, voxelSize);
    const int depth = k.kernel.depth;
    const ShadowGrid grid(voxelSize, k.floorY - voxelSize, depth);
    std::vector<glm::ivec3> voxel(n);
    glm::ivec3 lo = grid.voxelOf(s.position[0]), hi = lo;
    for (std::size_t i = 0; i < n; ++i) {
        voxel[i] = grid.voxelOf(s.position[i]);
        lo = glm::min(lo, voxel[i]);
        hi = glm::max(hi, voxel[i]);
    }
    // The grid path's voxels are at most the box, its margin and half its first size again on
    // each axis: where that could reach ShadowGrid's limit, take the grid path (and its error);
    // and for a box of more than 2^24 voxels, whose table and per-voxel sums (12 bytes a voxel
    // here) would outgrow the grid's five.
    const glm::dvec3 box = glm::dvec3(hi) - glm::dvec3(lo) + 1.0;
    const double m = depth;
    if ((box.x + 3 * m + 8) * (1.5 * box.y + 8) * (box.z + 3 * m + 8) >=
            static_cast<double>(kMaxShadowVoxels) ||
        box.x * box.y * box.z > static_cast<double>(std::size_t{1} << 24)) {
        recordLightByShadowGrid(s, voxelSize);
        return;
    }
    // sat[y][x][z]: nodes in layer y with x' <= x and z' <= z, over the box grown by the depth
    // on each side in x and z and above it, so that no square is clipped: each node reads four
    // entries a depth, one step apart each (the empty margins count nothing).
    const auto d = static_cast<std::size_t>(depth);
    const std::size_t dx = static_cast<std::size_t>(box.x) + 2 * d + 1;
    const std::size_t dz = static_cast<std::size_t>(box.z) + 2 * d + 1;
    const std::size_t dy = static_cast<std::size_t>(box.y) + d;
    const std::size_t sx = dz, sy = dx * dz;
    std::vector<std::uint32_t> sat(dy * sy, 0);
    auto at = [&](const glm::ivec3& v) {
        return static_cast<std::size_t>(v.y - lo.y) * sy +
               (static_cast<std::size_t>(v.x - lo.x) + d + 1) * sx +
               static_cast<std::size_t>(v.z - lo.z) + d + 1;
    };
    for (const glm::ivec3& v : voxel)
        ++sat[at(v)];
    // Rows before the box hold no node (they stay zero), rows after it repeat its last.
    const std::size_t rowsEnd = static_cast<std::size_t>(box.x) + d + 1;
    for (std::size_t y = 0; y < static_cast<std::size_t>(box.y); ++y) {
        std::uint32_t* layer = sat.data() + y * sy;
        for (std::size_t x = d + 1; x < rowsEnd; ++x) {
            std::uint32_t run = 0;
            for (std::size_t z = 1; z < dz; ++z) {
                run += layer[x * sx + z];
                layer[x * sx + z] = run + layer[(x - 1) * sx + z];
            }
        }
        for (std::size_t x = rowsEnd; x < dx; ++x)
            std::copy_n(layer + (x - 1) * sx, sx, layer + x * sx);
    }
    const std::vector<std::int32_t>& delta = k.kernel.delta;
    std::vector<std::int32_t> raw(n);
    const std::uint32_t* const t = sat.data();
    // Nodes share voxels (segments are shorter than a voxel): each voxel's sum is taken once.
    const auto bx = static_cast<std::size_t>(box.x), bz = static_cast<std::size_t>(box.z);
    std::vector<std::int64_t> memo(static_cast<std::size_t>(box.y) * bx * bz, -1);
    for (std::size_t i = 0; i < n; ++i) {
        const glm::ivec3 v = voxel[i];
        std::int64_t& m = memo[(static_cast<std::size_t>(v.y - lo.y) * bx +
                                static_cast<std::size_t>(v.x - lo.x)) *
                                   bz +
                               static_cast<std::size_t>(v.z - lo.z)];
        if (m < 0) {
            // The corners of the square q around the node's column at layer y + q.
            std::size_t hh = at(v), ll = hh - sx - 1, lh = hh - sx, hl = hh - 1;
            std::uint32_t sum = 0;
            for (std::size_t q = 0; q <= d; ++q) {
                sum += static_cast<std::uint32_t>(delta[q]) * (t[hh] - t[lh] - t[hl] + t[ll]);
                hh += sy + sx + 1;
                ll += sy - sx - 1;
                lh += sy - sx + 1;
                hl += sy + sx - 1;
            }
            m = sum;
        }
        raw[i] = static_cast<std::int32_t>(static_cast<std::uint32_t>(m));
    }
    gather(s, [&](std::size_t i) { return static_cast<double>(raw[i]); });
}

} // namespace sylva::growth
