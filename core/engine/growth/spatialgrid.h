#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

#include <glm/glm.hpp>

namespace sylva::growth {

/// Squared distance with one fixed evaluation order, `(dx² + dy²) + dz²`. Every growth model
/// that compares an accelerated search with a brute-force oracle must use this one function so
/// that both see bit-identical distances (and so identical tie-breaking).
inline float distance2(const glm::vec3& a, const glm::vec3& b) {
    const float dx = a.x - b.x;
    const float dy = a.y - b.y;
    const float dz = a.z - b.z;
    return (dx * dx + dy * dy) + dz * dz;
}

/// A uniform grid over a fixed set of points (attraction points, markers), stored cell by cell.
///
/// Built once by a counting sort: memory is linear in the number of points (the dense cell table
/// is capped at a few entries per point by enlarging the cell size when needed). Inside a cell the
/// points keep increasing index order, so loops over a cell are deterministic. Each non-empty
/// cell carries the tight bounds of its points, which lets callers skip whole cells with
/// boxDistance2(), a lower bound of distance2() to every point of the cell that holds in float
/// arithmetic too (rounding is monotonic), so pruning never changes a result.
///
/// Used by space colonization (cell-level pruning against cached nearest nodes) and meant for the
/// self-organizing model's markers (fixed-radius queries with forEachInRadius()).
class PointGrid {
public:
    struct Cell {
        std::uint32_t begin = 0; ///< range in order()
        std::uint32_t end = 0;
        glm::vec3 lo{0.0f}; ///< tight bounds of the cell's points
        glm::vec3 hi{0.0f};
    };

    PointGrid() = default;
    /// \param cellSize metres, > 0; enlarged automatically if the grid would need more than
    /// about four table entries per point.
    PointGrid(const std::vector<glm::vec3>& points, float cellSize);

    float cellSize() const { return mCellSize; }
    /// The non-empty cells, in grid order.
    const std::vector<Cell>& cells() const { return mCells; }
    /// Point indices, cell by cell (a permutation of 0..n-1).
    const std::vector<std::uint32_t>& order() const { return mOrder; }
    const std::vector<glm::vec3>& points() const { return mPoints; }

    /// Squared distance from \p p to the bounds of \p cell (0 inside): never larger than
    /// distance2(point, p) for any point of the cell.
    static float boxDistance2(const Cell& cell, const glm::vec3& p) {
        const float dx =
            p.x < cell.lo.x ? cell.lo.x - p.x : (p.x > cell.hi.x ? p.x - cell.hi.x : 0.0f);
        const float dy =
            p.y < cell.lo.y ? cell.lo.y - p.y : (p.y > cell.hi.y ? p.y - cell.hi.y : 0.0f);
        const float dz =
            p.z < cell.lo.z ? cell.lo.z - p.z : (p.z > cell.hi.z ? p.z - cell.hi.z : 0.0f);
        return (dx * dx + dy * dy) + dz * dz;
    }

    /// Drops every point whose index fails \p keep, keeping the cells (their bounds made tight
    /// again; an emptied cell is skipped by every query). Linear in the points held, without
    /// the construction's sorting: for a set that only shrinks (the self-organizing model's
    /// alive markers, cycle after cycle). The order of the points kept does not change.
    template <class Keep> void keepOnly(Keep&& keep) {
        std::uint32_t out = 0;
        for (Cell& cell : mCells) {
            const std::uint32_t begin = out;
            glm::vec3 lo(std::numeric_limits<float>::infinity()), hi(-lo);
            for (std::uint32_t k = cell.begin; k < cell.end; ++k) {
                if (!keep(mOrder[k])) continue;
                mOrder[out] = mOrder[k];
                mSorted[out] = mSorted[k];
                lo = glm::min(lo, mSorted[out]);
                hi = glm::max(hi, mSorted[out]);
                ++out;
            }
            cell.begin = begin;
            cell.end = out;
            // An empty cell: lo = +inf, so boxDistance2 is +inf and no query enters it.
            cell.lo = begin == out ? glm::vec3(std::numeric_limits<float>::infinity()) : lo;
            cell.hi = begin == out ? glm::vec3(std::numeric_limits<float>::infinity()) : hi;
        }
        mOrder.resize(out);
        mSorted.resize(out);
    }

