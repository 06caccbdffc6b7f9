#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "engine/lsystem/turtle.h"
#include "engine/mesh/leafplacement.h"
#include "engine/mesh/lod.h"
#include "engine/util/error.h"
#include "testwords.h"

using namespace sylva;

namespace {

skel::Skeleton leafyTree() {
    lsys::TurtleSettings t;
    t.angleDegrees = 30;
    t.step = 0.5;
    t.width = 0.3;
    skel::Skeleton s =
        lsys::interpret(sylva::testing::makeWord(sylva::testing::testTreeWord(5)), t);
    mesh::LeafPlacement p;
    p.maxBranchRadius = 0.05;
    s.leaves = mesh::placeLeaves(s, p);
    return s;
}

double submeshArea(const mesh::Mesh& m, const std::string& material) {
    double area = 0.0;
    for (const mesh::Submesh& sm : m.submeshes) {
        if (sm.material != material) continue;
        for (std::uint32_t i = sm.firstIndex; i < sm.firstIndex + sm.indexCount; i += 3) {
            const glm::vec3 a = m.positions[m.indices[i]], b = m.positions[m.indices[i + 1]],
                            c = m.positions[m.indices[i + 2]];
            area += 0.5 * glm::length(glm::cross(b - a, c - a));
        }
    }
    return area;
}

} // namespace

TEST(Lod, SelectsBandsAndTwigRadius) {
    mesh::LodSettings lod;
    lod.bands = {{0, 8, 1.0}, {10, 5, 0.5}, {40, 3, 0.2}};
    lod.screenHeightPx = 1000;
    lod.fovYDegrees = 90;
    lod.minTwigPixels = 2;
    EXPECT_EQ(mesh::selectLod(lod, 0).resolution, 8);
    EXPECT_EQ(mesh::selectLod(lod, 9.99).resolution, 8);
    EXPECT_EQ(mesh::selectLod(lod, 9.99).minBranchRadius, 0.0);
    const mesh::LodLevel mid = mesh::selectLod(lod, 20);
    EXPECT_EQ(mid.band, 1u);
    EXPECT_EQ(mid.resolution, 5);
    EXPECT_DOUBLE_EQ(mid.leafFraction, 0.5);
    // 2 px of 1000 at 20 m with tan(45°) = 1: diameter 2 * 20 / 1000 * 2 / 2 -> radius 0.04.
    EXPECT_NEAR(mid.minBranchRadius, 0.04, 1e-12);
    EXPECT_EQ(mesh::selectLod(lod, 1e6).resolution, 3);
}

TEST(Lod, RejectsBadBands) {
    mesh::LodSettings lod;
    lod.bands = {{5, 8, 1.0}};
    EXPECT_THROW(mesh::validateLod(lod), InvalidInput);
    lod.bands = {{0, 8, 1.0}, {0, 5, 1.0}};
    EXPECT_THROW(mesh::validateLod(lod), InvalidInput);
    lod.bands = {{0, 80, 1.0}};
    EXPECT_THROW(mesh::validateLod(lod), InvalidInput);
    lod.bands = {};
    EXPECT_THROW(mesh::validateLod(lod), InvalidInput);
}

TEST(Lod, ThinningConservesLeafArea) {
    std::vector<skel::Leaf> leaves(1000);
    for (std::size_t i = 0; i < leaves.size(); ++i)
        leaves[i].size = 0.05f + 0.0001f * i;
    double total = 0.0;
    for (const auto& l : leaves)
        total += l.size * l.size;
    for (double f : {0.9, 0.5, 0.1, 0.001}) {
        const auto kept = mesh::thinLeaves(leaves, f, 3);
        ASSERT_FALSE(kept.empty());
        EXPECT_LT(kept.size(), leaves.size());
        double area = 0.0;
        for (const auto& l : kept)
            area += l.size * l.size;
        EXPECT_NEAR(area / total, 1.0, 1e-4);
        if (f >= 0.1) {
            EXPECT_NEAR(static_cast<double>(kept.size()) / 1000.0, f, 0.06);
        }
    }
    EXPECT_EQ(mesh::thinLeaves(leaves, 1.0, 3).size(), leaves.size());
}

TEST(Lod, ChainDecreasesAndKeepsLeafArea) {
    const skel::Skeleton s = leafyTree();
    ASSERT_GT(s.leaves.size(), 100u);
    mesh::TreeMeshSettings settings;
    settings.lod.bands = {{0, 8, 1.0}, {20, 6, 0.6}, {50, 4, 0.35}, {120, 3, 0.15}};
    const auto chain = mesh::buildLodChain(s, settings);
    ASSERT_EQ(chain.size(), 4u);
    const double leafArea0 = submeshArea(chain[0].mesh, "leaf");
    ASSERT_GT(leafArea0, 0.0);
    for (std::size_t i = 1; i < chain.size(); ++i) {
        EXPECT_LT(chain[i].mesh.triangleCount(), chain[i - 1].mesh.triangleCount()) << i;
        EXPECT_NEAR(submeshArea(chain[i].mesh, "leaf") / leafArea0, 1.0, 0.05) << i;
    }
    // The far level drops twigs: fewer bark triangles than resolution alone would give.
    mesh::TreeMeshSettings plain = settings;
    plain.tubes.resolution = 3;
    plain.leaves = false;
    EXPECT_LT(submeshArea(chain[3].mesh, "bark"),
              submeshArea(mesh::buildTreeMesh(s, plain), "bark"));
}
