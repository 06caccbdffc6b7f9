// Forests at film scale (issue 30): a tree that nothing would adapt shows one of its species' K
// variants (shared mesh, its own transform); one near an obstacle or a neighbour's crown is grown
// for its place. Which is which is deterministic and reported.
#include <gtest/gtest.h>

#include <filesystem>
#include <set>

#include <omp.h>

#include "engine/environment/obstaclemesh.h"
#include "engine/forest/forestbuild.h"
#include "engine/mesh/lod.h"
#include "engine/util/random.h"
#include "engine/util/seedsalts.h"
#include "presetfile.h"

using namespace sylva;

namespace {

forest::ForestScene sparseForest(std::size_t count, bool wall) {
    graph::registerBuiltinNodeTypes();
    forest::ForestScene s;
    s.seed = 11;
    forest::SceneSpecies beech;
    beech.name = "beech";
    beech.graph = sylva::testing::loadPreset(std::filesystem::path(SYLVA_PRESETS_DIR) /
                                             "european-beech.json");
    beech.variants = 3;
    s.species.push_back(std::move(beech));
    placement::Domain d;
    d.min = {-60.0f, -60.0f};
    d.max = {60.0f, 60.0f};
    d.counts = {{"beech", count}};
    s.domains.push_back(d);
    if (wall) {
        std::vector<env::ObstacleMesh> meshes;
        meshes.push_back(env::makeBoxMesh({-60.0f, 0.0f, -1.0f}, {60.0f, 3.0f, 1.0f}, "wall"));
        s.obstacles = std::make_shared<const env::ObstacleScene>(std::move(meshes));
    }
    return s;
}

struct Built {
    std::vector<forest::ForestVariant> variants;
    std::vector<forest::ForestTree> trees;
    forest::ForestStats stats;
    int variantCalls = 0;
    bool variantsBeforeTrees = true;
};

Built build(const forest::ForestScene& s, forest::ForestOptions options) {
    Built b;
    options.onVariants = [&b](const std::vector<forest::ForestVariant>& v) {
        ++b.variantCalls;
        b.variantsBeforeTrees = b.variantsBeforeTrees && b.trees.empty();
        b.variants = v;
    };
    b.stats = forest::buildForest(s, options, [&b](const std::vector<forest::ForestTree>& batch) {
        b.trees.insert(b.trees.end(), batch.begin(), batch.end());
    });
    return b;
}

} // namespace

TEST(Instancing, FreeTreesShareTheirVariantsMeshTouchingOnesAreUnique) {
    const forest::ForestScene s = sparseForest(24, true);
    forest::ForestOptions options;
    options.useLod = false;
    const Built b = build(s, options);
    EXPECT_EQ(b.variantCalls, 1);
    EXPECT_TRUE(b.variantsBeforeTrees);
    ASSERT_EQ(b.variants.size(), 3u);
    EXPECT_EQ(b.stats.variants, 3u);
    for (std::size_t i = 0; i < b.variants.size(); ++i) {
        EXPECT_EQ(b.variants[i].index, i);
        EXPECT_EQ(b.variants[i].name, "beech_v" + std::to_string(i));
        ASSERT_TRUE(b.variants[i].mesh && b.variants[i].skeleton && b.variants[i].meshSettings);
        EXPECT_GT(b.variants[i].mesh->triangleCount(), 0u);
    }
    EXPECT_NE(b.variants[0].seed, b.variants[1].seed);

    ASSERT_EQ(b.trees.size(), 24u);
    EXPECT_EQ(b.stats.instanced + b.stats.unique, b.stats.trees);
    std::size_t instanced = 0, nearWall = 0;
    for (const forest::ForestTree& t : b.trees) {
        // Within a crown's reach of the wall (a beech's crown is several metres wide), a tree
        // must be unique.
        const bool close = std::abs(t.instance.position.z) < 2.0f;
        nearWall += close ? 1 : 0;
        if (t.variant < 0) continue;
        ++instanced;
        EXPECT_FALSE(close) << t.name << " stands at z = " << t.instance.position.z;
        const forest::ForestVariant& v = b.variants.at(static_cast<std::size_t>(t.variant));
        EXPECT_EQ(t.mesh.get(), v.mesh.get()) << "shared, not copied";
        EXPECT_EQ(t.skeleton.get(), v.skeleton.get());
        EXPECT_EQ(t.variant,
                  static_cast<std::int32_t>(mixSeed(t.instance.seed, salt::kVariantPick) % 3));
    }
    EXPECT_EQ(instanced, b.stats.instanced);
    // Sparse: most trees are free; the wall makes some unique.
    EXPECT_GT(b.stats.instanced, b.stats.trees / 2);
    EXPECT_GT(b.stats.unique, 0u);
    (void)nearWall;
}

