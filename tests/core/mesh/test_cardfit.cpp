#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <numeric>
#include <vector>

#include <glm/gtc/quaternion.hpp>

#include "engine/mesh/cardfit.h"
#include "engine/mesh/cardfitlanes.h"
#include "engine/util/random.h"

using namespace sylva;

namespace {

std::vector<skel::Leaf> randomLeaves(Rng& rng, int count) {
    std::vector<skel::Leaf> leaves(static_cast<std::size_t>(count));
    for (skel::Leaf& leaf : leaves) {
        leaf.position = glm::vec3(rng.uniformf(-3, 3), rng.uniformf(2, 9), rng.uniformf(-3, 3));
        leaf.orientation = glm::normalize(glm::quat(rng.uniformf(-1, 1), rng.uniformf(-1, 1),
                                                    rng.uniformf(-1, 1), rng.uniformf(-1, 1)));
        leaf.size = rng.uniformf(0.03f, 0.2f);
    }
    // Frames with zero components (signed zeros through the products) and the identity.
    leaves[3].orientation = glm::quat(1, 0, 0, 0);
    leaves[7].orientation = glm::quat(0, 0, 1, 0);
    leaves[8].orientation = glm::quat(-0.0f, 0.6f, -0.0f, 0.8f);
    leaves[12].orientation = glm::quat(0.5f, -0.5f, 0.5f, -0.5f);
    return leaves;
}

// The same bits (a float's or a double's -0.0 and its 0.0 differ).
template <typename V> bool sameBits(const V& a, const V& b) {
    return std::memcmp(&a, &b, sizeof(V)) == 0;
}

} // namespace

// The SSE2 preparation (four leaves a register) is the straightforward one bit for bit, for
// groups of every size (every remainder of four), in any order of the leaves.
TEST(CardFit, PreparationMatchesTheStraightforwardOne) {
    Rng rng(9);
    const std::vector<skel::Leaf> leaves = randomLeaves(rng, 300);
    mesh::CardFitInput fast, plain;
    for (std::uint32_t size = 1; size <= 23; ++size)
        for (int trial = 0; trial < 6; ++trial) {
            std::vector<std::uint32_t> group(size);
            for (std::uint32_t& i : group)
                i = static_cast<std::uint32_t>(rng.below(leaves.size()));
            if (trial == 0) std::iota(group.begin(), group.end(), 0u); // the special frames
            mesh::prepareCardFit(leaves, group, 0.45f, 1.7f, fast);
            mesh::prepareCardFitPlain(leaves, group, 0.45f, 1.7f, plain);
            ASSERT_EQ(fast.corners.size(), plain.corners.size());
            for (std::size_t k = 0; k < fast.corners.size(); ++k)
                EXPECT_TRUE(sameBits(fast.corners[k], plain.corners[k])) << size << " " << k;
            EXPECT_TRUE(sameBits(fast.heading, plain.heading)) << size;
            EXPECT_TRUE(sameBits(fast.up, plain.up)) << size;
            EXPECT_TRUE(sameBits(fast.left, plain.left)) << size;
            EXPECT_TRUE(sameBits(fast.m, plain.m)) << size;
            EXPECT_TRUE(sameBits(fast.cov, plain.cov)) << size;
        }
}

