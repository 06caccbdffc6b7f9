#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <functional>
#include <map>
#include <tuple>
#include <vector>

#include "engine/mesh/cardfit.h"
#include "engine/mesh/leafcell.h"
#include "engine/mesh/leafclusters.h"
#include "engine/util/error.h"
#include "engine/util/random.h"

using namespace sylva;

namespace {

using Groups = std::vector<std::vector<std::uint32_t>>;

// groupLeaves the straightforward way: at each cell size a map from every leaf's cell to its
// group (numbered in the order the cells are first met), the sizes tried as
// appendLeafClusterCards tries them (1.2 x the mean leaf, 8 % larger a step, the 40th taken
// whatever it gives).
Groups plainGroups(const std::vector<skel::Leaf>& leaves, double sizeScale, int perCard) {
    Groups out;
    if (leaves.empty()) return out;
    if (perCard <= 1) {
        for (std::uint32_t i = 0; i < leaves.size(); ++i)
            out.push_back({i});
        return out;
    }
    double mean = 0.0;
    for (const skel::Leaf& leaf : leaves)
        mean += leaf.size * sizeScale;
    mean = std::max(mean / static_cast<double>(leaves.size()), 1e-4);
    std::vector<glm::dvec3> mids;
    mesh::leafMiddlesPlain(leaves, sizeScale, mids);
    const auto limit = static_cast<std::size_t>(
        std::floor(static_cast<double>(leaves.size()) / static_cast<double>(perCard)));
    double cell = 1.2 * mean;
    for (int step = 0;; ++step) {
        std::map<std::tuple<std::int64_t, std::int64_t, std::int64_t>, std::uint32_t> groupOf;
        out.clear();
        for (std::uint32_t i = 0; i < mids.size(); ++i) {
            const mesh::LeafCell c = mesh::leafCellPlain(mids[i], cell);
            const auto [it, added] =
                groupOf.try_emplace({c.x, c.y, c.z}, static_cast<std::uint32_t>(groupOf.size()));
            if (added) out.emplace_back();
            out[it->second].push_back(i);
        }
        if (out.size() <= limit || step == 39) return out;
        cell *= 1.08;
    }
}

// A bush of \p clumps clumps of leaves (turned every way, sizes 0.02-0.3 m) round random
// centres, \p spread metres across.
std::vector<skel::Leaf> bush(std::uint64_t seed, int count, int clumps, double spread) {
    Rng rng(seed);
    std::vector<glm::vec3> centres;
    for (int c = 0; c < clumps; ++c)
        centres.emplace_back(rng.uniformf(-1, 1), rng.uniformf(-1, 1), rng.uniformf(-1, 1));
    std::vector<skel::Leaf> leaves(static_cast<std::size_t>(count));
    for (skel::Leaf& l : leaves) {
        const glm::vec3 offset(rng.uniformf(-0.3f, 0.3f), rng.uniformf(-0.3f, 0.3f),
                               rng.uniformf(-0.3f, 0.3f));
        l.position = static_cast<float>(spread) * (centres[rng.below(centres.size())] + offset);
        l.orientation = glm::normalize(glm::quat(rng.uniformf(-1, 1), rng.uniformf(-1, 1),
                                                 rng.uniformf(-1, 1), rng.uniformf(-1, 1)));
        l.size = rng.uniformf(0.02f, 0.3f);
        l.node = static_cast<int>(rng.below(100));
    }
    return leaves;
}

} // namespace

