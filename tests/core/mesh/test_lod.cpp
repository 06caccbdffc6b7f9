#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "../common/testtrees.h"
#include "engine/mesh/treemesh.h"
#include "engine/util/error.h"

using namespace sylva;

namespace {

using sylva::testing::leafyTree;

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

TEST(Lod, SelectsBandsAndPixelThresholds) {
    mesh::LodSettings lod;
    lod.bands = {{0, 8, 1.0}, {10, 5, 0.5}, {40, 3, 0.2}};
    lod.screenHeightPx = 1000;
    lod.fovYDegrees = 90;
    lod.minTwigPixels = 2;
    EXPECT_EQ(mesh::selectLod(lod, 0).resolution, 8);
    EXPECT_EQ(mesh::selectLod(lod, 9.99).resolution, 8);
    EXPECT_EQ(mesh::selectLod(lod, 9.99).minSubtreeExtent, 0.0);
    EXPECT_EQ(mesh::selectLod(lod, 9.99).leafCell, 0.0);
    const mesh::LodLevel mid = mesh::selectLod(lod, 20);
    EXPECT_EQ(mid.band, 1u);
    EXPECT_EQ(mid.resolution, 5);
    EXPECT_DOUBLE_EQ(mid.leafFraction, 0.5);
    // A pixel of 1000 at 20 m with tan(45°) = 1 is 2 · 20 / 1000 = 0.04 m.
    EXPECT_NEAR(mid.metresPerPixel, 0.04, 1e-12);
    EXPECT_NEAR(mid.minSubtreeExtent, 2 * 0.04, 1e-12);
    EXPECT_NEAR(mid.simplifyTolerance, lod.simplifyPixels * 0.04, 1e-12);
    EXPECT_NEAR(mid.leafCell, lod.leafClusterPixels * 0.04, 1e-12);
    EXPECT_NEAR(mid.ribbonRadius, 0.5 * lod.ribbonPixels * 0.04, 1e-12);
    EXPECT_EQ(mesh::selectLod(lod, 1e6).resolution, 3);
}

TEST(Lod, DropsASubtreeByItsWholeSizeNotItsTwigs) {
    // A trunk with two laterals of equally thin twigs (radius 1 mm): one a single 5 cm twig,
    // the other a 2 m branch of such twigs. With a 0.5 m threshold only the short one goes,
    // with its leaf; a radius test would have dropped both.
    skel::Skeleton s;
    const glm::quat up(1, 0, 0, 0);
    s.addNode({0, 0, 0}, -1, 0.2f, 0, up);
    s.addNode({0, 2, 0}, 0, 0.15f, 0, up);
    s.addNode({0, 4, 0}, 1, 0.1f, 0, up);
    const std::int32_t shortTwig = s.addNode({0.05f, 2, 0}, 1, 0.001f, 1, up);
    std::int32_t last = 2;
    std::int32_t firstLong = -1;
    for (int i = 1; i <= 20; ++i) {
        last = s.addNode({0.1f * static_cast<float>(i), 4, 0}, last, 0.001f, 1, up);
        if (firstLong < 0) firstLong = last;
    }
    s.leaves.push_back({s.position[static_cast<std::size_t>(shortTwig)], up, 0.01f, shortTwig});
    s.leaves.push_back({s.position[static_cast<std::size_t>(last)], up, 0.01f, last});
    s.finalize();
    const skel::Skeleton kept = mesh::dropSmallSubtrees(s, 0.5);
    EXPECT_TRUE(kept.flags[static_cast<std::size_t>(shortTwig)] & skel::kHidden);
    EXPECT_FALSE(kept.flags[static_cast<std::size_t>(firstLong)] & skel::kHidden);
    EXPECT_FALSE(kept.flags[static_cast<std::size_t>(last)] & skel::kHidden);
    ASSERT_EQ(kept.leaves.size(), 1u);
    EXPECT_EQ(kept.leaves[0].node, last);
    // The tube mesher's own radius rule drops both.
    mesh::TubeSettings radiusRule;
    radiusRule.minBranchRadius = 0.01;
    radiusRule.caps = false;
    EXPECT_EQ(mesh::buildTubeMesh(s, radiusRule).vertexCount(), 3u * 9u);
    EXPECT_GT(mesh::buildTubeMesh(kept, radiusRule).vertexCount(), 0u);
    // Nothing is dropped without a threshold.
    EXPECT_EQ(mesh::dropSmallSubtrees(s, 0.0).leaves.size(), 2u);
    // A leafy subtree under the leafy threshold loses its bark but keeps its leaf; one without
    // leaves is only dropped by the first threshold.
    skel::Skeleton bare = s;
    bare.leaves.pop_back(); // the long branch has no leaf now
    const skel::Skeleton leafy = mesh::dropSmallSubtrees(bare, 0.01, 1.0, 5.0);
    EXPECT_TRUE(leafy.flags[static_cast<std::size_t>(shortTwig)] & skel::kHidden);
    EXPECT_FALSE(leafy.flags[static_cast<std::size_t>(last)] & skel::kHidden);
    ASSERT_EQ(leafy.leaves.size(), 1u);
    EXPECT_EQ(leafy.leaves[0].node, shortTwig);
}

TEST(Lod, LeafClustersKeepAreaAndStayPut) {
    const skel::Skeleton s = leafyTree();
    ASSERT_GT(s.leaves.size(), 100u);
    double area = 0.0;
    for (const skel::Leaf& l : s.leaves)
        area += static_cast<double>(l.size) * l.size;
    for (double cell : {0.05, 0.2, 1.0}) {
        const std::vector<skel::Leaf> c = mesh::clusterLeaves(s.leaves, cell);
        EXPECT_LT(c.size(), s.leaves.size()) << cell;
        double a = 0.0;
        for (const skel::Leaf& l : c)
            a += static_cast<double>(l.size) * l.size;
        EXPECT_NEAR(a / area, 1.0, 1e-4) << cell;
        // Every cluster's card centre lies in the cube its leaves came from: within one cell
        // diagonal of some original card centre.
        const auto centre = [](const skel::Leaf& l) {
            return l.position + skel::headingOf(l.orientation) * (0.5f * l.size);
        };
        for (const skel::Leaf& l : c) {
            float best = 1e30f;
            for (const skel::Leaf& o : s.leaves)
                best = std::min(best, glm::length(centre(l) - centre(o)));
            EXPECT_LE(best, static_cast<float>(cell) * 1.7321f + 1e-5f);
        }
        // Deterministic.
        const std::vector<skel::Leaf> again = mesh::clusterLeaves(s.leaves, cell);
        ASSERT_EQ(again.size(), c.size());
        for (std::size_t i = 0; i < c.size(); ++i)
            EXPECT_EQ(again[i].position, c[i].position);
    }
    EXPECT_EQ(mesh::clusterLeaves(s.leaves, 0.0).size(), s.leaves.size());
    // A refused cluster card leaves its leaves as they were (a forest refuses cards that would
    // reach into an obstacle).
    const auto none = [](const skel::Leaf&) { return false; };
    const std::vector<skel::Leaf> refused = mesh::clusterLeaves(s.leaves, 0.2, 1.0, none);
    ASSERT_EQ(refused.size(), s.leaves.size());
    std::size_t same = 0;
    for (const skel::Leaf& l : refused)
        for (const skel::Leaf& o : s.leaves)
            same += l.position == o.position && l.size == o.size ? 1 : 0;
    EXPECT_EQ(same, s.leaves.size());
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
    const auto chain = sylva::testing::bandLevels(s, settings);
    ASSERT_EQ(chain.size(), 4u);
    const double leafArea0 = submeshArea(chain[0].second, "leaf");
    ASSERT_GT(leafArea0, 0.0);
    for (std::size_t i = 1; i < chain.size(); ++i) {
        EXPECT_LT(chain[i].second.triangleCount(), chain[i - 1].second.triangleCount()) << i;
        EXPECT_NEAR(submeshArea(chain[i].second, "leaf") / leafArea0, 1.0, 0.05) << i;
    }
    // Cards the LOD makes (clusters, enlarged survivors of thinning) are only drawn when
    // accepted: a forest refuses those that would reach into an obstacle.
    mesh::TreeMeshSettings refusing = settings;
    refusing.useLod = true;
    refusing.cameraDistance = 120;
    refusing.acceptLeafCard = [](const skel::Leaf&) { return false; };
    EXPECT_EQ(submeshArea(mesh::buildTreeMesh(s, refusing), "leaf"), 0.0);
    // The far level drops twigs: fewer bark triangles than resolution alone would give.
    mesh::TreeMeshSettings plain = settings;
    plain.tubes.resolution = 3;
    plain.leaves = false;
    EXPECT_LT(submeshArea(chain[3].second, "bark"),
              submeshArea(mesh::buildTreeMesh(s, plain), "bark"));
}

// tube_mesh's bare_twig_radius (TubeSettings::minBranchRadius) at full detail: the thin
// laterals lose their bark, every leaf keeps its card (issue #33: the spruce's twigs hidden
// in its needle sprays).
TEST(Lod, BareTwigsKeepTheirLeaves) {
    const skel::Skeleton s = leafyTree();
    mesh::TreeMeshSettings settings;
    const mesh::Mesh all = mesh::buildTreeMesh(s, settings);
    settings.tubes.minBranchRadius = 0.05;
    const mesh::Mesh bare = mesh::buildTreeMesh(s, settings);
    EXPECT_LT(submeshArea(bare, "bark"), 0.9 * submeshArea(all, "bark"));
    EXPECT_GT(submeshArea(bare, "bark"), 0.0);
    EXPECT_DOUBLE_EQ(submeshArea(bare, "leaf"), submeshArea(all, "leaf"));
}