// A card's corners, mean and covariance are the leaves' corners as appendLeafCards makes them
// (four a leaf, in order), and the SSE2 extent is the straightforward one bit for bit, for
// groups of every size and every direction.
TEST(CardFit, ExtentMatchesTheStraightforwardOne) {
    Rng rng(12);
    const std::vector<skel::Leaf> leaves = randomLeaves(rng, 400);
    mesh::CardFitInput in;
    for (std::uint32_t first = 0, size = 1; first + size <= leaves.size(); first += size++) {
        std::vector<std::uint32_t> group(size);
        std::iota(group.begin(), group.end(), first);
        mesh::prepareCardFit(leaves, group, 0.5f, 1.3f, in);
        ASSERT_EQ(in.corners.size(), 4 * group.size());
        glm::dvec3 sum(0.0);
        for (std::size_t k = 0; k < group.size(); ++k) {
            glm::vec3 c[4];
            mesh::leafCorners(leaves[group[k]], 0.5f, 1.3f, c);
            for (int j = 0; j < 4; ++j) {
                EXPECT_EQ(in.corners[4 * k + j], c[j]);
                sum += glm::dvec3(c[j]);
            }
        }
        EXPECT_EQ(in.m, sum / static_cast<double>(in.corners.size()));
        EXPECT_EQ(in.cov, glm::transpose(in.cov));
        for (int trial = 0; trial < 4; ++trial) {
            const glm::dvec3 along = glm::normalize(
                glm::dvec3(rng.uniform(-1, 1), rng.uniform(-1, 1), rng.uniform(-1, 1)));
            const glm::dvec3 across = glm::normalize(glm::cross(along, glm::dvec3(0.2, 1, 0.3)));
            double f[4], p[4];
            mesh::cardExtent(in, along, across, f[0], f[1], f[2], f[3]);
            mesh::cardExtentPlain(in, along, across, p[0], p[1], p[2], p[3]);
            for (int j = 0; j < 4; ++j)
                EXPECT_EQ(f[j], p[j]) << size << " " << j;
            EXPECT_LE(f[0], f[1]);
            EXPECT_LE(f[2], f[3]);
        }
    }
}

// The leaves' middles four at a time are the straightforward ones bit for bit, for every
// remainder of four, and so is the sum of their sizes made in the same pass (in leaf order:
// sizes of very different magnitudes, whose sum another order would round differently).
TEST(CardFit, MiddlesMatchTheStraightforwardOnes) {
    Rng rng(4);
    std::vector<skel::Leaf> all = randomLeaves(rng, 40);
    // Sizes a unit apart and halves of a unit's last place: summed in another order (the small
    // ones together first) they round differently.
    for (std::size_t i = 0; i < all.size(); ++i)
        all[i].size =
            i % 3 == 0 ? 1.0f + static_cast<float>(i % 5) : (i % 2 ? 0x1p-53f : 0x1.8p-53f);
    for (double scale : {1.0, 0.37}) {
        for (std::size_t count = 0; count <= all.size(); ++count) {
            const std::vector<skel::Leaf> leaves(all.begin(), all.begin() + count);
            RawVector<glm::dvec3> fast;
            std::vector<glm::dvec3> plain;
            const double fastSum = mesh::leafMiddles(leaves, scale, fast);
            const double plainSum = mesh::leafMiddlesPlain(leaves, scale, plain);
            ASSERT_EQ(fast.size(), count);
            for (std::size_t i = 0; i < count; ++i)
                EXPECT_TRUE(sameBits(fast[i], plain[i])) << count << " " << i;
            EXPECT_EQ(std::memcmp(&fastSum, &plainSum, sizeof fastSum), 0) << count;
        }
    }
}

