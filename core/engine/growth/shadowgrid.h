#pragma once

#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include <glm/glm.hpp>

namespace sylva::growth {

/// The shadow increments of one pyramid (Palubicki et al. 2009): Δs(q) = a·b^(−q) for
/// q = 0…q_max, stored in ShadowGrid's fixed-point units so that adding and removing the same
/// pyramid, in any order, returns the grid to exactly the same values.
struct ShadowKernel {
    int depth = 0;                   ///< q_max, voxels below the source, 0..32
    std::vector<std::int32_t> delta; ///< depth+1 fixed-point increments

    /// \param a shadow of the source voxel itself, > 0; \param b attenuation base, > 1.
    static ShadowKernel make(double a, double b, int depth);
};

/// One pyramid change of a batch (ShadowGrid::applyBatch): the pyramid of kernel \p kernel at
/// voxel \p voxel, added \p weight times (negative removes).
struct ShadowSource {
    glm::ivec3 voxel{0};
    std::int32_t weight = 1;
    std::uint32_t kernel = 0; ///< index into the kernels passed to applyBatch
};

/// A voxel grid of shadow values that grows on demand (Y up). A source at voxel (I, J, K)
/// shadows the voxels (I±p, J−q, K±p), p = 0…q, q = 0…q_max, by Δs(q). The grid always keeps
/// a horizontal margin of q_max voxels around every source, so no pyramid is ever clipped
/// sideways and growing the grid is a plain copy; pyramids are clipped only below the floor.
/// Values are fixed point (1/kScale), which makes incremental updates exact.
/// Most voxels a shadow grid may hold: 2^28 (268 million, 1.3 GB at five bytes a voxel: the
/// grid and its blocked flags), e.g. 300 × 300 × 360 m at voxel_size 0.5; the library's largest
/// self-organizing preset needs 146 million (the grid grows by half its size when a bud leaves
/// it). It was 2^31 (10.7 GB) until fuzzing found a shrub whose short-lived shoots reached 190 m
/// and made the grid 580 million voxels (3.7 GB) for a 16 m tree.
inline constexpr std::size_t kMaxShadowVoxels = std::size_t{1} << 28;

class ShadowGrid {
public:
    static constexpr double kScale = 16384.0;

    /// \param voxelSize edge length in metres, > 0; \param floorY lowest height (metres) that
    /// receives shadow; \param margin largest q_max of any source that will be added.
    ShadowGrid(float voxelSize, float floorY, int margin);

    float voxelSize() const { return mVoxelSize; }
    /// Integer voxel coordinates of a point (floor(p / voxelSize)).
    glm::ivec3 voxelOf(const glm::vec3& p) const {
        const glm::vec3 s = glm::floor(p / mVoxelSize);
        return {static_cast<int>(s.x), static_cast<int>(s.y), static_cast<int>(s.z)};
    }
    /// voxelOf() of each point into out[i].voxel (out.size() >= points.size()), four
    /// coordinates at a time on SSE2: the same divisions, and a floor from truncation that is
    /// exact wherever the scalar conversion is defined (the same ints everywhere else too).
    void voxelsOf(std::span<const glm::vec3> points, std::span<ShadowSource> out) const;
    /// Centre of a voxel in metres.
    glm::vec3 centreOf(const glm::ivec3& v) const;

    /// Adds (sign = +1) or removes (sign = −1) the pyramid of a source at voxel \p v, growing
    /// the grid first when needed.
    void addPyramid(const glm::ivec3& v, const ShadowKernel& kernel, int sign = 1);
    /// Applies many pyramid changes at once, equal to addPyramid for each of them in any order
    /// (integer arithmetic). Grows the grid once, then updates one horizontal layer at a time
    /// (in parallel over layers, so each layer stays in cache and no two threads write the
    /// same voxel): the result is identical on any number of threads.
    void applyBatch(std::span<const ShadowSource> sources, std::span<const ShadowKernel> kernels);
    /// Shadow value s at a voxel (0 above or beside the grid, the floor row's value below it).
    double shadow(const glm::ivec3& v) const { return raw(v) / kScale; }
    std::int32_t raw(const glm::ivec3& v) const {
        glm::ivec3 c = v;
        if (c.y < mFloor) c.y = mFloor;
        return inside(c) ? mValues[index(c)] : 0;
    }

    /// Value of neighbourhood() for an opaque voxel.
    static constexpr std::int32_t kOpaque = 0x7fffffff;
    /// Raw values of the 3×3×3 voxels around \p v, index (dy+1)·9 + (dx+1)·3 + (dz+1), with
    /// kOpaque for blocked voxels; same values as raw() and blocked() voxel by voxel, but one
    /// bounds test and nine contiguous triples in the common case.
    void neighbourhood(const glm::ivec3& v, std::int32_t (&out)[27]) const;

