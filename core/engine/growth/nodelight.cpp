#include "engine/growth/nodelight.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <span>
#include <vector>

#include "engine/growth/shadowcounts.h"
#include "engine/growth/shadowgrid.h"

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

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

// A node's own light from the raw shadow at its voxel.
float ownLight(double raw) {
    const double shadow = std::max(raw / ShadowGrid::kScale - kShadowA, 0.0);
    return static_cast<float>(1.0 / (1.0 + shadow));
}

// ownLight of each of \p n raw values, two at a time on SSE2: the same double operations (the
// division by kScale, a power of two, as the product by its inverse: exact either way; maxpd
// of x and 0 is std::max's x < 0 ? 0 : x, x never −0 or NaN here), one divpd for two nodes.
void ownLights(const std::int32_t* raw, std::size_t n, float* own) {
    std::size_t i = 0;
#if defined(__SSE2__)
    static_assert(ShadowGrid::kScale == 16384.0);
    const __m128d inv = _mm_set1_pd(1.0 / ShadowGrid::kScale), a = _mm_set1_pd(kShadowA);
    const __m128d one = _mm_set1_pd(1.0), zero = _mm_setzero_pd();
    for (; i + 2 <= n; i += 2) {
        const __m128d r =
            _mm_cvtepi32_pd(_mm_loadl_epi64(reinterpret_cast<const __m128i*>(raw + i)));
        const __m128d shadow = _mm_max_pd(_mm_sub_pd(_mm_mul_pd(r, inv), a), zero);
        const __m128 f = _mm_cvtpd_ps(_mm_div_pd(one, _mm_add_pd(one, shadow)));
        _mm_storel_pi(reinterpret_cast<__m64*>(own + i), f);
    }
#endif
    for (; i < n; ++i)
        own[i] = ownLight(raw[i]);
}

// Each node's light: its own (\p own), then, children coming after their parents, one backward
// pass sums each subtree.
void gather(skel::Skeleton& s, const std::vector<float>& own) {
    for (std::size_t i = s.size(); i-- > 0;) {
        s.light[i] += own[i];
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
    std::vector<float> own(n);
    for (std::size_t i = 0; i < n; ++i)
        own[i] = ownLight(grid.raw(sources[i].voxel));
    gather(s, own);
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
    // voxelOf's divisions four coordinates at a time (voxelsOf: the same ints).
    std::vector<ShadowSource> sources(n);
    grid.voxelsOf(s.position, sources);
    std::vector<glm::ivec3> voxel(n);
    for (std::size_t i = 0; i < n; ++i)
        voxel[i] = sources[i].voxel;
    std::vector<std::int32_t> raw;
    if (!shadowAtSources(voxel, k.kernel, raw)) {
        recordLightByShadowGrid(s, voxelSize);
        return;
    }
    std::vector<float> own(n);
    ownLights(raw.data(), n, own.data());
    gather(s, own);
}

} // namespace sylva::growth
