// The editor's incremental regeneration: a forest built with a TreeCache equals one built
// without it, tree for tree and vertex for vertex, and an edit regrows only what it touched.
#include "document/project.h"
#include "document/scenebuild.h"
#include "engine/forest/forestbuild.h"
#include "engine/forest/treecache.h"

#include <gtest/gtest.h>

#include <cstring>
#include <filesystem>

using namespace sylva;

namespace {

struct Built {
    std::vector<std::string> names;
    std::vector<std::shared_ptr<const mesh::Mesh>> meshes;
    forest::ForestStats stats;
};

Built build(const forest::ForestScene& s, forest::TreeCache* cache) {
    forest::ForestOptions options;
    options.cache = cache;
    options.obstaclesKey = 1;
    Built out;
    out.stats = forest::buildForest(s, options, [&](const std::vector<forest::ForestTree>& batch) {
        for (const forest::ForestTree& t : batch) {
            out.names.push_back(t.name);
            out.meshes.push_back(t.mesh);
        }
    });
    return out;
}

bool sameMesh(const mesh::Mesh& a, const mesh::Mesh& b) {
    return a.positions.size() == b.positions.size() && a.indices == b.indices &&
           std::memcmp(a.positions.data(), b.positions.data(),
                       a.positions.size() * sizeof(glm::vec3)) == 0;
}

void expectSame(const Built& a, const Built& b) {
    ASSERT_EQ(a.names, b.names);
    for (std::size_t i = 0; i < a.meshes.size(); ++i)
        EXPECT_TRUE(sameMesh(*a.meshes[i], *b.meshes[i])) << a.names[i];
    EXPECT_EQ(a.stats.triangles, b.stats.triangles);
    EXPECT_DOUBLE_EQ(a.stats.metrics.co2Kg, b.stats.metrics.co2Kg);
}

} // namespace

TEST(TreeCache, RegrowsOnlyTheTreesAnEditTouched) {
    doc::Project project =
        doc::loadProject(SYLVA_SOURCE_DIR "/resources/demo/alder-reference.sylva");
    const forest::ForestScene original = doc::makeForestScene(project);
    forest::TreeCache cache;
    const Built first = build(original, &cache);
    const std::size_t trees = first.names.size();
    ASSERT_GT(trees, 10u);
    EXPECT_EQ(cache.misses(), trees);
    expectSame(first, build(original, nullptr));

    const Built again = build(original, &cache);
    EXPECT_EQ(cache.hits(), trees);
    EXPECT_EQ(cache.misses(), 0u);
    expectSame(again, first);

    // Reseed the hand-placed tree: it regrows, and so do only the trees around it whose
    // neighbour crowns changed (none: the seed does not move a crown).
    project.instances[0].seed = 99;
    const forest::ForestScene reseeded = doc::makeForestScene(project);
    const Built third = build(reseeded, &cache);
    EXPECT_EQ(cache.misses(), 1u);
    expectSame(third, build(reseeded, nullptr));

    // Move it: placement around it may change, but far trees are reused.
    project.instances[0].position.x += 0.5f;
    const forest::ForestScene moved = doc::makeForestScene(project);
    const Built fourth = build(moved, &cache);
    EXPECT_GE(cache.misses(), 1u);
    EXPECT_LT(cache.misses(), trees / 2);
    expectSame(fourth, build(moved, nullptr));
    EXPECT_LE(cache.size(), trees); // only the last build's trees are kept
}

TEST(TreeCache, SpeciesAreKeyedByTheFilesTheyNameNotByTheirFolder) {
    // A project saved into another folder names the same species file, grammar and meshes by
    // other relative paths (its inline species' paths are rebased): its trees are the same and
    // must not regrow. Another file is another species.
    const std::filesystem::path tmp = std::filesystem::temp_directory_path();
    auto species = [](const std::filesystem::path& dir, const std::string& grammar,
                      const std::string& obstacle) {
        graph::SpeciesGraph g;
        g.name = "alder";
        g.output = "grow";
        g.baseDir = dir;
        sylva::Value::Object adapt{{"obstacles", sylva::Value::Array{sylva::Value::Object{
                                                     {"file", obstacle}, {"scale", 2.0}}}}};
        g.nodes.push_back({"grow", "lsystem", sylva::Value::Object{{"grammar_file", grammar}}, {}});
        g.nodes.push_back({"adapt", "adapt", sylva::Value(adapt), {"grow"}});
        return g;
    };
    const std::uint64_t there =
        forest::speciesHash(species(tmp / "project", "../presets/alder.lsys", "meshes/wall.obj"));
    // The same files named from another folder, and through a roundabout spelling of it.
    EXPECT_EQ(forest::speciesHash(species(tmp / "elsewhere" / "deeper", "../../presets/alder.lsys",
                                          "../../project/meshes/wall.obj")),
              there);
    EXPECT_EQ(forest::speciesHash(species(tmp / "x" / ".." / "project", "../presets/alder.lsys",
                                          "meshes/wall.obj")),
              there);
    // The same relative names from another folder are other files: another species.
    EXPECT_NE(
        forest::speciesHash(species(tmp / "elsewhere", "../presets/alder.lsys", "meshes/wall.obj")),
        there);
    EXPECT_NE(forest::speciesHash(
                  species(tmp / "project", "../presets/alder.lsys", "meshes/boulder.obj")),
              there);
}
