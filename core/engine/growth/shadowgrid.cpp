#include "engine/growth/shadowgrid.h"

#include <algorithm>
#include <cmath>

#include "engine/util/error.h"

namespace sylva::growth {

ShadowKernel ShadowKernel::make(double a, double b, int depth) {
    requireRange("shadow_a", a, 1e-6, 100.0);
    requireRange("shadow_b", b, 1.0 + 1e-6, 100.0);
    requireRange("shadow_depth", depth, 0, 32);
    ShadowKernel k;
    k.depth = depth;
    k.delta.resize(static_cast<std::size_t>(depth) + 1);
    for (int q = 0; q <= depth; ++q)
        k.delta[static_cast<std::size_t>(q)] =
            static_cast<std::int32_t>(std::lround(a * std::pow(b, -q) * ShadowGrid::kScale));
    return k;
}

ShadowGrid::ShadowGrid(float voxelSize, float floorY, int margin)
    : mVoxelSize(voxelSize), mMargin(std::max(margin, 0)) {
    requireRange("voxel size", voxelSize, 1e-4, 1e3);
    mFloor = static_cast<int>(std::floor(floorY / voxelSize));
}

glm::ivec3 ShadowGrid::voxelOf(const glm::vec3& p) const {
    const glm::vec3 s = glm::floor(p / mVoxelSize);
    return {static_cast<int>(s.x), static_cast<int>(s.y), static_cast<int>(s.z)};
}

glm::vec3 ShadowGrid::centreOf(const glm::ivec3& v) const {
    return (glm::vec3(v) + 0.5f) * mVoxelSize;
}

void ShadowGrid::setBlocked(const glm::ivec3& v) {
    if (v.y < mFloor) return;
    reserveAround(v);
    mBlocked[index(v)] = 1;
    mAnyBlocked = true;
}

void ShadowGrid::clearShadow() {
    std::fill(mValues.begin(), mValues.end(), 0);
}

void ShadowGrid::reserveAround(const glm::ivec3& v) {
    const glm::ivec3 needLo(v.x - mMargin, mFloor, v.z - mMargin);
    const glm::ivec3 needHi(v.x + mMargin, std::max(v.y, mFloor), v.z + mMargin);
    if (!mValues.empty() && inside(needLo) && inside(needHi)) return;
    glm::ivec3 lo = needLo, hi = needHi;
    if (!mValues.empty()) {
        // Grow by half the current size on the side that overflows, so that a growing tree
        // triggers only O(log n) copies.
        const glm::ivec3 curHi = mLo + mDim - 1;
        const glm::ivec3 slack = glm::max(mDim / 2, glm::ivec3(4));
        for (int a = 0; a < 3; ++a) {
            lo[a] = needLo[a] < mLo[a] ? std::min(needLo[a], mLo[a] - slack[a]) : mLo[a];
            hi[a] = needHi[a] > curHi[a] ? std::max(needHi[a], curHi[a] + slack[a]) : curHi[a];
        }
        lo.y = mFloor;
    }
    resize(lo, hi);
}

void ShadowGrid::resize(const glm::ivec3& lo, const glm::ivec3& hi) {
    const glm::ivec3 dim = hi - lo + 1;
    const std::size_t count = static_cast<std::size_t>(dim.x) * static_cast<std::size_t>(dim.y) *
                              static_cast<std::size_t>(dim.z);
    if (count > (std::size_t{1} << 31))
        throw LimitExceeded("shadow grid would need " + std::to_string(count) +
                            " voxels; use a larger voxel_size");
    std::vector<std::int32_t> values(count, 0);
    std::vector<std::uint8_t> blockedNew(count, 0);
    for (int y = mLo.y; y < mLo.y + mDim.y; ++y)
        for (int x = mLo.x; x < mLo.x + mDim.x; ++x) {
            const std::size_t from = index({x, y, mLo.z});
            const std::size_t to =
                (static_cast<std::size_t>(y - lo.y) * static_cast<std::size_t>(dim.x) +
                 static_cast<std::size_t>(x - lo.x)) *
                    static_cast<std::size_t>(dim.z) +
                static_cast<std::size_t>(mLo.z - lo.z);
            std::copy_n(mValues.begin() + static_cast<std::ptrdiff_t>(from), mDim.z,
                        values.begin() + static_cast<std::ptrdiff_t>(to));
            std::copy_n(mBlocked.begin() + static_cast<std::ptrdiff_t>(from), mDim.z,
                        blockedNew.begin() + static_cast<std::ptrdiff_t>(to));
        }
    mLo = lo;
    mDim = dim;
    mValues = std::move(values);
    mBlocked = std::move(blockedNew);
}

void ShadowGrid::addPyramid(const glm::ivec3& v, const ShadowKernel& kernel, int sign) {
    if (kernel.depth > mMargin)
        throw InvalidInput("shadow_depth " + std::to_string(kernel.depth) +
                           " exceeds the grid margin " + std::to_string(mMargin));
    reserveAround(v);
    for (int q = 0; q <= kernel.depth; ++q) {
        const int y = v.y - q;
        if (y < mFloor) break;
        const std::int32_t d = sign * kernel.delta[static_cast<std::size_t>(q)];
        for (int x = v.x - q; x <= v.x + q; ++x) {
            std::int32_t* row = mValues.data() + index({x, y, v.z - q});
            for (int k = 0; k <= 2 * q; ++k)
                row[k] += d;
        }
    }
}

bool ShadowGrid::sameShadow(const ShadowGrid& other) const {
    const glm::ivec3 lo = glm::min(mLo, other.mLo);
    const glm::ivec3 hi = glm::max(mLo + mDim, other.mLo + other.mDim);
    for (int y = lo.y; y < hi.y; ++y)
        for (int x = lo.x; x < hi.x; ++x)
            for (int z = lo.z; z < hi.z; ++z) {
                const glm::ivec3 v(x, y, z);
                const std::int32_t a = inside(v) ? mValues[index(v)] : 0;
                const std::int32_t b = other.inside(v) ? other.mValues[other.index(v)] : 0;
                if (a != b) return false;
            }
    return true;
}

} // namespace sylva::growth
