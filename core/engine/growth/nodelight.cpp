#include "engine/growth/nodelight.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <span>
#include <vector>

#include "engine/growth/shadowcounts.h"
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

// Only the nodes' own voxels are read: they are counted (shadowAtSources) instead of spread
// over a grid, the same raw values bit for bit (every node is above the grid's floor, which
// clips nothing it reads).
void recordLight(skel::Skeleton& s, float voxelSize) {
    const std::size_t n = s.size();
    s.light.assign(n, 0.0f);
    if (n == 0) return;
    const Setup k = setup(s, voxelSize);
    const ShadowGrid grid(voxelSize, k.floorY - voxelSize, k.kernel.depth);
    std::vector<glm::ivec3> voxel(n);
    for (std::size_t i = 0; i < n; ++i)
        voxel[i] = grid.voxelOf(s.position[i]);
    std::vector<std::int32_t> raw;
    if (!shadowAtSources(voxel, k.kernel, raw)) {
        recordLightByShadowGrid(s, voxelSize);
        return;
    }
    gather(s, [&](std::size_t i) { return static_cast<double>(raw[i]); });
}

} // namespace sylva::growth
