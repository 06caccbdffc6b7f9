#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <unordered_map>

#include "engine/mesh/leaflight.h"
#include "engine/util/random.h"

using namespace sylva;

namespace {

// leafCardLight as it was before its dense grid of cells (the cells in a hash map by the same
// 21-bit keys, each card's 27 cells looked up one by one, only the found ones added): the
// reference the grid must match bit for bit.
std::uint64_t referenceKey(int x, int y, int z) {
    auto u = [](int v) {
        return static_cast<std::uint64_t>(static_cast<std::uint32_t>(v) & 0x1fffff);
    };
    return (u(x) << 42) | (u(y) << 21) | u(z);
}

glm::ivec3 referenceCell(const glm::dvec3& p) {
    const glm::dvec3 q = glm::floor(p / 0.5);
    return {static_cast<int>(q.x), static_cast<int>(q.y), static_cast<int>(q.z)};
}

std::vector<float> referenceLight(const mesh::Mesh& mesh, std::size_t firstVertex,
                                  const std::vector<skel::Leaf>& leaves, const skel::Skeleton& s) {
    const std::size_t n = s.size();
    if (n == 0 || s.light.size() != n || firstVertex >= mesh.positions.size()) return {};
    std::vector<double> children(n, 0.0), tips(n, 0.0);
    std::vector<char> hasChild(n, 0);
    for (std::size_t i = 0; i < n; ++i)
        if (s.parent[i] >= 0) hasChild[static_cast<std::size_t>(s.parent[i])] = 1;
    for (std::size_t i = n; i-- > 0;) {
        if (!hasChild[i]) tips[i] += 1.0;
        if (s.parent[i] < 0) continue;
        const auto p = static_cast<std::size_t>(s.parent[i]);
        tips[p] += tips[i];
        children[p] += s.light[i];
    }
    std::vector<float> perTip(n);
    for (std::size_t i = 0; i < n; ++i) {
        const double own = s.light[i] - children[i];
        perTip[i] = static_cast<float>(own > 1e-4 * std::max(1.0, static_cast<double>(s.light[i]))
                                           ? own
                                           : s.light[i] / std::max(tips[i], 1.0));
    }
    struct Sum {
        double light = 0.0, count = 0.0;
    };
    std::unordered_map<std::uint64_t, Sum> cells;
    Sum all;
    for (const skel::Leaf& leaf : leaves) {
        if (leaf.node < 0 || static_cast<std::size_t>(leaf.node) >= n) continue;
        const double l = perTip[static_cast<std::size_t>(leaf.node)];
        const glm::ivec3 c = referenceCell(glm::dvec3(leaf.position));
        Sum& sum = cells[referenceKey(c.x, c.y, c.z)];
        sum.light += l;
        sum.count += 1.0;
        all.light += l;
        all.count += 1.0;
    }
    if (all.count == 0.0) return {};
    const std::size_t vertices = mesh.positions.size() - firstVertex;
    std::vector<float> light((vertices + 3) / 4);
    for (std::size_t card = 0; card < light.size(); ++card) {
        const std::size_t v = firstVertex + 4 * card;
        const std::size_t end = std::min(mesh.positions.size(), v + 4);
        glm::dvec3 centre(0.0);
        for (std::size_t k = v; k < end; ++k)
            centre += glm::dvec3(mesh.positions[k]);
        centre /= static_cast<double>(end - v);
        const glm::ivec3 c = referenceCell(centre);
        Sum sum;
        if (auto it = cells.find(referenceKey(c.x, c.y, c.z)); it != cells.end()) sum = it->second;
        if (sum.count == 0.0)
            for (int dx = -1; dx <= 1; ++dx)
                for (int dy = -1; dy <= 1; ++dy)
                    for (int dz = -1; dz <= 1; ++dz)
                        if (auto it = cells.find(referenceKey(c.x + dx, c.y + dy, c.z + dz));
                            it != cells.end()) {
                            sum.light += it->second.light;
                            sum.count += it->second.count;
                        }
        if (sum.count == 0.0) sum = all;
        light[card] = static_cast<float>(sum.light / sum.count);
    }
    std::vector<float> sorted = light;
    const auto mid = sorted.begin() + static_cast<std::ptrdiff_t>(sorted.size() / 2);
    std::nth_element(sorted.begin(), mid, sorted.end());
    const float hi = *mid;
    const auto low = sorted.begin() + static_cast<std::ptrdiff_t>(sorted.size() / 20);
    std::nth_element(sorted.begin(), low, mid);
    const float lo = *low;
    const float span = hi - lo;
    for (float& l : light)
        l = span > 1e-9f ? std::clamp((l - lo) / span, 0.0f, 1.0f) : 1.0f;
    return light;
}

// A random tree of \p nodes with light records, \p leafCount leaves spread over \p spread
// metres around \p at (a few on no node), and a card of four corners around most leaves (some
// moved a cell or two away, so that their own cell is empty; a few far from every leaf).
struct Scene {
    skel::Skeleton skeleton;
    std::vector<skel::Leaf> leaves;
    mesh::Mesh mesh;
};

Scene makeScene(std::uint64_t seed, std::size_t nodes, std::size_t leafCount, float spread,
                glm::vec3 at) {
    Scene sc;
    Rng rng(seed);
    for (std::size_t i = 0; i < nodes; ++i) {
        const auto parent = i == 0 ? -1 : static_cast<std::int32_t>(rng.below(i));
        sc.skeleton.addNode(glm::vec3(0.0f, static_cast<float>(i), 0.0f), parent, 0.01f, 0,
                            glm::quat(1, 0, 0, 0));
    }
    sc.skeleton.light.resize(nodes);
    for (std::size_t i = 0; i < nodes; ++i)
        sc.skeleton.light[i] = rng.uniformf(0.0f, 3.0f);
    for (std::size_t i = 0; i < leafCount; ++i) {
        skel::Leaf leaf;
        leaf.position = at + glm::vec3(rng.uniformf(-spread, spread), rng.uniformf(-spread, spread),
                                       rng.uniformf(-spread, spread));
        // Some on a cell's boundary or a hair either side of it (the cells' floors), -0 and
        // subnormal coordinates included.
        for (int a = 0; a < 3; ++a)
            switch (rng.below(12)) {
            case 0:
                leaf.position[a] = std::round(leaf.position[a] * 2.0f) * 0.5f;
                break;
            case 1:
                leaf.position[a] =
                    std::nextafter(std::round(leaf.position[a] * 2.0f) * 0.5f, -1e9f);
                break;
            case 2:
                leaf.position[a] = std::nextafter(std::round(leaf.position[a] * 2.0f) * 0.5f, 1e9f);
                break;
            case 3:
                leaf.position[a] = rng.below(2) ? -0.0f : -1e-40f;
                break;
            default:
                break;
            }
        leaf.node = rng.below(40) == 0 ? -1 : static_cast<std::int32_t>(rng.below(nodes));
        sc.leaves.push_back(leaf);
        glm::vec3 centre = leaf.position;
        if (rng.below(4) == 0)
            centre += glm::vec3(rng.uniformf(-1.2f, 1.2f), rng.uniformf(-1.2f, 1.2f),
                                rng.uniformf(-1.2f, 1.2f));
        if (rng.below(50) == 0) centre += glm::vec3(40.0f, 0.0f, 0.0f);
        if (rng.below(6) == 0) {
            // A card centred on a cell's corner (its corners' mean exactly there), or a hair
            // off it.
            const glm::vec3 corner = glm::round(centre * 2.0f) * 0.5f;
            const float hair = rng.below(2) ? 0.0f : 1e-6f;
            for (const glm::vec3 d :
                 {glm::vec3(0.125f, -0.25f, 0.125f), glm::vec3(-0.125f, 0.25f, -0.125f),
                  glm::vec3(0.25f, 0.125f, -0.25f), glm::vec3(-0.25f, -0.125f, 0.25f + hair)})
                sc.mesh.positions.push_back(corner + d);
            continue;
        }
        for (int k = 0; k < 4; ++k)
            sc.mesh.positions.push_back(centre + glm::vec3(rng.uniformf(-0.1f, 0.1f),
                                                           rng.uniformf(-0.1f, 0.1f),
                                                           rng.uniformf(-0.1f, 0.1f)));
    }
    return sc;
}

void expectSameBits(const std::vector<float>& a, const std::vector<float>& b) {
    ASSERT_EQ(a.size(), b.size());
    for (std::size_t i = 0; i < a.size(); ++i) {
        std::uint32_t x = 0, y = 0;
        std::memcpy(&x, &a[i], 4);
        std::memcpy(&y, &b[i], 4);
        ASSERT_EQ(x, y) << "card " << i;
    }
}

} // namespace