    /// Calls f(pointIndex, distance2) for every point with distance2(point, center) < radius²,
    /// cell by cell in grid order, points of a cell in increasing index order.
    template <class F> void forEachInRadius(const glm::vec3& center, float radius, F&& f) const {
        if (mCells.empty()) return;
        const float r2 = radius * radius;
        // Every point lies in the points' bounds: a sphere that misses them finds none (the
        // self-organizing model asks for every marker, most far from the few buds early on).
        if (!(boxDistance2(mBounds, center) < r2)) return;
        // The cells the box around the sphere overlaps, or one more at an edge it grazes:
        // multiplied by the reciprocal instead of cellCoord's division (that was ~45 % of a
        // self-organizing tree's time). A cell more holds no point within the radius (the box
        // test and the distance skip it), so f sees the same points in the same order.
        const glm::ivec3 a = cellRange(center - glm::vec3(radius), -kRangeSlack);
        const glm::ivec3 b = cellRange(center + glm::vec3(radius), kRangeSlack);
        for (int z = a.z; z <= b.z; ++z)
            for (int y = a.y; y <= b.y; ++y)
                for (int x = a.x; x <= b.x; ++x) {
                    const std::int32_t c = mTable[tableIndex(x, y, z)];
                    if (c < 0) continue;
                    const Cell& cell = mCells[static_cast<std::size_t>(c)];
                    if (!(boxDistance2(cell, center) < r2)) continue;
                    for (std::uint32_t k = cell.begin; k < cell.end; ++k) {
                        const float d2 = distance2(mSorted[k], center);
                        if (d2 < r2) f(mOrder[k], d2);
                    }
                }
    }

private:
    glm::ivec3 cellCoord(const glm::vec3& p) const; ///< clamped to the grid
    /// Far more than the rounding of (p - origin) · (1 / cell) against cellCoord's division.
    static constexpr double kRangeSlack = 1e-6;
    /// cellCoord of \p p with \p slack cells added before the floor (negative: the cell
    /// below when \p p is that close to its lower face), clamped to the grid.
    glm::ivec3 cellRange(const glm::vec3& p, double slack) const {
        glm::ivec3 c;
        for (int a = 0; a < 3; ++a) {
            const double f =
                std::floor((static_cast<double>(p[a]) - mOrigin[a]) * mInvCellSize + slack);
            c[a] = static_cast<int>(std::clamp(f, 0.0, static_cast<double>(mDims[a] - 1)));
        }
        return c;
    }
    std::size_t tableIndex(int x, int y, int z) const {
        return (static_cast<std::size_t>(z) * static_cast<std::size_t>(mDims.y) +
                static_cast<std::size_t>(y)) *
                   static_cast<std::size_t>(mDims.x) +
               static_cast<std::size_t>(x);
    }

    std::vector<glm::vec3> mPoints;
    float mCellSize = 1.0f;
    double mInvCellSize = 1.0; ///< 1 / mCellSize
    Cell mBounds;              ///< lo, hi: the bounds of every point
    glm::vec3 mOrigin{0.0f};
    glm::ivec3 mDims{0};
    std::vector<std::int32_t> mTable; ///< dense: cell coordinate -> index into mCells or -1
    std::vector<Cell> mCells;
    std::vector<std::uint32_t> mOrder;
    /// mPoints in mOrder's order: a cell's points side by side (the queries read them in a
    /// row instead of one cache miss each through mOrder).
    std::vector<glm::vec3> mSorted;
};

} // namespace sylva::growth