// The axes of every quaternion whose components are signed zeros, ±1, a value whose squares and
// products are subnormal or vanish, and plain values (not normalised: any finite quaternion):
// the corners, the axes' sums and the middles the straightforward ones' bit for bit, signed
// zeros included (the products by 0 and 1 the SSE2 axes leave out; the +0 they still add, which
// the middles of leaves at -0 show).
TEST(CardFit, AxesOfQuaternionsWithZerosMatchTheStraightforwardOnes) {
    const float values[] = {0.0f, -0.0f, 1.0f, -1.0f, 0.6f, -0.8f, 3e-20f, -1e-25f};
    std::vector<skel::Leaf> leaves;
    for (float x : values)
        for (float y : values)
            for (float z : values)
                for (float w : values) {
                    skel::Leaf leaf;
                    leaf.position =
                        glm::vec3(0.25f * static_cast<float>(leaves.size() % 7), 1.0f, -0.5f);
                    leaf.orientation = glm::quat(w, x, y, z);
                    leaf.size = 0.1f;
                    leaves.push_back(leaf);
                }
    mesh::CardFitInput fast, plain;
    for (std::uint32_t first = 0, size = 1; first < leaves.size();
         first += size, size = size % 7 + 1) {
        std::vector<std::uint32_t> group(std::min<std::size_t>(size, leaves.size() - first));
        std::iota(group.begin(), group.end(), first);
        mesh::prepareCardFit(leaves, group, 0.5f, 1.0f, fast);
        mesh::prepareCardFitPlain(leaves, group, 0.5f, 1.0f, plain);
        for (std::size_t k = 0; k < fast.corners.size(); ++k)
            ASSERT_TRUE(sameBits(fast.corners[k], plain.corners[k])) << first << " " << k;
        ASSERT_TRUE(sameBits(fast.heading, plain.heading)) << first;
        ASSERT_TRUE(sameBits(fast.up, plain.up)) << first;
        ASSERT_TRUE(sameBits(fast.left, plain.left)) << first;
    }
    // The axes alone, one leaf a group.
    for (std::uint32_t i = 0; i < leaves.size(); ++i) {
        const std::uint32_t one[] = {i};
        mesh::prepareCardFit(leaves, one, 0.5f, 1.0f, fast);
        mesh::prepareCardFitPlain(leaves, one, 0.5f, 1.0f, plain);
        ASSERT_TRUE(sameBits(fast.heading, plain.heading)) << i;
        ASSERT_TRUE(sameBits(fast.up, plain.up)) << i;
        ASSERT_TRUE(sameBits(fast.left, plain.left)) << i;
    }
    // The middles at -0 (where a heading's -0 and +0 give middles of different bits).
    for (skel::Leaf& leaf : leaves)
        leaf.position = glm::vec3(-0.0f);
    RawVector<glm::dvec3> fastMids;
    std::vector<glm::dvec3> plainMids;
    mesh::leafMiddles(leaves, 1.0, fastMids);
    mesh::leafMiddlesPlain(leaves, 1.0, plainMids);
    for (std::size_t i = 0; i < leaves.size(); ++i)
        ASSERT_TRUE(sameBits(fastMids[i], plainMids[i])) << i;
}

// Four groups a register (AVX, a group a lane; eight with AVX-512) are the straightforward
// preparation and extent bit for bit in every lane: one to cardFitLanesWidth() groups, of equal and
// unequal sizes (a lane whose group has ended adds nothing), every size 1-23 in some lane, the
// special frames included.
TEST(CardFit, LanesMatchTheStraightforwardOnes) {
    if (!mesh::cardFitLanesAvailable()) GTEST_SKIP() << "no AVX lanes here";
    Rng rng(21);
    const std::vector<skel::Leaf> leaves = randomLeaves(rng, 300);
    mesh::CardFitLanes lanes;
    const std::size_t width = mesh::cardFitLanesWidth();
    ASSERT_TRUE(width == 4 || width == 8);
    std::size_t checked = 0, expected = 0;
    for (int trial = 0; trial < 120; ++trial) {
        const std::size_t n = 1 + static_cast<std::size_t>(trial) % width;
        expected += n;
        std::vector<std::uint32_t> groups[8];
        std::span<const std::uint32_t> spans[8];
        for (std::size_t k = 0; k < n; ++k) {
            const std::size_t size =
                trial % 3 == 0 ? 1 + static_cast<std::size_t>(trial / 3) % 23 : 1 + rng.below(23);
            groups[k].resize(size);
            for (std::uint32_t& i : groups[k])
                i = static_cast<std::uint32_t>(rng.below(leaves.size()));
            if (trial < 4 && k == 0)
                std::iota(groups[k].begin(), groups[k].end(), 0u); // the special frames
            spans[k] = groups[k];
        }
        mesh::CardFitInput fast[8], plain[8];
        mesh::prepareCardFitLanes(leaves, spans, n, 0.45f, 1.7f, fast, lanes);
        glm::dvec3 along[8], across[8];
        for (std::size_t k = 0; k < n; ++k) {
            mesh::prepareCardFitPlain(leaves, spans[k], 0.45f, 1.7f, plain[k]);
            EXPECT_TRUE(sameBits(fast[k].heading, plain[k].heading)) << trial << " " << k;
            EXPECT_TRUE(sameBits(fast[k].up, plain[k].up)) << trial << " " << k;
            EXPECT_TRUE(sameBits(fast[k].left, plain[k].left)) << trial << " " << k;
            EXPECT_TRUE(sameBits(fast[k].m, plain[k].m)) << trial << " " << k;
            EXPECT_TRUE(sameBits(fast[k].cov, plain[k].cov)) << trial << " " << k;
            along[k] = glm::normalize(
                glm::dvec3(rng.uniform(-1, 1), rng.uniform(-1, 1), rng.uniform(-1, 1)));
            across[k] = glm::normalize(glm::cross(along[k], glm::dvec3(0.2, 1, 0.3)));
        }
        double extent[8][4];
        mesh::cardExtentLanes(lanes, plain, along, across, n, extent);
        for (std::size_t k = 0; k < n; ++k) {
            double p[4];
            mesh::cardExtentPlain(plain[k], along[k], across[k], p[0], p[1], p[2], p[3]);
            for (int j = 0; j < 4; ++j)
                EXPECT_TRUE(sameBits(extent[k][j], p[j])) << trial << " " << k << " " << j;
            ++checked;
        }
    }
    EXPECT_EQ(checked, expected);
}