// The cell table (open addressing, its first probe and the new-cell writes without a branch)
// gives the groups of a map of cells: bushes dense and sparse (many cells to a table, probes
// past a neighbour's slot), every cluster size, a bush whose leaves are too far apart for any
// of the 39 sizes (the 40th taken), leaves all in one cell, one leaf.
TEST(LeafGroups, SameAsAMapOfCells) {
    std::size_t compared = 0;
    for (std::uint64_t seed = 1; seed <= 6; ++seed)
        for (int perCard : {0, 1, 2, 3, 4, 6, 9, 16, 64}) {
            const double spread = seed % 2 ? 3.0 : 12.0;
            const std::vector<skel::Leaf> leaves = bush(seed, 500 + 700 * static_cast<int>(seed),
                                                        3 + 5 * static_cast<int>(seed), spread);
            for (double scale : {1.0, 0.37}) {
                EXPECT_EQ(mesh::groupLeaves(leaves, scale, perCard),
                          plainGroups(leaves, scale, perCard))
                    << seed << " " << perCard << " " << scale;
                ++compared;
            }
        }
    std::vector<skel::Leaf> far = bush(9, 300, 300, 1e5);
    EXPECT_EQ(mesh::groupLeaves(far, 1.0, 4), plainGroups(far, 1.0, 4));
    std::vector<skel::Leaf> together(50);
    for (skel::Leaf& l : together)
        l.size = 0.1f;
    EXPECT_EQ(mesh::groupLeaves(together, 1.0, 4), plainGroups(together, 1.0, 4));
    EXPECT_EQ(mesh::groupLeaves(std::vector<skel::Leaf>(1), 1.0, 4),
              plainGroups(std::vector<skel::Leaf>(1), 1.0, 4));
    EXPECT_EQ(compared, 108u);
}

// The first cell size is ruled out by a bound on its cells' count (distinct hash bits), not by a
// fill: leaves two to a cell along a line, as many cells at the first size as the limit allows
// (taken there: a bound that overcounts would go on to the next size) and one more (the next
// size taken: one that undercounts, or compares with the limit one off, would stop there). The
// small counts' cells mostly have a hash bit each, so a bound one off reaches the limit there.
TEST(LeafGroups, FirstSizeRuledOutOnlyPastTheLimit) {
    for (const int n : {8, 9, 12, 20, 21, 40, 200, 201, 202, 4000, 4002}) {
        std::vector<skel::Leaf> leaves(static_cast<std::size_t>(n));
        for (int i = 0; i < n; ++i) {
            // Middles at x = 0.03 + 0.06 i: two a cell of 1.2 x the mean size 0.1 (0.12).
            leaves[static_cast<std::size_t>(i)].position =
                glm::vec3(0.03f + 0.06f * static_cast<float>(i), -0.05f, 0.0f);
            leaves[static_cast<std::size_t>(i)].size = 0.1f;
        }
        const Groups groups = mesh::groupLeaves(leaves, 1.0, 2);
        EXPECT_EQ(groups, plainGroups(leaves, 1.0, 2)) << n;
        // n / 2 groups (rounded up) at the first size: taken where that is the limit (n even).
        const bool firstSize = n % 2 == 0;
        EXPECT_EQ(groups.size() == static_cast<std::size_t>((n + 1) / 2), firstSize) << n;
    }
}