TEST(LeafCardLight, DenseGridMatchesTheHashedCells) {
    for (std::uint64_t seed = 1; seed <= 6; ++seed) {
        // A crown's spread (the dense grid), and off the origin on the negative side.
        const Scene sc = makeScene(seed, 300, 3000, 4.0f, glm::vec3(-3.3f, 5.0f, 1.7f));
        const std::vector<float> got = mesh::leafCardLight(sc.mesh, 0, sc.leaves, sc.skeleton);
        ASSERT_FALSE(got.empty());
        expectSameBits(got, referenceLight(sc.mesh, 0, sc.leaves, sc.skeleton));
        // From a later vertex, with a last card of two corners.
        mesh::Mesh cut = sc.mesh;
        cut.positions.resize(cut.positions.size() - 2);
        expectSameBits(mesh::leafCardLight(cut, 8, sc.leaves, sc.skeleton),
                       referenceLight(cut, 8, sc.leaves, sc.skeleton));
    }
}

TEST(LeafCardLight, FlatGridWiderThanPackedSlotsMatchesTheHashedCells) {
    // A grid two cells thick and ~200 cells square: still dense (10,000 leaves), but its x
    // stride (~40,000 cells) is past the packed slots' 15 bits: the slots made from the three
    // ints.
    Scene sc = makeScene(10, 300, 10000, 4.0f, glm::vec3(0.0f));
    for (skel::Leaf& leaf : sc.leaves) {
        leaf.position.x = leaf.position.x < 0.0f ? 0.2f : 0.7f;
        leaf.position.y *= 12.5f;
        leaf.position.z *= 12.5f;
    }
    for (glm::vec3& p : sc.mesh.positions) {
        p.y *= 12.5f;
        p.z *= 12.5f;
    }
    expectSameBits(mesh::leafCardLight(sc.mesh, 0, sc.leaves, sc.skeleton),
                   referenceLight(sc.mesh, 0, sc.leaves, sc.skeleton));
}

