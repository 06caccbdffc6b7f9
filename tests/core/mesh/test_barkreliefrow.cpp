#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <numbers>
#include <vector>

#include "engine/mesh/barkrelief.h"
#include "engine/util/random.h"
#include "engine/util/safenormalize.h"

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

// barkSlopeRow (four quotients to a division on SSE2) against the relief vertices' slopes as the
// tube mesher made them one vertex at a time, bit for bit: every side count from 3 to 100 (each
// remainder of four, the seam's neighbours), rows of random ρ with repeated values, steps ds
// above, at and below the 1e-12 threshold (0 and negative included).
TEST(BarkReliefRow, SlopeRowIsTheVertexByVertexQuotients) {
    sylva::Rng rng(31);
    for (int res = 3; res <= 100; ++res)
        for (const float ds : {0.37f, 1e-12f, 2e-12f, 0.0f, -0.5f, 3.0e-7f}) {
            std::vector<float> row(static_cast<std::size_t>(res) + 1), a(row.size()), b(row.size());
            for (std::size_t j = 0; j < row.size(); ++j) {
                row[j] = rng.below(5) == 0 ? 0.25f : rng.uniformf(0.05f, 0.6f);
                a[j] = rng.uniformf(0.05f, 0.6f);
                b[j] = rng.below(7) == 0 ? a[j] : rng.uniformf(0.05f, 0.6f);
            }
            const float dTheta = 2.0f * std::numbers::pi_v<float> / static_cast<float>(res);
            std::vector<float> dTh(row.size() + 3), dS(row.size() + 3);
            mesh::barkSlopeRow(row.data(), a.data(), b.data(), res, 2.0f * dTheta, ds, dTh.data(),
                               dS.data());
            for (int j = 0; j <= res; ++j) {
                const int jPrev = j == 0 ? res - 1 : j - 1, jNext = j == res ? 1 : j + 1;
                const auto k = static_cast<std::size_t>(j);
                const float theta =
                    (row[static_cast<std::size_t>(jNext)] - row[static_cast<std::size_t>(jPrev)]) /
                    (2.0f * dTheta);
                const float along = ds > 1e-12f ? (b[k] - a[k]) / ds : 0.0f;
                EXPECT_EQ(std::memcmp(&dTh[k], &theta, sizeof theta), 0) << res << " " << j;
                EXPECT_EQ(std::memcmp(&dS[k], &along, sizeof along), 0)
                    << res << " " << j << " " << ds;
            }
        }
}

