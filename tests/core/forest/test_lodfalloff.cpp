// Issue #32: the forest's camera LOD keeps getting cheaper with distance, all the way down. In
// the benchmark project (1,000 alders of 4.3 m) the 100 trees farthest from the project camera
// (255-260 m) must carry at most half the triangles of the 100 nearest (47-52 m), at the
// silhouette bar test_lodcoverage holds the LOD to. The demo project mixes species and sizes, so
// there each tree's triangles count as a fraction of its own full-detail mesh: the farthest
// quarter's mean fraction at most half the nearest quarter's (its depth is only 50-103 m).
// Instanced trees count with the variant level they are drawn with.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <iostream>
#include <map>

#include "document/project.h"
#include "document/scenebuild.h"
#include "engine/forest/forestbuild.h"
#include "engine/graph/graph.h"

using namespace sylva;

namespace {

const std::filesystem::path kDemo =
    std::filesystem::path(SYLVA_PRESETS_DIR) / ".." / "resources" / "demo";

struct Falloff {
    double nearMean = 0.0, farMean = 0.0;
    double nearFraction = 0.0, farFraction = 0.0; ///< of each tree's full-detail triangles
    double nearFrom = 0.0, nearTo = 0.0, farFrom = 0.0, farTo = 0.0;
    std::size_t trees = 0, instanced = 0;
};

Falloff measure(const std::string& project) {
    graph::registerBuiltinNodeTypes();
    const doc::Project p = doc::loadProject(QString::fromStdString((kDemo / project).string()));
    const forest::ForestScene s = doc::makeForestScene(p);
    std::map<std::uint64_t, std::size_t> full;
    forest::ForestOptions options;
    options.useLod = false;
    forest::buildForest(s, options, [&](const std::vector<forest::ForestTree>& batch) {
        for (const forest::ForestTree& t : batch)
            full[t.instance.id] = t.mesh->triangleCount();
    });
    struct Tree {
        double distance;
        std::size_t triangles;
        double fraction;
        bool operator<(const Tree& o) const { return distance < o.distance; }
    };
    std::vector<Tree> trees;
    Falloff f;
    options.useLod = true;
    forest::buildForest(s, options, [&](const std::vector<forest::ForestTree>& batch) {
        for (const forest::ForestTree& t : batch) {
            const auto tris = t.mesh->triangleCount();
            trees.push_back({glm::length(s.camera - t.instance.position), tris,
                             static_cast<double>(tris) / static_cast<double>(std::max<std::size_t>(
                                                             1, full.at(t.instance.id)))});
            f.instanced += t.variant >= 0;
        }
    });
    std::sort(trees.begin(), trees.end());
    f.trees = trees.size();
    const std::size_t n = std::min<std::size_t>(100, trees.size() / 4);
    for (std::size_t i = 0; i < n; ++i) {
        const Tree& a = trees[i];
        const Tree& b = trees[trees.size() - 1 - i];
        f.nearMean += static_cast<double>(a.triangles) / static_cast<double>(n);
        f.farMean += static_cast<double>(b.triangles) / static_cast<double>(n);
        f.nearFraction += a.fraction / static_cast<double>(n);
        f.farFraction += b.fraction / static_cast<double>(n);
    }
    f.nearFrom = trees.front().distance;
    f.nearTo = trees[n - 1].distance;
    f.farFrom = trees[trees.size() - n].distance;
    f.farTo = trees.back().distance;
    std::cout << project << ": " << f.trees << " trees (" << f.instanced << " instanced); nearest "
              << n << " (" << f.nearFrom << "-" << f.nearTo << " m) " << f.nearMean
              << " triangles on average, farthest " << n << " (" << f.farFrom << "-" << f.farTo
              << " m) " << f.farMean << "; of full detail: nearest " << f.nearFraction
              << ", farthest " << f.farFraction << "\n";
    return f;
}

} // namespace

TEST(LodFalloff, BenchmarkFarTreesCostLess) {
    const Falloff f = measure("bench-1000.sylva");
    EXPECT_LE(f.farMean, 0.5 * f.nearMean);
    EXPECT_LE(f.farFraction, 0.5 * f.nearFraction);
}

TEST(LodFalloff, DemoFarTreesCostLess) {
    const Falloff f = measure("forest.sylva");
    EXPECT_LE(f.farFraction, 0.5 * f.nearFraction);
}