TEST(LeafCardLight, SparseLeavesAndFarCellsMatchTheHashedCells) {
    // Two clumps far apart: the box of cells is too large for a grid (the hashed cells).
    Scene sc = makeScene(7, 50, 400, 1.0f, glm::vec3(0.0f));
    const Scene far = makeScene(8, 50, 400, 1.0f, glm::vec3(9000.0f, -300.0f, 20.0f));
    for (skel::Leaf leaf : far.leaves)
        sc.leaves.push_back(leaf);
    sc.mesh.positions.insert(sc.mesh.positions.end(), far.mesh.positions.begin(),
                             far.mesh.positions.end());
    expectSameBits(mesh::leafCardLight(sc.mesh, 0, sc.leaves, sc.skeleton),
                   referenceLight(sc.mesh, 0, sc.leaves, sc.skeleton));
    // A grid, and cards 2^21 cells (1,048,576 m) off it: cellKey's 21 bits meet the leaves'
    // cells there, and the grid must find them as the hashed cells did.
    Scene one = makeScene(9, 50, 300, 1.0f, glm::vec3(0.5f, 0.0f, -0.5f));
    for (std::size_t v = 0; v < 64; ++v)
        one.mesh.positions[v].x += 1048576.0f;
    one.mesh.positions[64].z -= 1048576.0f;
    const std::vector<float> got = mesh::leafCardLight(one.mesh, 0, one.leaves, one.skeleton);
    expectSameBits(got, referenceLight(one.mesh, 0, one.leaves, one.skeleton));
}

TEST(LeafCardLight, PositionsBoxGivesTheCellsBox) {
    // leafCellBox (the positions' box, then its floors) against leafCellBoxOfCells (every leaf's
    // cell): the same box and count, with leaves on cell borders (exact half metres and a float
    // either side), on both sides of zero, on no node, NaN and far (past 2^30 cells) coordinates.
    const float nan = std::numeric_limits<float>::quiet_NaN();
    auto check = [](const std::vector<skel::Leaf>& leaves, std::size_t n, const char* what) {
        glm::ivec3 lo(1), hi(2), refLo(3), refHi(4);
        const std::size_t count = mesh::leafCellBox(leaves, n, lo, hi);
        const std::size_t refCount = mesh::leafCellBoxOfCells(leaves, n, refLo, refHi);
        EXPECT_EQ(count, refCount) << what;
        for (int a = 0; a < 3; ++a) {
            EXPECT_EQ(lo[a], refLo[a]) << what << " axis " << a;
            EXPECT_EQ(hi[a], refHi[a]) << what << " axis " << a;
        }
    };
    Rng rng(41);
    const std::size_t n = 20;
    auto coordinate = [&](float reach) {
        float v = std::round(rng.uniformf(-reach, reach) * 2.0f) * 0.5f; // a cell border
        switch (rng.below(4)) {
        case 0:
            return v;
        case 1:
            return std::nextafter(v, -1e30f);
        case 2:
            return std::nextafter(v, 1e30f);
        default:
            return rng.uniformf(-reach, reach);
        }
    };
    for (std::size_t size = 0; size <= 41; ++size)
        for (int round = 0; round < 20; ++round) {
            const float reach = round % 2 == 0 ? 3.0f : 40000.0f;
            std::vector<skel::Leaf> leaves(size);
            for (skel::Leaf& leaf : leaves) {
                leaf.position = {coordinate(reach), coordinate(reach), coordinate(reach)};
                leaf.node = static_cast<std::int32_t>(rng.below(n + 4)) - 2; // some on no node
            }
            check(leaves, n, "borders");
            if (size == 0) continue;
            // One far or NaN coordinate, counted or not.
            std::vector<skel::Leaf> odd = leaves;
            skel::Leaf& leaf = odd[rng.below(size)];
            const float far[] = {nan, 3e9f, -3e9f, 1e30f, -1e30f, 5.4e8f, -5.4e8f};
            leaf.position[static_cast<int>(rng.below(3))] = far[rng.below(7)];
            check(odd, n, "far or NaN");
            leaf.node = 0;
            check(odd, n, "far or NaN, counted");
        }
}
