#include <gtest/gtest.h>

#include <bit>
#include <cstdint>
#include <vector>

#include "engine/mesh/barkrelief.h"

using namespace sylva;

namespace {

// The ring the straightforward way: one barkReliefShape a vertex.
std::vector<float> plainRow(mesh::BarkPattern pattern, int columns, int sides, float y,
                            std::uint32_t seed, float amplitude) {
    std::vector<float> row(static_cast<std::size_t>(sides));
    for (int j = 0; j < sides; ++j)
        row[static_cast<std::size_t>(j)] =
            amplitude * mesh::barkReliefShape(
                            pattern, static_cast<float>(j * columns) / static_cast<float>(sides), y,
                            columns, seed);
    return row;
}

} // namespace

// A ring made at once (lattice hashes and each column's height and break made once a ring) is
// the ring made vertex by vertex, bit for bit: even and odd column counts (the warp lattice is
// two columns wide for even ones), more sides than four a column, rings along the axis across
// the lattice rows and the ridges' breaks, a negative y, both patterns.
TEST(BarkReliefRow, MatchesTheShapeVertexByVertex) {
    int compared = 0, nonZero = 0;
    for (mesh::BarkPattern pattern : {mesh::BarkPattern::Ridges, mesh::BarkPattern::Plates})
        for (int columns : {1, 2, 3, 4, 5, 7, 8, 12, 24, 31, 32})
            for (int sides : {columns * mesh::kBarkSidesPerColumn, 64, 3 * columns + 1})
                for (std::uint32_t seed : {0u, 17u, 0xDEADBEEFu}) {
                    const float amplitude = seed == 17u ? 1.0f : 0.15f;
                    for (float y = -3.7f; y < 40.0f; y += 0.613f) {
                        const std::vector<float> plain =
                            plainRow(pattern, columns, sides, y, seed, amplitude);
                        std::vector<float> row(static_cast<std::size_t>(sides), -1.0f);
                        mesh::barkReliefRow(pattern, columns, sides, y, seed, amplitude,
                                            row.data());
                        for (int j = 0; j < sides; ++j) {
                            const auto k = static_cast<std::size_t>(j);
                            ASSERT_EQ(std::bit_cast<std::uint32_t>(row[k]),
                                      std::bit_cast<std::uint32_t>(plain[k]))
                                << "columns " << columns << " sides " << sides << " seed " << seed
                                << " y " << y << " j " << j;
                            ++compared;
                            nonZero += plain[k] != 0.0f;
                        }
                    }
                }
    EXPECT_GT(compared, 100000);
    EXPECT_GT(nonZero, compared / 2); // the rings compared carry relief, not zeros
}

// One BarkRing an axis (what depends on a vertex's place around the axis alone, made once, and
// the room a ring's lattice rows take, reused) for every ring along it and every seed, against
// the ring made vertex by vertex, bit for bit: the same column and side counts as above, rings
// whose lattice rows and column breaks change from one to the next.
TEST(BarkReliefRow, OneRingLayoutServesEveryRingOfTheAxis) {
    int compared = 0;
    for (mesh::BarkPattern pattern : {mesh::BarkPattern::Ridges, mesh::BarkPattern::Plates})
        for (int columns : {1, 2, 3, 4, 5, 7, 8, 12, 24, 31, 32})
            for (int sides : {columns * mesh::kBarkSidesPerColumn, 64, 3 * columns + 1}) {
                mesh::BarkRing ring(pattern, columns, sides);
                for (std::uint32_t seed : {0u, 17u, 0xDEADBEEFu})
                    for (float y = 41.3f; y > -5.0f; y -= 0.377f) {
                        const std::vector<float> plain =
                            plainRow(pattern, columns, sides, y, seed, 0.4f);
                        std::vector<float> row(static_cast<std::size_t>(sides), -1.0f);
                        mesh::barkReliefRow(ring, y, seed, 0.4f, row.data());
                        for (std::size_t k = 0; k < row.size(); ++k, ++compared)
                            ASSERT_EQ(std::bit_cast<std::uint32_t>(row[k]),
                                      std::bit_cast<std::uint32_t>(plain[k]))
                                << "columns " << columns << " sides " << sides << " seed " << seed
                                << " y " << y << " k " << k;
                    }
            }
    EXPECT_GT(compared, 100000);
}