// Eight cards a register (AVX-512): the axes, extent and corners are cardAxes', cardExtentPlain's,
// cardRect's and cardCorners' bit for bit in every lane, for one to eight cards: the leaves'
// mean heading long enough in the plane or not (then +-e1), the normal turned toward the leaves'
// up or not; a lane whose e2 runs along its e1 refuses the register.
TEST(CardFit, FinishLanesMatchTheStraightforwardOnes) {
    if (mesh::cardFitLanesWidth() != 8) GTEST_SKIP() << "no AVX-512 lanes here";
    Rng rng(33);
    const std::vector<skel::Leaf> leaves = randomLeaves(rng, 300);
    mesh::CardFitLanes lanes;
    const auto unit = [&rng] {
        return glm::normalize(
            glm::dvec3(rng.uniform(-1, 1), rng.uniform(-1, 1), rng.uniform(-1, 1)));
    };
    std::size_t checked = 0, refused = 0, flipped = 0, shortHeading = 0;
    for (int trial = 0; trial < 160; ++trial) {
        const std::size_t n = 1 + static_cast<std::size_t>(trial) % 8;
        std::vector<std::uint32_t> groups[8];
        std::span<const std::uint32_t> spans[8];
        for (std::size_t k = 0; k < n; ++k) {
            groups[k].resize(2 + rng.below(14));
            for (std::uint32_t& i : groups[k])
                i = static_cast<std::uint32_t>(rng.below(leaves.size()));
            spans[k] = groups[k];
        }
        mesh::CardFitInput in[8], plain[8];
        mesh::prepareCardFitLanes(leaves, spans, n, 0.45f, 1.7f, in, lanes);
        glm::dvec3 e1[8], e2[8];
        for (std::size_t k = 0; k < n; ++k) {
            // The lanes keep the corners, the plain extent reads them from its input.
            mesh::prepareCardFitPlain(leaves, spans[k], 0.45f, 1.7f, plain[k]);
            e1[k] = unit();
            e2[k] = unit();
            const int kind = static_cast<int>(rng.below(6));
            if (kind == 0) in[k].heading *= 1e-3; // too short in the plane: +-e1
            if (kind == 1) in[k].heading = -e1[k] * 1e-4;
            if (kind == 2) in[k].up = -in[k].up;
            if (kind == 3 && trial % 10 == 0) e2[k] = e1[k] * 2.0; // along e1: refused
            plain[k].heading = in[k].heading;
            plain[k].up = in[k].up;
        }
        glm::vec3 fast[8][5];
        glm::vec3* out[8];
        for (std::size_t k = 0; k < 8; ++k)
            out[k] = fast[k];
        const bool done = mesh::finishCardFitLanes(lanes, in, spans, e1, e2, n, out);
        glm::dvec3 e2Plain[8];
        std::copy(e2, e2 + n, e2Plain);
        mesh::CardAxes axes[8];
        bool along = false;
        for (std::size_t k = 0; k < n; ++k)
            along = along || glm::length(e2[k] - glm::dot(e2[k], e1[k]) * e1[k]) < 1e-9;
        ASSERT_EQ(done, !along) << trial;
        if (!done) {
            ++refused;
            continue;
        }
        mesh::cardAxes(plain, spans, e1, e2Plain, axes, n);
        for (std::size_t k = 0; k < n; ++k) {
            double extent[4];
            mesh::cardExtentPlain(plain[k], axes[k].along, axes[k].across, extent[0], extent[1],
                                  extent[2], extent[3]);
            glm::vec3 corners[4], normal;
            mesh::cardCorners(mesh::cardRect(plain[k], axes[k], extent), axes[k], corners, normal);
            for (int c = 0; c < 4; ++c)
                EXPECT_TRUE(sameBits(fast[k][c], corners[c])) << trial << " " << k << " " << c;
            EXPECT_TRUE(sameBits(fast[k][4], normal)) << trial << " " << k;
            flipped += glm::dot(glm::cross(e1[k], e2Plain[k]), plain[k].up) < 0.0;
            shortHeading += axes[k].along == e1[k] || axes[k].along == -e1[k];
            ++checked;
        }
    }
    EXPECT_GT(refused, 0u);
    EXPECT_GT(flipped, 20u);
    EXPECT_GT(shortHeading, 20u);
    EXPECT_GT(checked, 500u);
}

