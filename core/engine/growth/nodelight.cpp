#include "engine/growth/nodelight.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <span>

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

} // namespace

void recordLight(skel::Skeleton& s, float voxelSize) {
    const std::size_t n = s.size();
    s.light.assign(n, 0.0f);
    if (n == 0) return;
    const int depth = std::clamp(static_cast<int>(std::lround(kReachMetres / voxelSize)), 2, 16);
    const ShadowKernel kernel = ShadowKernel::make(kShadowA, kShadowB, depth);
    float floorY = std::numeric_limits<float>::max();
    for (const glm::vec3& p : s.position)
        floorY = std::min(floorY, p.y);
    ShadowGrid grid(voxelSize, floorY - voxelSize, depth);
    std::vector<ShadowSource> sources(n);
    for (std::size_t i = 0; i < n; ++i)
        sources[i].voxel = grid.voxelOf(s.position[i]);
    grid.applyBatch(sources, std::span<const ShadowKernel>(&kernel, 1));
    // Children come after their parents: one backward pass sums each subtree.
    for (std::size_t i = n; i-- > 0;) {
        const double shadow = std::max(grid.shadow(sources[i].voxel) - kShadowA, 0.0);
        s.light[i] += static_cast<float>(1.0 / (1.0 + shadow));
        if (s.parent[i] >= 0) s.light[static_cast<std::size_t>(s.parent[i])] += s.light[i];
    }
}

} // namespace sylva::growth