TEST(Instancing, OffEveryTreeIsUniqueAndNoVariantIsMade) {
    forest::ForestOptions options;
    options.instancing = false;
    options.buildMeshes = false;
    const Built b = build(sparseForest(10, false), options);
    EXPECT_EQ(b.stats.instanced, 0u);
    EXPECT_EQ(b.stats.unique, 10u);
    EXPECT_EQ(b.stats.variants, 0u);
    for (const forest::ForestTree& t : b.trees)
        EXPECT_EQ(t.variant, -1);
}

TEST(Instancing, KIsPerSpeciesWithTheOptionAsDefaultAndChecked) {
    forest::ForestScene s = sparseForest(6, false);
    s.species[0].variants = -1;
    forest::ForestOptions options;
    options.buildMeshes = false;
    options.variantsPerSpecies = 5;
    EXPECT_EQ(build(s, options).variants.size(), 5u);
    options.variantsPerSpecies = 0;
    EXPECT_THROW(build(s, options), InvalidInput);
    s.species[0].variants = 300;
    options.variantsPerSpecies = 8;
    EXPECT_THROW(build(s, options), InvalidInput);
    // 0: a species whose every tree is grown for its place.
    s.species[0].variants = 0;
    const Built hero = build(s, options);
    EXPECT_TRUE(hero.variants.empty());
    EXPECT_EQ(hero.stats.instanced, 0u);
    EXPECT_EQ(hero.stats.unique, 6u);
}

// Same project, same forest: which trees are instanced, their variants, and every mesh byte,
// on one thread or two.
TEST(Instancing, DeterministicOnOneAndTwoThreads) {
    const forest::ForestScene s = sparseForest(30, true);
    forest::ForestOptions options;
    options.batchSize = 7;
    const int threads = omp_get_max_threads();
    omp_set_num_threads(1);
    const Built one = build(s, options);
    omp_set_num_threads(2);
    const Built two = build(s, options);
    omp_set_num_threads(threads);
    ASSERT_EQ(one.trees.size(), two.trees.size());
    ASSERT_EQ(one.variants.size(), two.variants.size());
    for (std::size_t i = 0; i < one.variants.size(); ++i) {
        EXPECT_EQ(one.variants[i].seed, two.variants[i].seed);
        EXPECT_EQ(one.variants[i].mesh->positions, two.variants[i].mesh->positions);
    }
    for (std::size_t i = 0; i < one.trees.size(); ++i) {
        EXPECT_EQ(one.trees[i].instance.id, two.trees[i].instance.id);
        EXPECT_EQ(one.trees[i].variant, two.trees[i].variant);
        EXPECT_EQ(one.trees[i].mesh->positions, two.trees[i].mesh->positions) << i;
        EXPECT_EQ(one.trees[i].mesh->indices, two.trees[i].mesh->indices) << i;
    }
    EXPECT_EQ(one.stats.instanced, two.stats.instanced);
}

// Issue #32: with the camera LOD, an instanced tree draws one of its variant's levels (made
// once per variant, shared), the one for its distance over its scale: never a finer level than
// a nearer tree of the same variant and scale would get, and level 0 is the variant's mesh.
// This is the one path (forest's per-instance meshing at the tree's distance was merged into it):
// an instanced tree shares its variant's skeleton and settings, and its mesh is the variant's
// level itself (the same pointer), never more triangles than the full-detail variant.
TEST(Instancing, InstancesDrawTheirVariantsLevelForTheirDistance) {
    forest::ForestScene s = sparseForest(24, false);
    s.camera = {0.0f, 10.0f, 150.0f};
    forest::ForestOptions options;
    options.useLod = true;
    const Built b = build(s, options);
    std::size_t instanced = 0;
    std::set<std::size_t> levelsDrawn;
    for (const forest::ForestVariant& v : b.variants) {
        ASSERT_GE(v.levels.size(), 2u) << v.name;
        EXPECT_EQ(v.levels.front().mesh.get(), v.mesh.get());
        for (std::size_t i = 1; i < v.levels.size(); ++i) {
            EXPECT_GT(v.levels[i].distance, v.levels[i - 1].distance);
            EXPECT_LT(v.levels[i].mesh->triangleCount(), v.levels[i - 1].mesh->triangleCount());
        }
    }
    for (const forest::ForestTree& t : b.trees) {
        if (t.variant < 0) continue;
        ++instanced;
        const forest::ForestVariant& v = b.variants.at(static_cast<std::size_t>(t.variant));
        const double scale = double(t.instance.scale) * double(t.instance.growth);
        const double d = glm::length(s.camera - t.instance.position) / scale;
        const std::size_t k = mesh::levelFor(v.levels, d);
        EXPECT_EQ(t.skeleton.get(), v.skeleton.get());
        EXPECT_EQ(t.meshSettings.get(), v.meshSettings.get());
        EXPECT_EQ(t.mesh.get(), v.levels[k].mesh.get()) << t.name << " at " << d << " m";
        EXPECT_NEAR(t.meshCameraDistance, v.levels[k].distance * scale, 1e-6);
        EXPECT_LE(t.mesh->triangleCount(), v.mesh->triangleCount()) << t.name;
        levelsDrawn.insert(k);
    }
    EXPECT_GT(instanced, 12u);
    // The forest spans 90-210 m from the camera: its instances do not all draw one level.
    EXPECT_GE(levelsDrawn.size(), 2u);
}