    /// Index of the value raw(v) reads (below the floor: the floor row's), or −1 outside the
    /// grid, for lookups split in two passes: first every index (arithmetic only), then the
    /// values with prefetchCell() a few lookups ahead. Bud lookups are scattered over a grid of
    /// tens of MB, so overlapping their cache misses is most of their cost.
    std::int64_t cellOf(const glm::ivec3& v) const {
        glm::ivec3 c = v;
        if (c.y < mFloor) c.y = mFloor;
        return inside(c) ? static_cast<std::int64_t>(index(c)) : -1;
    }
    std::int32_t rawAt(std::int64_t cell) const {
        return cell < 0 ? 0 : mValues[static_cast<std::size_t>(cell)];
    }
    void prefetchCell(std::int64_t cell) const {
        if (cell >= 0) __builtin_prefetch(mValues.data() + cell);
    }
    /// False when no voxel is blocked (the common obstacle-free case).
    bool anyBlocked() const { return mAnyBlocked; }
    /// Hints the cache to load the 3×3×3 neighbourhood of \p v ahead of neighbourhood().
    void prefetchNeighbourhood(const glm::ivec3& v) const {
        if (!(inside(v - 1) && inside(v + 1))) return;
        const std::int32_t* base = mValues.data() + index(v - 1);
        const auto sx = static_cast<std::size_t>(mDim.z);
        const std::size_t sy = sx * static_cast<std::size_t>(mDim.x);
        for (std::size_t y = 0; y < 3; ++y)
            for (std::size_t x = 0; x < 3; ++x) {
                __builtin_prefetch(base + y * sy + x * sx);
                __builtin_prefetch(base + y * sy + x * sx + 2);
            }
    }

    /// Marks a voxel opaque (obstacles): buds there get no light and never grow towards it.
    void setBlocked(const glm::ivec3& v);
    bool blocked(const glm::ivec3& v) const {
        return mAnyBlocked && inside(v) && mBlocked[index(v)] != 0;
    }

    /// Zeroes every shadow value (keeps bounds and blocked voxels).
    void clearShadow();
    /// Makes sure the voxel \p v plus the margin is inside the grid.
    void reserveAround(const glm::ivec3& v);

    const glm::ivec3& lo() const { return mLo; }
    const glm::ivec3& dims() const { return mDim; }
    /// Raw values in (y, x, z) order, for comparisons in tests.
    const std::vector<std::int32_t>& values() const { return mValues; }
    /// True when both grids hold the same shadow at every voxel either of them covers.
    bool sameShadow(const ShadowGrid& other) const;

private:
    bool inside(const glm::ivec3& v) const {
        return v.x >= mLo.x && v.y >= mLo.y && v.z >= mLo.z && v.x < mLo.x + mDim.x &&
               v.y < mLo.y + mDim.y && v.z < mLo.z + mDim.z;
    }
    std::size_t index(const glm::ivec3& v) const {
        return (static_cast<std::size_t>(v.y - mLo.y) * static_cast<std::size_t>(mDim.x) +
                static_cast<std::size_t>(v.x - mLo.x)) *
                   static_cast<std::size_t>(mDim.z) +
               static_cast<std::size_t>(v.z - mLo.z);
    }
    void resize(const glm::ivec3& lo, const glm::ivec3& hi);

    float mVoxelSize;
    int mFloor;  ///< lowest voxel row
    int mMargin; ///< horizontal margin kept around sources
    glm::ivec3 mLo{0};
    glm::ivec3 mDim{0};
    std::vector<std::int32_t> mValues;
    std::vector<std::uint8_t> mBlocked;
    bool mAnyBlocked = false; ///< lets the common obstacle-free case skip the lookup
    /// applyBatch scratch: sources by layer (counting sort), each layer's extent (x0, x1, z0,
    /// z1) and how many of its sources reach each depth.
    struct SortedSource {
        int x, z;
        std::int32_t weight;
        std::uint32_t kernel;
    };
    std::vector<std::uint32_t> mBucketStart, mReach;
    std::vector<SortedSource> mSorted;
    std::vector<glm::ivec4> mLayerExtent;
    /// applyBatch: one thread's share of the sort (counts, then first slots, per layer).
    struct Part {
        std::vector<std::uint32_t> count, reach;
        std::vector<glm::ivec4> extent;
    };
    std::vector<Part> mPart;
    /// applyBatch: one zeroed difference plane per thread ((dims.x + 1) · (dims.z + 1)).
    std::vector<std::vector<std::int32_t>> mDiff;
    /// applyBatch: Δs(q) of every kernel, q-major (q · kernels + kernel), 0 beyond its depth.
    std::vector<std::int32_t> mDeltaByDepth;
};

} // namespace sylva::growth
