#pragma once

#include <cstdint>
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

    /// Calls f(pointIndex, distance2) for every point with distance2(point, center) < radius²,
    /// cell by cell in grid order, points of a cell in increasing index order.
    template <class F> void forEachInRadius(const glm::vec3& center, float radius, F&& f) const {
        if (mCells.empty()) return;
        const float r2 = radius * radius;
        const glm::ivec3 a = cellCoord(center - glm::vec3(radius));
        const glm::ivec3 b = cellCoord(center + glm::vec3(radius));
        for (int z = a.z; z <= b.z; ++z)
            for (int y = a.y; y <= b.y; ++y)
                for (int x = a.x; x <= b.x; ++x) {
                    const std::int32_t c = mTable[tableIndex(x, y, z)];
                    if (c < 0) continue;
                    const Cell& cell = mCells[static_cast<std::size_t>(c)];
                    if (!(boxDistance2(cell, center) < r2)) continue;
                    for (std::uint32_t k = cell.begin; k < cell.end; ++k) {
                        const std::uint32_t i = mOrder[k];
                        const float d2 = distance2(mPoints[i], center);
                        if (d2 < r2) f(i, d2);
                    }
                }
    }

private:
    glm::ivec3 cellCoord(const glm::vec3& p) const; ///< clamped to the grid
    std::size_t tableIndex(int x, int y, int z) const {
        return (static_cast<std::size_t>(z) * static_cast<std::size_t>(mDims.y) +
                static_cast<std::size_t>(y)) *
                   static_cast<std::size_t>(mDims.x) +
               static_cast<std::size_t>(x);
    }

    std::vector<glm::vec3> mPoints;
    float mCellSize = 1.0f;
    glm::vec3 mOrigin{0.0f};
    glm::ivec3 mDims{0};
    std::vector<std::int32_t> mTable; ///< dense: cell coordinate -> index into mCells or -1
    std::vector<Cell> mCells;
    std::vector<std::uint32_t> mOrder;
};

} // namespace sylva::growth
