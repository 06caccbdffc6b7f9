#include "engine/forest/treestage.h"

#include "engine/forest/treecache.h"
#include "engine/forest/treekey.h"
#include "engine/mesh/treemesh.h"
#include "engine/util/error.h"
#include "engine/util/random.h"
#include "engine/util/seedsalts.h"

#include <algorithm>
#include <optional>
#include <string>

namespace sylva::forest::build {

namespace {

/// Whether a variant with extent \p e placed as \p in comes near an obstacle (a capsule around
/// its cylinder: conservative, so an instanced tree never enters one).
bool touchesObstacles(const env::ObstacleScene& obstacles, const placement::Instance& in,
                      const Extent& e) {
    if (obstacles.empty()) return false;
    const float s = in.scale * in.growth;
    const float r = e.radius * s;
    const glm::vec3 a = in.position + glm::vec3(0.0f, e.bottom * s, 0.0f);
    const glm::vec3 b = in.position + glm::vec3(0.0f, e.top * s, 0.0f);
    if (!obstacles.overlapsBounds(a - glm::vec3(r), b + glm::vec3(r))) return false;
    return obstacles.touches({a, b}, r);
}

/// Makes \p tree show variant \p v: its skeleton and settings shared, its mesh the variant's
/// or the variant's level for this tree's size on screen.
void showVariant(ForestTree& tree, const TreeStage& stage, std::size_t v, double cameraDistance) {
    const placement::Instance& in = tree.instance;
    const ForestOptions& options = stage.options;
    const ForestVariant& variant = stage.variants.variants[v];
    tree.variant = static_cast<std::int32_t>(v);
    tree.adaptedFrom = -1;
    tree.instanceChecked = false;
    tree.skeleton = variant.skeleton;
    if (options.keepGrown) tree.grown = variant.skeleton;
    tree.meshSettings = variant.meshSettings;
    tree.metrics = forest::measureTree(stage.variants.measures[v], stage.plans[in.species].wood,
                                       in.scale * in.growth);
    if (!options.useLod || !options.buildMeshes || !options.meshInstances ||
        variant.levels.empty()) {
        tree.mesh = variant.mesh; // shared: drawn with the tree's transform
        return;
    }
    // The variant's level for this tree's size on screen, made once per variant (the
    // full-detail variant drawn 1,000 times made an OBJ 13 times larger): the variant stands
    // at scale 1, the tree at scale·growth.
    const double s = std::max(1e-3, static_cast<double>(in.scale) * static_cast<double>(in.growth));
    const mesh::DistanceLevel& level =
        variant.levels[mesh::levelFor(variant.levels, cameraDistance / s)];
    tree.mesh = level.mesh;
    tree.meshCameraDistance = level.distance * s;
}

/// The tree's skeleton before its branch edits and adaptation.
std::shared_ptr<const skel::Skeleton> treeSkeleton(ForestTree& tree, const TreeStage& stage,
                                                   std::size_t index, std::int64_t fromVariant,
                                                   const graph::TreeContext& ctx, bool edited,
                                                   std::uint64_t grownKey,
                                                   graph::Evaluator& evaluator) {
    const placement::Instance& in = tree.instance;
    const SpeciesPlan& plan = stage.plans[in.species];
    TreeCache* cache = stage.options.cache;
    if (plan.stand) return stage.standGrown[index];
    if (fromVariant >= 0)
        return stage.variants.variants[static_cast<std::size_t>(fromVariant)].skeleton;
    // Only its branch edits changed: the tree as grown is kept, the edits are applied to it
    // again (a hand edit on screen at once, issue 43).
    if (edited && cache && plan.seedOnly)
        if (std::shared_ptr<const skel::Skeleton> kept = cache->findGrown(grownKey)) return kept;
    const graph::NodeOutput& grown =
        evaluator.evaluateTree(in.seed, ctx, noProgress(), plan.skeletonNode);
    if (cache && in.handPlaced && plan.seedOnly && grown.skeleton)
        cache->storeGrown(grownKey, grown.skeleton);
    // A species' own adapt node reports what it did through its stats.
    auto stat = [&grown](const char* key) {
        auto it = grown.stats.find(key);
        return it == grown.stats.end() ? 0.0 : it->second;
    };
    tree.adapt.collidingBefore = static_cast<std::size_t>(stat("adapt_colliding_before"));
    tree.adapt.hiddenNodes = static_cast<std::size_t>(stat("adapt_hidden_nodes"));
    return grown.skeleton;
}

/// Applies a tree's hand edits of single branches (bends are world directions).
std::shared_ptr<const skel::Skeleton> applyEdits(ForestTree& tree,
                                                 std::shared_ptr<const skel::Skeleton> skeleton,
                                                 const std::vector<skel::BranchEdit>& edits,
                                                 const glm::mat4& transform) {
    std::vector<skel::BranchEdit> local = edits;
    const glm::mat3 toLocal = glm::inverse(glm::mat3(transform));
    for (skel::BranchEdit& e : local)
        if (e.bend) e.bend = toLocal * *e.bend;
    skel::Skeleton edited = *skeleton;
    tree.branchEdits = skel::applyBranchEdits(edited, local);
    return std::make_shared<const skel::Skeleton>(std::move(edited));
}

/// Meshes the tree's skeleton at its camera distance, dropping the leaf cards that would touch
/// an obstacle.
void meshTree(ForestTree& tree, const TreeStage& stage, const graph::TreeContext& ctx,
              const std::shared_ptr<const skel::Skeleton>& skeleton) {
    const placement::Instance& in = tree.instance;
    const ForestOptions& options = stage.options;
    const env::ObstacleScene& obstacles = stage.obstacles;
    mesh::TreeMeshSettings settings = stage.plans[in.species].meshSettings;
    settings.seed = mixSeed(in.seed, salt::kTreeMesh);
    if (in.season >= 0) settings.season = static_cast<mesh::Season>(in.season);
    tree.meshSettings = std::make_shared<const mesh::TreeMeshSettings>(settings);
    if (options.useLod) {
        tree.meshCameraDistance = ctx.cameraDistance;
        settings.useLod = true;
        // LOD bands are in world metres; the mesh is built in the tree's frame.
        settings.cameraDistance = ctx.cameraDistance;
        settings.hasCamera = true;
        settings.cameraLocal =
            glm::vec3(glm::inverse(ctx.transform) * glm::vec4(stage.scene.camera, 1.0f));
    }
    if ((options.useLod || settings.leafClusterSize > 1) && options.adapt && !obstacles.empty())
        settings.acceptLeafCard = [&obstacles, &ctx, &skeleton](const skel::Leaf& leaf) {
            const bool onNode =
                leaf.node >= 0 && static_cast<std::size_t>(leaf.node) < skeleton->size();
            const glm::vec3 stem =
                onNode ? skeleton->position[static_cast<std::size_t>(leaf.node)] : leaf.position;
            return !env::leafCardTouches(obstacles, ctx.transform, leaf, stem, ctx.leafScale,
                                         ctx.leafAspect);
        };
    if (options.windData) settings.tubes.nodeIds = true;
    tree.mesh = std::make_shared<const mesh::Mesh>(mesh::buildTreeMesh(*skeleton, settings));
}

} // namespace

ForestTree buildTree(const TreeStage& stage, std::size_t index, Workers& workers,
                     std::size_t thread) {
    const ForestScene& scene = stage.scene;
    const ForestOptions& options = stage.options;
    const env::ObstacleScene& obstacles = stage.obstacles;
    const placement::Instance& in = stage.placed.instances[index];
    const SceneSpecies& species = scene.species[in.species];
    const SpeciesPlan& plan = stage.plans[in.species];
    ForestTree tree;
    tree.instance = in;
    tree.name = species.name + "_" + std::to_string(in.id);

    std::vector<env::CrownVolume> near;
    if (options.neighbours && plan.adaptsToNeighbours) near = stage.neighbours.around(index);
    graph::TreeContext ctx;
    ctx.transform = in.transform();
    ctx.obstacles = options.adapt ? &obstacles : nullptr;
    ctx.neighbours = near.data();
    ctx.neighbourCount = near.size();
    ctx.lightDirection = scene.lightDirection;
    ctx.cameraDistance = glm::length(scene.camera - in.position);
    ctx.leafScale = static_cast<float>(plan.meshSettings.leafCards.sizeScale);
    ctx.leafAspect = static_cast<float>(plan.meshSettings.leafCards.aspect);
    ctx.key = in.id + 1;

    // A domain tree nothing would adapt (no obstacle near its variant, no neighbour's crown
    // core in its own, as adaptation sees them) shows one of its species' variants, picked by
    // its seed. Hand-placed trees are the artist's own: always grown from their seed. A tree in
    // a season of its own is grown as itself too (the variants are grown in the scene's
    // season).
    const bool ownSeason =
        in.season >= 0 && static_cast<mesh::Season>(in.season) != plan.meshSettings.season;
    // A hand-placed tree's hand edits of single branches (never an instance).
    const std::vector<skel::BranchEdit>* edits = nullptr;
    if (in.handPlaced)
        if (auto e = scene.branchEdits.find(in.id);
            e != scene.branchEdits.end() && !e->second.empty())
            edits = &e->second;
    const bool hasVariants = stage.variants.first[in.species] >= 0 && !in.handPlaced && !edits;
    const std::size_t v = hasVariants ? stage.variants.pick(in.species, in.seed) : 0;
    const bool clearOfObstacles =
        hasVariants && !touchesObstacles(obstacles, in, stage.variants.extents[v]);
    if (hasVariants && near.empty() && !ownSeason && clearOfObstacles) {
        showVariant(tree, stage, v, ctx.cameraDistance);
        return tree;
    }

    // Adapted from its variant (see ForestOptions::adaptVariants): the species' growth sees
    // neither obstacles nor neighbours, so only adaptation and meshing are this tree's own.
    const bool fromVariant = hasVariants && options.adaptVariants && plan.seedOnly;
    if (fromVariant) tree.adaptedFrom = static_cast<std::int32_t>(v);

    TreeCache* cache = plan.cached ? options.cache : nullptr;
    std::uint64_t cacheKey = 0, grownKey = 0;
    if (cache) {
        cacheKey = treeKey(plan.cacheKey, in, near, scene, options, ctx.cameraDistance, edits);
        grownKey = treeKey(plan.cacheKey, in, near, scene, options, ctx.cameraDistance, nullptr);
        if (fromVariant) cacheKey = mixSeed(cacheKey, stage.variants.variants[v].seed);
        if (std::optional<ForestTree> cached = cache->findTree(cacheKey)) {
            tree = std::move(*cached);
            // Its skeleton as grown stays at hand for its next branch edit.
            if (in.handPlaced && plan.seedOnly && tree.grown)
                cache->storeGrown(grownKey, tree.grown);
            tree.name = species.name + "_" + std::to_string(in.id);
            return tree;
        }
    }

    auto t = Clock::now();
    std::shared_ptr<const skel::Skeleton> skeleton =
        treeSkeleton(tree, stage, index, fromVariant ? static_cast<std::int64_t>(v) : -1, ctx,
                     edits != nullptr, grownKey, workers.evaluator(thread, in.species));
    if (!skeleton) throw InvalidInput("species '" + species.name + "' produced no skeleton");
    if (options.keepGrown) tree.grown = skeleton;
    // After growth, before adaptation.
    if (edits) skeleton = applyEdits(tree, std::move(skeleton), *edits, ctx.transform);
    workers.generateMs[thread] += msSince(t);

    if (options.adapt && plan.forestAdapts && (!obstacles.empty() || !near.empty())) {
        t = Clock::now();
        env::AdaptParams params;
        params.lightDirection = scene.lightDirection;
        params.leafScale = ctx.leafScale;
        params.leafAspect = ctx.leafAspect;
        const std::vector<float> bark = mesh::tubeRadii(*skeleton, plan.meshSettings.tubes);
        params.barkRadii = bark;
        if (!plan.adaptsToNeighbours) params.maxBend = 0.0f;
        env::AdaptResult adapted =
            env::adaptTree(*skeleton, obstacles, ctx.transform, params, near);
        tree.adapt = adapted.stats;
        skeleton = std::make_shared<const skel::Skeleton>(std::move(adapted.skeleton));
        workers.adaptMs[thread] += msSince(t);
        // A variant whose branches reach no neighbour's crown core (the cylinder test above is
        // coarse: crowns are not solid cylinders) and that no obstacle is near is not changed
        // by adaptation: the tree touches nothing and is an instance. Obstacles keep a tree
        // unique: the variant's merged leaf clusters are not checked against them.
        if (fromVariant && clearOfObstacles && !ownSeason && tree.adapt.collidingBefore == 0 &&
            tree.adapt.droppedLeaves == 0) {
            showVariant(tree, stage, v, ctx.cameraDistance);
            tree.instanceChecked = true;
            if (cacheKey) cache->storeTree(cacheKey, tree);
            return tree;
        }
    }

    tree.skeleton = skeleton;
    tree.metrics = forest::measureTree(*skeleton, plan.wood, in.scale * in.growth);
    if (!options.buildMeshes) {
        tree.mesh = std::make_shared<const mesh::Mesh>();
    } else {
        t = Clock::now();
        meshTree(tree, stage, ctx, skeleton);
        workers.meshMs[thread] += msSince(t);
    }
    if (cacheKey) cache->storeTree(cacheKey, tree);
    return tree;
}

} // namespace sylva::forest::build