// A unique domain tree of a species whose growth sees nothing of its place (no adapt node)
// starts from the skeleton of the variant its seed picks and is adapted for its place: the
// trees at the wall are pruned copies of their variant, the others keep its nodes; a
// hand-placed tree and every tree with adaptVariants off are grown from their own seed.
TEST(Instancing, UniqueTreesAreAdaptedFromTheirVariantsSkeleton) {
    forest::ForestScene s = sparseForest(30, true);
    // A wall as tall as the crowns, so that the trees beside it are cut back.
    std::vector<env::ObstacleMesh> meshes;
    meshes.push_back(env::makeBoxMesh({-60.0f, 0.0f, -1.0f}, {60.0f, 30.0f, 1.0f}, "wall"));
    s.obstacles = std::make_shared<const env::ObstacleScene>(std::move(meshes));
    placement::Instance hand;
    hand.species = 0;
    hand.id = 7;
    hand.position = {20.0f, 0.0f, 0.5f}; // at the wall: unique
    hand.seed = mixSeed(s.seed, hand.id);
    hand.handPlaced = true;
    s.handPlaced.push_back(hand);
    forest::ForestOptions options;
    options.useLod = false;
    const Built b = build(s, options);
    ASSERT_GT(b.stats.unique, 2u);
    std::size_t adapted = 0, changed = 0, handSeen = 0, checked = 0;
    for (const forest::ForestTree& t : b.trees) {
        if (t.variant >= 0) {
            EXPECT_EQ(t.adaptedFrom, -1) << t.name;
            checked += t.instanceChecked ? 1 : 0;
            if (t.instanceChecked) {
                EXPECT_EQ(t.adapt.collidingBefore, 0u) << t.name;
            }
            continue;
        }
        if (t.instance.handPlaced) {
            ++handSeen;
            EXPECT_EQ(t.adaptedFrom, -1) << "an artist's tree grows from its own seed";
            continue;
        }
        ASSERT_GE(t.adaptedFrom, 0) << t.name;
        ++adapted;
        const auto pick =
            static_cast<std::int32_t>(mixSeed(t.instance.seed, salt::kVariantPick) % 3);
        EXPECT_EQ(t.adaptedFrom, pick) << t.name;
        const skel::Skeleton& v = *b.variants.at(static_cast<std::size_t>(pick)).skeleton;
        // Adaptation bends (positions), prunes (kHidden flags) and drops leaf cards.
        const bool same = t.skeleton->size() == v.size() && t.skeleton->position == v.position &&
                          t.skeleton->flags == v.flags &&
                          t.skeleton->leaves.size() == v.leaves.size();
        EXPECT_EQ(same, t.adapt.collidingBefore == 0 && t.adapt.droppedLeaves == 0) << t.name;
        changed += same ? 0 : 1;
        // Far from the wall, only a neighbour makes a tree unique, and only where its variant
        // reaches into that neighbour's crown core: otherwise it is an instance.
        if (std::abs(t.instance.position.z) > 20.0f) {
            EXPECT_GT(t.adapt.collidingBefore, 0u) << t.name;
        }
        EXPECT_NE(t.mesh.get(), b.variants[static_cast<std::size_t>(pick)].mesh.get())
            << "its own mesh";
    }
    EXPECT_EQ(handSeen, 1u);
    EXPECT_EQ(adapted, b.stats.adaptedVariants);
    EXPECT_EQ(checked, b.stats.instancedByCheck);
    EXPECT_EQ(adapted + handSeen, b.stats.unique);
    EXPECT_GT(changed, 0u) << "the trees at the wall are cut back";

    options.adaptVariants = false;
    const Built grown = build(s, options);
    EXPECT_EQ(grown.stats.adaptedVariants, 0u);
    EXPECT_EQ(grown.stats.unique, b.stats.unique) << "which trees are unique does not change";
    for (const forest::ForestTree& t : grown.trees) {
        EXPECT_EQ(t.adaptedFrom, -1);
        if (t.variant >= 0 || t.instance.handPlaced) continue;
        for (const forest::ForestVariant& v : grown.variants)
            EXPECT_NE(t.skeleton->size(), v.skeleton->size()) << t.name << " grown from its seed";
    }
}

