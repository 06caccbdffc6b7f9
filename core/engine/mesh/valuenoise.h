#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "engine/util/rawvector.h"

namespace sylva::mesh {

/// Three value noises in [-1, 1] (the leaf tints' patches over a crown, leaftint.h): random
/// values at the integer lattice of \p seed, smoothly interpolated. Deterministic: a point's
/// value depends only on the seed and the point.
///
/// The eight lattice values of the last cell are kept: cards come branch by branch, and the
/// next card is often in the same cell (perf record of the English oak: the noise half of
/// tintLeafCards' time). A lattice value is 24 hashes of the point; with cover(), the values of
/// a box's lattice are kept in a grid, each made the first time a cell needs it (the oak's
/// cards change cell every other card: about 5,000 cells of 48 hashes a tree, most of them the
/// same points again); a cell inside the grid reads its eight points there, after one bounds
/// test and one test that the cell's points are made (the last cell's copy is only for points
/// outside the grid: its branch on the cell being the last one was mispredicted about every
/// other card). The same values with or without it.
class ValueNoise {
public:
    explicit ValueNoise(std::uint64_t seed) : mSeed(seed) {}

    /// Keeps the lattice values of the points from floor(lo) - 1 to floor(hi) + 2 in a grid when
    /// they are at most \p maxPoints; else (or outside the box) they are made as needed.
    void cover(const glm::dvec3& lo, const glm::dvec3& hi, std::size_t maxPoints);

    glm::dvec3 operator()(const glm::dvec3& p);

    /// The value at the lattice point (x, y, z), made from the seed (what the grid keeps).
    glm::dvec3 lattice(std::int64_t x, std::int64_t y, std::int64_t z) const;

private:
    const glm::dvec3& kept(std::int64_t x, std::int64_t y, std::int64_t z);
    void makeCell(std::int64_t x, std::int64_t y, std::int64_t z, std::size_t base);
    // The trilinear blend of a cell's points, row[dz][dy][dx].
    static glm::dvec3 interpolate(const glm::dvec3* const row[2][2], double sx, double sy,
                                  double sz);

    std::uint64_t mSeed;
    bool mValid = false;
    std::int64_t mCell[3] = {0, 0, 0};
    glm::dvec3 mCorner[2][2][2];
    // The grid: mSize points along each axis from mOrigin; mMade says which are made.
    std::int64_t mOrigin[3] = {0, 0, 0};
    std::int64_t mSize[3] = {0, 0, 0};
    /// The grid's points, each written when it is made (mMade) before it is read: a RawVector,
    /// whose resize does not zero them (the English oak's crown: ~10-40k points, 24 bytes each,
    /// a zero fill a tree that the points overwrote or never read).
    RawVector<glm::dvec3> mGrid;
    std::vector<std::uint8_t> mMade;
    std::vector<std::uint8_t>
        mCellMade; ///< the cells (by their lowest point) whose points are made
    glm::dvec3 mScratch{0.0};
};

} // namespace sylva::mesh