// A plan's cards (planLeafClusterCards, then appendLeafClusterCards with it, after a bark made
// with room for them) are the cards of one call into an empty mesh, placed after what the mesh
// held: that untouched, the cards' indices past it, the wind, node and colour attributes
// extended with the cards' values; crossed cards, and cards an accept callback refuses (their
// leaves' own cards instead). A plan made for other leaves or settings is refused.
TEST(LeafClusterPlan, CardsAfterTheBarkAreTheCardsOfAnEmptyMesh) {
    const std::vector<skel::Leaf> leaves = bush(4, 900, 9, 3.0);
    mesh::LeafCardSettings cards;
    cards.aspect = 0.45;
    cards.sizeScale = 1.3;
    // Some bark: vertices with every attribute, a bark submesh.
    mesh::Mesh bark;
    for (int i = 0; i < 37; ++i) {
        bark.positions.emplace_back(0.1f * static_cast<float>(i), 1.0f, -2.0f);
        bark.normals.emplace_back(1.0f, 0.0f, 0.0f);
        bark.uvs.emplace_back(0.5f, 0.01f * static_cast<float>(i));
        bark.branchOrder.push_back(static_cast<std::uint16_t>(i % 3));
        bark.flexibility.push_back(0.25f);
        bark.node.push_back(static_cast<std::uint32_t>(i));
        bark.colors.emplace_back(10, 20, 30, 255);
    }
    for (std::uint32_t i = 0; i + 2 < 37; ++i)
        bark.indices.insert(bark.indices.end(), {i, i + 1, i + 2});
    bark.submeshes.push_back({"bark", 0, static_cast<std::uint32_t>(bark.indices.size())});
    const auto refuse = [](const skel::Leaf& card) { return card.position.x < 0.0f; };
    for (const bool crossed : {false, true})
        for (const bool withAccept : {false, true}) {
            mesh::LeafClusterSettings cs;
            cs.leavesPerCard = 5;
            cs.seed = 21;
            cs.crossed = crossed;
            const std::function<bool(const skel::Leaf&)> accept =
                withAccept ? std::function<bool(const skel::Leaf&)>(refuse) : nullptr;
            mesh::Mesh alone;
            const std::size_t made =
                mesh::appendLeafClusterCards(alone, leaves, cards, cs, nullptr, accept);
            const mesh::LeafClusterPlan plan =
                mesh::planLeafClusterCards(leaves, cards, cs, accept);
            ASSERT_EQ(plan.cards(), made);
            if (withAccept) { // some cards refused: more, single leaves' ones
                EXPECT_GT(made, mesh::planLeafClusterCards(leaves, cards, cs).cards());
            }
            mesh::Mesh m = bark;
            m.positions.reserve(m.positions.size() + 4 * plan.cards());
            m.indices.reserve(m.indices.size() + 6 * plan.cards());
            ASSERT_EQ(mesh::appendLeafClusterCards(m, leaves, cs, nullptr, plan), made);
            const std::size_t n = bark.positions.size(), ni = bark.indices.size();
            ASSERT_EQ(m.positions.size(), n + 4 * made);
            ASSERT_EQ(m.indices.size(), ni + 6 * made);
            EXPECT_TRUE(
                std::equal(bark.positions.begin(), bark.positions.end(), m.positions.begin()));
            EXPECT_TRUE(std::equal(alone.positions.begin(), alone.positions.end(),
                                   m.positions.begin() + static_cast<std::ptrdiff_t>(n)));
            EXPECT_TRUE(std::equal(bark.normals.begin(), bark.normals.end(), m.normals.begin()));
            EXPECT_TRUE(std::equal(alone.normals.begin(), alone.normals.end(),
                                   m.normals.begin() + static_cast<std::ptrdiff_t>(n)));
            EXPECT_TRUE(std::equal(bark.uvs.begin(), bark.uvs.end(), m.uvs.begin()));
            EXPECT_TRUE(std::equal(alone.uvs.begin(), alone.uvs.end(),
                                   m.uvs.begin() + static_cast<std::ptrdiff_t>(n)));
            EXPECT_TRUE(std::equal(bark.indices.begin(), bark.indices.end(), m.indices.begin()));
            for (std::size_t k = 0; k < alone.indices.size(); ++k)
                ASSERT_EQ(m.indices[ni + k], alone.indices[k] + n) << k;
            // A card's vertices carry its first leaf's node (the groups' order where no card is
            // refused or crossed), order 0 (no skeleton), flexibility 1, white.
            const auto groups = mesh::groupLeaves(leaves, cards.sizeScale, cs.leavesPerCard);
            for (std::size_t k = n; k < m.positions.size(); ++k) {
                const std::size_t card = (k - n) / 4;
                if (!crossed && !withAccept) {
                    ASSERT_EQ(m.node[k], static_cast<std::uint32_t>(leaves[groups[card][0]].node))
                        << k;
                }
                ASSERT_EQ(m.node[k], m.node[n + 4 * card]) << k;
                ASSERT_EQ(m.branchOrder[k], 0u) << k;
                ASSERT_EQ(m.flexibility[k], 1.0f) << k;
                ASSERT_EQ(m.colors[k], glm::u8vec4(255)) << k;
            }
            ASSERT_EQ(m.submeshes.size(), 2u);
            EXPECT_EQ(m.submeshes[1].material, "leaf");
            EXPECT_EQ(m.submeshes[1].firstIndex, ni);
            EXPECT_EQ(m.submeshes[1].indexCount, 6 * made);
            mesh::LeafClusterSettings other = cs;
            other.crossed = !crossed;
            EXPECT_THROW(mesh::appendLeafClusterCards(m, leaves, other, nullptr, plan),
                         InvalidInput);
            const std::vector<skel::Leaf> fewer(leaves.begin(), leaves.end() - 1);
            EXPECT_THROW(mesh::appendLeafClusterCards(m, fewer, cs, nullptr, plan), InvalidInput);
        }
}
