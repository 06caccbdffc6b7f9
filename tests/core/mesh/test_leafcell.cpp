#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "engine/mesh/leafcell.h"
#include "engine/mesh/leafcellhash.h"
#include "engine/util/random.h"

using namespace sylva;

// The SSE2 cell (two axes a register, floors from the 1.5 * 2^52 sum) is the one of one axis
// at a time, for middles on cell boundaries and a hair either side of them, signed zeros,
// negative and far coordinates (quotients past 2^51 take the plain path).
TEST(LeafCell, MatchesThePlainCell) {
    Rng rng(51);
    std::vector<double> cells = {0.264195, 0.1, 1.0, 3.5e-4, 7.0};
    for (int i = 0; i < 20; ++i)
        cells.push_back(rng.uniform(1e-4, 5.0));
    std::vector<double> coordinates = {0.0, -0.0, 1e-300, -1e-300};
    for (int i = 0; i < 2000; ++i)
        coordinates.push_back(rng.uniform(-50.0, 50.0) *
                              std::ldexp(1.0, static_cast<int>(rng.below(40)) - 20));
    std::size_t checked = 0;
    for (double cell : cells) {
        std::vector<double> values = coordinates;
        for (int k = -40; k <= 40; ++k) {
            const double edge = k * cell;
            values.insert(values.end(),
                          {edge, std::nextafter(edge, 1e9), std::nextafter(edge, -1e9)});
        }
        // Quotients about 2^51 (the fast floors' bound) and past it, inside the int64 range
        // (floorToInt's).
        for (double q : {0x1p51, -0x1p51, 0x1p51 - 1.0, -(0x1p51 - 1.0), 0x1p52, -0x1p53, 0x1p62})
            values.insert(values.end(), {q * cell, std::nextafter(q * cell, 0.0)});
        for (std::size_t i = 0; i < values.size(); ++i) {
            const glm::dvec3 mid(values[i], values[(i * 7 + 3) % values.size()],
                                 values[(i * 13 + 5) % values.size()]);
            EXPECT_EQ(mesh::leafCell(mid, cell), mesh::leafCellPlain(mid, cell))
                << mid.x << " " << mid.y << " " << mid.z << " / " << cell;
            ++checked;
        }
    }
    EXPECT_GT(checked, 50000u);
}

// leafCellsHashed (eight leaves a register with AVX-512) gives the plain cells and masked hashes
// bit for bit: middles on cell boundaries and either side, signed zeros, far coordinates (blocks
// past 2^51 take the plain cells), runs that are not whole blocks of eight.
TEST(LeafCell, HashedCellsMatchThePlainOnes) {
    Rng rng(41);
    std::vector<double> values = {0.0, -0.0, 1e-300, -1e-300};
    const double cell = 0.264195;
    for (int i = 0; i < 3000; ++i)
        values.push_back(rng.uniform(-30.0, 30.0) *
                         std::ldexp(1.0, static_cast<int>(rng.below(30)) - 15));
    for (int k = -60; k <= 60; ++k)
        values.insert(values.end(),
                      {k * cell, std::nextafter(k * cell, 1e9), std::nextafter(k * cell, -1e9)});
    for (double q : {0x1p51, -0x1p51, 0x1p51 - 1.0, -0x1p52})
        values.push_back(q * cell);
    std::vector<glm::dvec3> mids;
    for (std::size_t i = 0; i < values.size(); ++i)
        mids.emplace_back(values[i], values[(i * 7 + 3) % values.size()],
                          values[(i * 13 + 5) % values.size()]);
    for (std::uint64_t mask : {std::uint64_t{0xffff}, std::uint64_t{0xffffffff}}) {
        for (std::size_t n : {mids.size(), std::size_t{13}, std::size_t{8}, std::size_t{5}}) {
            std::vector<mesh::LeafCell> cells(n), plainCells(n);
            std::vector<std::uint32_t> hashes(n), plainHashes(n);
            mesh::leafCellsHashed(mids.data(), n, cell, mask, cells.data(), hashes.data());
            mesh::leafCellsHashedPlain(mids.data(), n, cell, mask, plainCells.data(),
                                       plainHashes.data());
            for (std::size_t i = 0; i < n; ++i) {
                ASSERT_EQ(cells[i], plainCells[i]) << i;
                ASSERT_EQ(hashes[i], plainHashes[i]) << i;
                ASSERT_EQ(plainCells[i], mesh::leafCellPlain(mids[i], cell)) << i;
                ASSERT_EQ(plainHashes[i], mesh::leafCellHash(plainCells[i]) & mask) << i;
            }
        }
    }
}
