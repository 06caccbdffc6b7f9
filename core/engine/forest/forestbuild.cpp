#include "engine/forest/forestbuild.h"

#include "engine/forest/placing.h"
#include "engine/forest/speciesplan.h"
#include "engine/forest/stands.h"
#include "engine/forest/treecache.h"
#include "engine/forest/treestage.h"
#include "engine/forest/variants.h"
#include "engine/forest/workers.h"
#include "engine/util/error.h"

#include <algorithm>
#include <exception>
#include <string>

#include <omp.h>

namespace sylva::forest {

namespace {

using build::Clock;
using build::msSince;

const env::ObstacleScene& emptyScene() {
    static const env::ObstacleScene scene;
    return scene;
}

/// Adds one finished tree to the build's counts.
void count(ForestStats& stats, const ForestTree& tree) {
    ++(tree.variant >= 0 ? stats.instanced : stats.unique);
    if (tree.adaptedFrom >= 0) ++stats.adaptedVariants;
    if (tree.instanceChecked) ++stats.instancedByCheck;
    stats.vertices += tree.mesh->vertexCount();
    stats.triangles += tree.mesh->triangleCount();
    stats.collidingTrees += tree.adapt.collidingBefore > 0 ? 1 : 0;
    stats.prunedNodes += tree.adapt.hiddenNodes;
    stats.metrics.add(tree.metrics);
    stats.branchEdits += tree.branchEdits.applied;
    stats.orphanedEdits += tree.branchEdits.orphaned.size();
    for (const std::string& id : tree.branchEdits.orphaned)
        stats.warnings.push_back("tree " + std::to_string(tree.instance.id) +
                                 ": the edit of branch " + id +
                                 " found no such branch (kept, not applied)");
}

double sum(const std::vector<double>& v) {
    double s = 0;
    for (double x : v)
        s += x;
    return s;
}

} // namespace

ForestStats buildForest(const ForestScene& scene, const ForestOptions& options,
                        const TreeSink& sink, Progress& progress) {
    if (scene.species.empty()) throw InvalidInput("the scene has no species");
    requireRange("tile count", options.tileCount, 1, 1e6);
    requireRange("tile", options.tile, 0, options.tileCount - 1);
    ForestStats stats;

    // 1. Species: graphs checked, growth policies decided, crowns measured on a sample tree.
    auto t0 = Clock::now();
    if (options.cache) options.cache->beginBuild();
    const std::vector<build::SpeciesPlan> plans = build::planSpecies(scene, options);
    stats.wallMs["species"] = msSince(t0);

    // 2. Placement over the whole scene, then the tile; every tree's crown for its neighbours.
    t0 = Clock::now();
    build::Placed placed = build::placeTrees(scene, options, plans);
    stats.shortfalls = placed.shortfalls;
    stats.treesInScene = placed.instances.size();
    stats.trees = placed.selected.size();
    const build::NeighbourGrid neighbours(placed.instances, plans);
    stats.wallMs["place"] = msSince(t0);

    // 3. The stand trees of the whole scene, grown together.
    t0 = Clock::now();
    const std::vector<std::shared_ptr<const skel::Skeleton>> standGrown =
        build::growStands(scene, plans, placed.instances, progress);
    stats.wallMs["stand"] = msSince(t0);

    // 4. Variants with their levels.
    t0 = Clock::now();
    build::Workers workers(scene, std::max(1, omp_get_max_threads()));
    const build::VariantSet variants =
        build::buildVariants(scene, options, plans, placed, workers, progress);
    stats.variants = variants.variants.size();
    if (options.onVariants) options.onVariants(variants.variants);
    stats.wallMs["variants"] = msSince(t0);

    // 5. The tile's trees, in parallel batches handed on in instance order.
    t0 = Clock::now();
    const build::TreeStage stage{
        scene,      options,    plans,    placed,
        neighbours, standGrown, variants, scene.obstacles ? *scene.obstacles : emptyScene()};
    const std::vector<std::size_t>& selected = placed.selected;
    const std::size_t batchSize = std::max<std::size_t>(1, options.batchSize);
    for (std::size_t begin = 0; begin < selected.size(); begin += batchSize) {
        progress.checkCancelled();
        const std::size_t end = std::min(selected.size(), begin + batchSize);
        std::vector<ForestTree> batch(end - begin);
        std::vector<std::exception_ptr> errors(end - begin);
#pragma omp parallel for schedule(dynamic, 1) num_threads(workers.threads)
        for (std::ptrdiff_t k = 0; k < static_cast<std::ptrdiff_t>(end - begin); ++k) {
            // Ctrl-C/SIGTERM: the trees not started are skipped, the batch ends with the trees
            // in flight and checkCancelled() below throws (a batch of 64 takes seconds).
            if (progress.isCancelled()) continue;
            const auto slot = static_cast<std::size_t>(k);
            const auto thread = static_cast<std::size_t>(omp_get_thread_num());
            try {
                batch[slot] = build::buildTree(stage, selected[begin + slot], workers, thread);
            } catch (...) {
                errors[slot] = std::current_exception();
            }
        }
        progress.checkCancelled();
        for (const std::exception_ptr& e : errors)
            if (e) std::rethrow_exception(e); // the first failing tree in instance order
        for (const ForestTree& tree : batch)
            count(stats, tree);
        sink(batch);
        progress.report(static_cast<double>(end) / static_cast<double>(selected.size()), "trees");
    }
    stats.cpuMs["generate"] = sum(workers.generateMs);
    stats.cpuMs["adapt"] = sum(workers.adaptMs);
    stats.cpuMs["mesh"] = sum(workers.meshMs);
    stats.wallMs["trees"] = msSince(t0);
    if (options.cache) options.cache->endBuild();
    return stats;
}

} // namespace sylva::forest
