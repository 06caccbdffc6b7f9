// A forest's trees carry how their meshes were made (issue 29), so a viewer makes coarser
// levels of the same tree from them without deriving anything again: the carried settings and
// camera distance give back the very mesh the forest made.
#include <gtest/gtest.h>

#include <cstring>
#include <filesystem>
#include <set>

#include "engine/forest/forestbuild.h"
#include "engine/mesh/treemesh.h"
#include "engine/util/random.h"
#include "engine/util/seedsalts.h"
#include "presetfile.h"

using namespace sylva;

namespace {

forest::ForestScene smallForest() {
    graph::registerBuiltinNodeTypes();
    forest::ForestScene s;
    s.seed = 7;
    forest::SceneSpecies beech;
    beech.name = "beech";
    beech.graph = sylva::testing::loadPreset(std::filesystem::path(SYLVA_PRESETS_DIR) /
                                             "european-beech.json");
    s.species.push_back(std::move(beech));
    placement::Domain d;
    d.min = {-20.0f, -20.0f};
    d.max = {20.0f, 20.0f};
    d.counts = {{"beech", 3}};
    s.domains.push_back(d);
    s.camera = {0.0f, 10.0f, 60.0f};
    return s;
}

std::vector<forest::ForestTree> build(const forest::ForestScene& s,
                                      const forest::ForestOptions& options) {
    std::vector<forest::ForestTree> trees;
    forest::buildForest(s, options, [&](const std::vector<forest::ForestTree>& batch) {
        trees.insert(trees.end(), batch.begin(), batch.end());
    });
    return trees;
}

bool sameMesh(const mesh::Mesh& a, const mesh::Mesh& b) {
    return a.positions.size() == b.positions.size() && a.indices == b.indices &&
           std::memcmp(a.positions.data(), b.positions.data(),
                       a.positions.size() * sizeof(glm::vec3)) == 0 &&
           a.submeshes.size() == b.submeshes.size();
}

} // namespace

TEST(ForestBuild, TreesCarryTheSettingsAndDistanceTheirMeshWasMadeWith) {
    const forest::ForestScene s = smallForest();
    forest::ForestOptions unique; // instanced trees show their variant's mesh (tested elsewhere)
    unique.instancing = false;
    const std::vector<forest::ForestTree> trees = build(s, unique);
    ASSERT_EQ(trees.size(), 3u);
    for (const forest::ForestTree& tree : trees) {
        ASSERT_TRUE(tree.meshSettings) << tree.name;
        ASSERT_TRUE(tree.skeleton) << tree.name;
        EXPECT_EQ(tree.meshSettings->seed, mixSeed(tree.instance.seed, salt::kTreeMesh));
        // Before the camera: a viewer applies its own level of detail.
        EXPECT_FALSE(tree.meshSettings->hasCamera);
        EXPECT_FALSE(tree.meshSettings->acceptLeafCard);
        // Textures resolved from the species file's folder, as the forest drew them.
        EXPECT_TRUE(std::filesystem::path(tree.meshSettings->barkTexture).is_absolute())
            << tree.meshSettings->barkTexture;
        const double distance = glm::length(s.camera - tree.instance.position);
        EXPECT_DOUBLE_EQ(tree.meshCameraDistance, distance);

        // The carried settings at the carried distance make the forest's mesh again.
        mesh::TreeMeshSettings again = *tree.meshSettings;
        again.useLod = true;
        again.cameraDistance = tree.meshCameraDistance;
        again.hasCamera = true;
        again.cameraLocal =
            glm::vec3(glm::inverse(tree.instance.transform()) * glm::vec4(s.camera, 1.0f));
        EXPECT_TRUE(sameMesh(mesh::buildTreeMesh(*tree.skeleton, again), *tree.mesh)) << tree.name;
    }
}

TEST(ForestBuild, WithoutTheCameraLodTheSettingsAloneMakeTheMesh) {
    forest::ForestOptions options;
    options.useLod = false; // unique and instanced trees alike
    for (const forest::ForestTree& tree : build(smallForest(), options)) {
        ASSERT_TRUE(tree.meshSettings);
        EXPECT_EQ(tree.meshCameraDistance, 0.0);
        EXPECT_TRUE(sameMesh(mesh::buildTreeMesh(*tree.skeleton, *tree.meshSettings), *tree.mesh))
            << tree.name;
    }
    options.buildMeshes = false;
    for (const forest::ForestTree& tree : build(smallForest(), options))
        EXPECT_FALSE(tree.meshSettings) << tree.name;
}

// The salts' values are part of the byte-identical guarantee: a changed one fails to compile.
static_assert(salt::kTreeMesh == 0x7EAF && salt::kLeafPlacement == 0x1EAF);
static_assert(salt::kSpaceColonization == 0x636f6c6f6e697a65ull &&
              salt::kEnvelope == 0x656e76656c6f7065ull);
static_assert(salt::kSelfOrganizingTree == 0x5e1f && salt::kSelfOrganizingMarkers == 0x3a7c &&
              salt::kSelfOrganizingCycle == 0x5400);
static_assert(salt::kCrownSample == 0xC0000 && salt::kDomainSlots == 0xD0A1 &&
              salt::kPlacedTree == 0x0A11);
static_assert(salt::kBrushStroke == 7919 && salt::kPlaceTool == 104729);
static_assert(salt::kWindPhase == 0x771D0 && salt::kViewWindPhase == 0x771D7);
static_assert(salt::kVariant == 0x5A1A7 && salt::kVariantPick == 0x5A1B);
static_assert(salt::kSeason == 0x5EA5);

TEST(SeedSalts, EverySaltIsItsOwn) {
    const std::set<std::uint64_t> salts{salt::kTreeMesh,
                                        salt::kLeafPlacement,
                                        salt::kSpaceColonization,
                                        salt::kEnvelope,
                                        salt::kSelfOrganizingTree,
                                        salt::kSelfOrganizingMarkers,
                                        salt::kSelfOrganizingCycle,
                                        salt::kCrownSample,
                                        salt::kDomainSlots,
                                        salt::kPlacedTree,
                                        salt::kBrushStroke,
                                        salt::kPlaceTool,
                                        salt::kWindPhase,
                                        salt::kWindPhase + 1,
                                        salt::kViewWindPhase,
                                        salt::kVariant,
                                        salt::kVariantPick,
                                        salt::kSeason,
                                        salt::kLeafClusters};
    EXPECT_EQ(salts.size(), 19u);
}