// Issue #41: variants are grown only where a tree may show one. Hand-placed trees are always
// grown from their own seed, so a project of hand-placed trees grows no variant (library.sylva
// grew 96, twenty times its trees' time) and builds the same trees as with K = 0.
TEST(Instancing, HandPlacedTreesAloneGrowNoVariant) {
    forest::ForestScene s = sparseForest(0, false);
    s.domains.clear();
    s.species[0].variants = -1; // the option's K (8)
    for (std::uint64_t i = 0; i < 3; ++i) {
        placement::Instance in;
        in.species = 0;
        in.id = i + 1;
        in.seed = 100 + i;
        in.position = {15.0f * static_cast<float>(i), 0.0f, 0.0f};
        in.handPlaced = true;
        s.handPlaced.push_back(in);
    }
    forest::ForestOptions options;
    const Built placedOnly = build(s, options);
    EXPECT_EQ(placedOnly.stats.variants, 0u);
    EXPECT_TRUE(placedOnly.variants.empty());
    EXPECT_EQ(placedOnly.stats.unique, 3u);
    s.species[0].variants = 0;
    const Built none = build(s, options);
    ASSERT_EQ(placedOnly.trees.size(), none.trees.size());
    for (std::size_t i = 0; i < none.trees.size(); ++i) {
        EXPECT_EQ(placedOnly.trees[i].variant, -1);
        EXPECT_EQ(placedOnly.trees[i].mesh->positions, none.trees[i].mesh->positions) << i;
        EXPECT_EQ(placedOnly.trees[i].mesh->indices, none.trees[i].mesh->indices) << i;
    }
    // A domain tree of the species brings its variants back.
    s.species[0].variants = 2;
    placement::Domain d;
    d.min = {100.0f, 100.0f};
    d.max = {140.0f, 140.0f};
    d.counts = {{"beech", 1}};
    s.domains.push_back(d);
    options.buildMeshes = false;
    EXPECT_EQ(build(s, options).stats.variants, 2u);
}

// Issue #41: merged exports with wind data (OBJ, FBX, glTF without instancing, with --wind)
// draw an instance at its variant's level for its distance too: the levels carry the node ids
// the wind data is derived from, and far instances get at most half the triangles of the
// nearest (every instance drew the full variant: bench-1000 with --wind wrote a 7 GB OBJ).
TEST(Instancing, WithWindDataInstancesStillDrawTheirLevel) {
    forest::ForestScene s = sparseForest(24, false);
    s.camera = {0.0f, 10.0f, 80.0f};
    forest::ForestOptions options;
    options.useLod = true;
    options.windData = true;
    const Built b = build(s, options);
    for (const forest::ForestVariant& v : b.variants) {
        ASSERT_GE(v.levels.size(), 2u) << v.name;
        for (const mesh::DistanceLevel& level : v.levels)
            EXPECT_EQ(level.mesh->node.size(), level.mesh->positions.size()) << v.name;
    }
    std::size_t nearest = 0, farthest = 0;
    double dNear = 1e30, dFar = 0.0;
    for (std::size_t i = 0; i < b.trees.size(); ++i) {
        const forest::ForestTree& t = b.trees[i];
        if (t.variant < 0) continue;
        EXPECT_EQ(t.mesh->node.size(), t.mesh->positions.size()) << t.name;
        const double d = glm::length(s.camera - t.instance.position) /
                         (double(t.instance.scale) * double(t.instance.growth));
        if (d < dNear) dNear = d, nearest = i;
        if (d > dFar) dFar = d, farthest = i;
    }
    ASSERT_GT(dFar, dNear);
    EXPECT_LE(2 * b.trees[farthest].mesh->triangleCount(),
              b.variants.at(std::size_t(b.trees[farthest].variant)).mesh->triangleCount());
    EXPECT_LE(b.trees[farthest].mesh->triangleCount(), b.trees[nearest].mesh->triangleCount());
}
