#include <gtest/gtest.h>

#include <filesystem>

#include "../common/testtrees.h"
#include "engine/mesh/season.h"
#include "engine/mesh/treemesh.h"
#include "engine/util/error.h"

using namespace sylva;

namespace {

using sylva::testing::leafyTree;

std::uint32_t leafTriangles(const mesh::Mesh& m) {
    std::uint32_t n = 0;
    for (const mesh::Submesh& s : m.submeshes)
        if (s.material == "leaf") n += s.indexCount / 3;
    return n;
}

mesh::Mesh meshIn(const skel::Skeleton& s, mesh::Season season, bool deciduous, bool lod = false) {
    mesh::TreeMeshSettings settings;
    settings.season = season;
    settings.deciduous = deciduous;
    settings.seed = 99;
    settings.useLod = lod;
    settings.cameraDistance = 10.0;
    return mesh::buildTreeMesh(s, settings);
}

} // namespace

TEST(Season, NamesRoundTripAndBadNamesSayWhatIsAllowed) {
    for (mesh::Season s : mesh::kAllSeasons)
        EXPECT_EQ(mesh::parseSeason(mesh::seasonName(s)), s);
    EXPECT_EQ(mesh::parseSeason("fall"), mesh::Season::Autumn);
    try {
        (void)mesh::parseSeason("Monsoon");
        FAIL() << "accepted a season that does not exist";
    } catch (const InvalidInput& e) {
        EXPECT_NE(std::string(e.what()).find("spring, summer, autumn or winter"),
                  std::string::npos);
    }
}

TEST(Season, WinterBroadleafIsBareAndEvergreensNeverChange) {
    const skel::Skeleton tree = leafyTree();
    ASSERT_GT(tree.leaves.size(), 50u);
    for (bool lod : {false, true}) {
        const mesh::Mesh summer = meshIn(tree, mesh::Season::Summer, true, lod);
        ASSERT_GT(leafTriangles(summer), 0u);
        const mesh::Mesh winter = meshIn(tree, mesh::Season::Winter, true, lod);
        EXPECT_EQ(leafTriangles(winter), 0u) << "a deciduous tree kept leaves in winter";
        // The bark is the same tree.
        EXPECT_EQ(winter.triangleCount(), summer.triangleCount() - leafTriangles(summer));
        for (mesh::Season s : mesh::kAllSeasons) {
            // A conifer (not deciduous) is the exact summer mesh in every season.
            const mesh::Mesh evergreen = meshIn(tree, s, false, lod);
            const mesh::Mesh evergreenSummer = meshIn(tree, mesh::Season::Summer, false, lod);
            EXPECT_EQ(evergreen.positions, evergreenSummer.positions);
            EXPECT_EQ(evergreen.indices, evergreenSummer.indices);
        }
    }
}

TEST(Season, SpringAndAutumnThinTheCrownDeterministically) {
    const skel::Skeleton tree = leafyTree();
    const std::uint32_t summer = leafTriangles(meshIn(tree, mesh::Season::Summer, true));
    const std::uint32_t spring = leafTriangles(meshIn(tree, mesh::Season::Spring, true));
    const std::uint32_t autumn = leafTriangles(meshIn(tree, mesh::Season::Autumn, true));
    // About 70 % and 75 % of the leaves; each a per-leaf draw.
    EXPECT_NEAR(double(spring) / summer, 0.70, 0.1);
    EXPECT_NEAR(double(autumn) / summer, 0.75, 0.1);
    EXPECT_EQ(meshIn(tree, mesh::Season::Spring, true).positions,
              meshIn(tree, mesh::Season::Spring, true).positions);
    // Spring leaves are young: smaller cards.
    const auto kept = mesh::seasonLeaves(tree.leaves, mesh::Season::Spring, true, 5);
    ASSERT_FALSE(kept.empty());
    double springSize = 0, summerSize = 0;
    for (const skel::Leaf& l : kept)
        springSize += l.size;
    for (const skel::Leaf& l : tree.leaves)
        summerSize += l.size;
    EXPECT_LT(springSize / kept.size(), 0.8 * summerSize / tree.leaves.size());
}

TEST(Season, LeafTextureOfASeasonIsDrawnBesideTheSummerOne) {
    const std::string oak = SYLVA_PRESETS_DIR "/textures/english-oak_leaf.png";
    ASSERT_TRUE(std::filesystem::exists(oak));
    EXPECT_EQ(mesh::seasonTextureFile(oak, mesh::Season::Summer), oak);
    const std::string autumn = mesh::seasonTextureFile(oak, mesh::Season::Autumn);
    EXPECT_EQ(std::filesystem::path(autumn).filename(), "english-oak_leaf_autumn.png");
    EXPECT_TRUE(std::filesystem::exists(autumn));
    // No winter leaves are drawn: the summer file stays (a bare tree shows none anyway).
    EXPECT_EQ(mesh::seasonTextureFile(oak, mesh::Season::Winter), oak);
    // The mesh names the season's texture on its leaf submesh.
    mesh::TreeMeshSettings settings;
    settings.leafTexture = oak;
    settings.deciduous = true;
    settings.season = mesh::Season::Autumn;
    const mesh::Mesh m = mesh::buildTreeMesh(leafyTree(), settings);
    bool found = false;
    for (const mesh::Submesh& s : m.submeshes)
        if (s.material == "leaf") {
            EXPECT_EQ(s.texture, autumn);
            found = true;
        }
    EXPECT_TRUE(found);
}