// The second power iteration's matrix and start eight cards a register (AVX-512) are
// secondMatrix's bit for bit in every lane, for one to eight cards; a lane whose seed vanishes
// (its leaves' left sum along e1) refuses the register.
TEST(CardFit, SecondMatrixLanesMatchTheScalarOne) {
    if (mesh::cardFitLanesWidth() != 8) GTEST_SKIP() << "no AVX-512 lanes here";
    Rng rng(45);
    const std::vector<skel::Leaf> leaves = randomLeaves(rng, 300);
    mesh::CardFitLanes lanes;
    std::size_t checked = 0, refused = 0;
    for (int trial = 0; trial < 160; ++trial) {
        const std::size_t n = 1 + static_cast<std::size_t>(trial) % 8;
        std::vector<std::uint32_t> groups[8];
        std::span<const std::uint32_t> spans[8];
        for (std::size_t k = 0; k < n; ++k) {
            groups[k].resize(2 + rng.below(14));
            for (std::uint32_t& i : groups[k])
                i = static_cast<std::uint32_t>(rng.below(leaves.size()));
            spans[k] = groups[k];
        }
        mesh::CardFitInput in[8];
        mesh::prepareCardFitLanes(leaves, spans, n, 0.45f, 1.7f, in, lanes);
        glm::dvec3 e1[8];
        bool vanishes = false;
        for (std::size_t k = 0; k < n; ++k) {
            e1[k] = glm::normalize(
                glm::dvec3(rng.uniform(-1, 1), rng.uniform(-1, 1), rng.uniform(-1, 1)));
            if (trial % 12 == 5 && k == n - 1) in[k].left = -3.0 * e1[k]; // the seed vanishes
            glm::dvec3 seed;
            (void)mesh::secondMatrix(in[k], e1[k], seed);
            const glm::dvec3 s2 = in[k].left - glm::dot(in[k].left, e1[k]) * e1[k];
            vanishes = vanishes || glm::length(s2) < 1e-9;
        }
        glm::dmat3 rest[8];
        glm::dvec3 seed2[8];
        const bool done = mesh::secondMatrixLanes(in, e1, n, rest, seed2);
        ASSERT_EQ(done, !vanishes) << trial;
        if (!done) {
            ++refused;
            continue;
        }
        for (std::size_t k = 0; k < n; ++k) {
            glm::dvec3 seed;
            const glm::dmat3 plain = mesh::secondMatrix(in[k], e1[k], seed);
            EXPECT_TRUE(sameBits(rest[k], plain)) << trial << " " << k;
            EXPECT_TRUE(sameBits(seed2[k], seed)) << trial << " " << k;
            ++checked;
        }
    }
    EXPECT_GT(refused, 0u);
    EXPECT_GT(checked, 500u);
}