// barkReliefVertices (four vertices to an instruction on SSE2) against glm's expressions a vertex
// at a time, as the tube mesher wrote the relief rings, bit for bit: every side count from 3 to
// 100 (each remainder of four), random frames, ρ and slopes, vertices whose normal has no length
// (ρ and the slopes 0: the radial direction instead), one of a length just under and over the
// least, and -0 directions (a ring table's sines of 0 and π).
TEST(BarkReliefRow, ReliefVerticesAreGlmsVertexByVertex) {
    sylva::Rng rng(37);
    auto unitVector = [&] {
        return glm::normalize(
            glm::vec3(rng.uniformf(-1, 1), rng.uniformf(-1, 1), rng.uniformf(-1, 1)) +
            glm::vec3(0.0f, 0.01f, 0.0f));
    };
    for (int sides = 3; sides <= 100; ++sides) {
        const std::size_t count = static_cast<std::size_t>(sides) + 1, stride = count + 3;
        std::vector<float> ax(stride, 0.0f), ay(stride, 0.0f), rho(stride, 0.0f),
            dTheta(stride, 0.0f), dS(stride, 0.0f);
        for (std::size_t j = 0; j < count; ++j) {
            const double a = 2.0 * std::numbers::pi * static_cast<double>(j % sides) / sides;
            ax[j] = static_cast<float>(std::cos(a));
            ay[j] = j % 7 == 3 ? -0.0f : static_cast<float>(std::sin(a));
            rho[j] = j % 5 == 2 ? 0.0f : rng.uniformf(0.05f, 0.6f);
            dTheta[j] = j % 5 == 2 ? 0.0f : rng.uniformf(-0.3f, 0.3f);
            dS[j] = j % 5 == 2 ? 0.0f : rng.uniformf(-0.2f, 0.2f);
        }
        const glm::vec3 n = unitVector(), t = glm::normalize(glm::cross(n, unitVector())),
                        b = glm::cross(t, n);
        const glm::vec3 p(rng.uniformf(-5, 5), rng.uniformf(0, 20), rng.uniformf(-5, 5));
        // The least length: over most normals, between two vertices' in turn.
        const float least = sides % 3 == 0 ? 1e-10f : sides % 3 == 1 ? 0.2f : 0.35f;
        std::vector<float> out(6 * stride);
        mesh::barkReliefVertices(ax.data(), ay.data(), count, p, n, b, t, rho.data(), dTheta.data(),
                                 dS.data(), least, out.data(), stride);
        for (std::size_t j = 0; j < count; ++j) {
            const glm::vec3 radial = ax[j] * n + ay[j] * b;
            const glm::vec3 around = -ay[j] * n + ax[j] * b;
            const glm::vec3 position = p + rho[j] * radial;
            const glm::vec3 normal = safeNormalize(
                rho[j] * radial - dTheta[j] * around - rho[j] * dS[j] * t, radial, least);
            for (int k = 0; k < 3; ++k) {
                const float got = out[static_cast<std::size_t>(k) * stride + j];
                const float gotNormal = out[static_cast<std::size_t>(3 + k) * stride + j];
                EXPECT_EQ(std::memcmp(&got, &position[k], sizeof got), 0) << sides << " " << j;
                EXPECT_EQ(std::memcmp(&gotNormal, &normal[k], sizeof got), 0)
                    << sides << " " << j << " " << k;
            }
        }
    }
}

// barkReliefInterleave against the vertex-by-vertex writes it replaces (a position, a normal and
// uTiles · u, v a vertex), bit for bit: every count 0-40 (every tail past the fours), lanes of
// random values with -0, a NaN and a subnormal among them, the vertices after the last untouched.
TEST(BarkReliefRow, InterleaveIsTheVertexByVertexWrites) {
    sylva::Rng rng(53);
    for (std::size_t count = 0; count <= 40; ++count) {
        const std::size_t stride = count + 3;
        std::vector<float> lanes(6 * stride), u(stride);
        for (float& x : lanes)
            x = rng.uniformf(-50.0f, 50.0f);
        for (float& x : u)
            x = rng.uniformf(0.0f, 1.0f);
        if (count > 2) {
            lanes[1] = -0.0f;
            lanes[stride + 2] = std::numeric_limits<float>::quiet_NaN();
            lanes[4 * stride + count - 1] = 1e-42f;
            u[count - 1] = -0.0f;
        }
        const float uTiles = rng.uniformf(1.0f, 7.0f), v = rng.uniformf(0.0f, 30.0f);
        std::vector<glm::vec3> pos(count + 2, glm::vec3(7.0f)), nrm(count + 2, glm::vec3(7.0f));
        std::vector<glm::vec2> uv(count + 2, glm::vec2(7.0f));
        mesh::barkReliefInterleave(lanes.data(), stride, count, u.data(), uTiles, v, pos.data(),
                                   nrm.data(), uv.data());
        auto same = [](float a, float b) {
            return std::bit_cast<std::uint32_t>(a) == std::bit_cast<std::uint32_t>(b);
        };
        for (std::size_t j = 0; j < count + 2; ++j) {
            const bool written = j < count;
            for (int k = 0; k < 3; ++k) {
                const auto kk = static_cast<std::size_t>(k);
                EXPECT_TRUE(same(pos[j][k], written ? lanes[kk * stride + j] : 7.0f))
                    << count << " " << j << " " << k;
                EXPECT_TRUE(same(nrm[j][k], written ? lanes[(3 + kk) * stride + j] : 7.0f))
                    << count << " " << j << " " << k;
            }
            EXPECT_TRUE(same(uv[j].x, written ? uTiles * u[j] : 7.0f)) << count << " " << j;
            EXPECT_TRUE(same(uv[j].y, written ? v : 7.0f)) << count << " " << j;
        }
    }
}
