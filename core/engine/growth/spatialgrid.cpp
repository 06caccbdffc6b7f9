#include "engine/growth/spatialgrid.h"

#include <algorithm>
#include <cmath>

#include "engine/util/error.h"

namespace sylva::growth {

PointGrid::PointGrid(const std::vector<glm::vec3>& points, float cellSize) : mPoints(points) {
    if (!(cellSize > 0.0f) || !std::isfinite(cellSize))
        throw InvalidInput("grid cell size must be positive and finite");
    if (mPoints.empty()) return;
    glm::vec3 lo = mPoints[0];
    glm::vec3 hi = mPoints[0];
    for (const glm::vec3& p : mPoints) {
        if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z))
            throw InvalidInput("grid point is not finite");
        lo = glm::min(lo, p);
        hi = glm::max(hi, p);
    }
    // Keep the dense table linear in the number of points.
    const double maxCells = std::max<double>(4096.0, 4.0 * static_cast<double>(mPoints.size()));
    const glm::dvec3 extent = glm::dvec3(hi - lo);
    double h = cellSize;
    for (;;) {
        const double n = (std::floor(extent.x / h) + 1) * (std::floor(extent.y / h) + 1) *
                         (std::floor(extent.z / h) + 1);
        if (n <= maxCells) break;
        h *= 1.25;
    }
    mCellSize = static_cast<float>(h);
    mInvCellSize = 1.0 / static_cast<double>(mCellSize);
    mBounds.lo = lo;
    mBounds.hi = hi;
    mOrigin = lo;
    mDims = glm::ivec3(static_cast<int>(std::floor(extent.x / h)) + 1,
                       static_cast<int>(std::floor(extent.y / h)) + 1,
                       static_cast<int>(std::floor(extent.z / h)) + 1);
    const std::size_t tableSize = static_cast<std::size_t>(mDims.x) *
                                  static_cast<std::size_t>(mDims.y) *
                                  static_cast<std::size_t>(mDims.z);

    // Counting sort by cell; a stable pass keeps increasing point index inside each cell.
    std::vector<std::uint32_t> cellOf(mPoints.size());
    std::vector<std::uint32_t> count(tableSize + 1, 0);
    for (std::size_t i = 0; i < mPoints.size(); ++i) {
        const glm::ivec3 c = cellCoord(mPoints[i]);
        cellOf[i] = static_cast<std::uint32_t>(tableIndex(c.x, c.y, c.z));
        ++count[cellOf[i] + 1];
    }
    for (std::size_t t = 0; t < tableSize; ++t)
        count[t + 1] += count[t];
    mOrder.resize(mPoints.size());
    std::vector<std::uint32_t> fill(count.begin(), count.end() - 1);
    for (std::size_t i = 0; i < mPoints.size(); ++i)
        mOrder[fill[cellOf[i]]++] = static_cast<std::uint32_t>(i);

    mSorted.resize(mPoints.size());
    for (std::size_t k = 0; k < mOrder.size(); ++k)
        mSorted[k] = mPoints[mOrder[k]];

    mTable.assign(tableSize, -1);
    for (std::size_t t = 0; t < tableSize; ++t) {
        if (count[t] == count[t + 1]) continue;
        Cell cell;
        cell.begin = count[t];
        cell.end = count[t + 1];
        cell.lo = cell.hi = mPoints[mOrder[cell.begin]];
        for (std::uint32_t k = cell.begin; k < cell.end; ++k) {
            cell.lo = glm::min(cell.lo, mPoints[mOrder[k]]);
            cell.hi = glm::max(cell.hi, mPoints[mOrder[k]]);
        }
        mTable[t] = static_cast<std::int32_t>(mCells.size());
        mCells.push_back(cell);
    }
}

glm::ivec3 PointGrid::cellCoord(const glm::vec3& p) const {
    glm::ivec3 c;
    for (int a = 0; a < 3; ++a) {
        // floor((p - origin) / cell), the division only where the product by the reciprocal
        // (at most an ulp or two off) is that close to a whole number: the same cells, without
        // three divisions a point.
        const double d = static_cast<double>(p[a]) - mOrigin[a];
        const double v = d * mInvCellSize;
        double f = std::floor(v);
        if (v - f < 1e-9 || f + 1.0 - v < 1e-9) f = std::floor(d / mCellSize);
        c[a] = static_cast<int>(std::clamp(f, 0.0, static_cast<double>(mDims[a] - 1)));
    }
    return c;
}

} // namespace sylva::growth
