#include "engine/forest/forestbuild.h"

#include "engine/forest/treecache.h"
#include "engine/growth/selforganizing.h"
#include "engine/mesh/lod.h"
#include "engine/nodes/meshnodes.h"
#include "engine/nodes/selforganizingnode.h"
#include "engine/util/error.h"
#include "engine/util/random.h"
#include "engine/util/seedsalts.h"
#include "engine/wind/windelements.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <exception>
#include <limits>
#include <unordered_map>

#include <omp.h>

namespace sylva::forest {

namespace {

using Clock = std::chrono::steady_clock;

double msSince(Clock::time_point t) {
    return std::chrono::duration<double, std::milli>(Clock::now() - t).count();
}

/// What the builder needs to know about one species' graph.
struct SpeciesPlan {
    const graph::NodeDesc* meshNode = nullptr; ///< the output node
    std::string skeletonNode;                  ///< its input: yields the (adapted) skeleton
    bool hasAdaptNode = false;
    bool selfOrganizing = false; ///< grows with the scene's other such trees in one stand
    CrownShape crown;
    forest::WoodProperties wood;
};

SpeciesPlan planSpecies(const SceneSpecies& s) {
    SpeciesPlan plan;
    const graph::SpeciesGraph& g = s.graph;
    plan.meshNode = graph::meshOutput(g);
    if (!plan.meshNode)
        throw InvalidInput("species '" + s.name +
                           "': a forest needs the species' output node to be a tube_mesh with "
                           "one input (the skeleton)");
    plan.skeletonNode = g.skeletonSource();
    for (const graph::NodeDesc& n : g.nodes)
        plan.hasAdaptNode = plan.hasAdaptNode || graph::roleOf(n.type) == graph::NodeRole::Adapt;
    const graph::NodeDesc* grow = g.findNode(plan.skeletonNode);
    plan.selfOrganizing = grow && grow->type == "self_organizing";
    plan.wood.densityKgM3 = g.traits.woodDensity;
    plan.wood.carbonFraction = g.traits.carbonFraction;
    return plan;
}

/// Uniform grid over the instances' ground positions, for neighbour look-ups.
class NeighbourGrid {
public:
    NeighbourGrid(const std::vector<env::CrownVolume>& crowns, float cell)
        : mCrowns(crowns), mCell(cell) {
        for (std::size_t i = 0; i < crowns.size(); ++i)
            mCells[key(crowns[i].base)].push_back(static_cast<std::uint32_t>(i));
    }
    /// Crowns other than \p self whose cylinders overlap its cylinder, in instance order.
    std::vector<env::CrownVolume> around(std::size_t self) const {
        const env::CrownVolume& c = mCrowns[self];
        std::vector<std::uint32_t> found;
        const auto cx = static_cast<long long>(std::floor(c.base.x / mCell));
        const auto cz = static_cast<long long>(std::floor(c.base.z / mCell));
        for (long long dx = -1; dx <= 1; ++dx)
            for (long long dz = -1; dz <= 1; ++dz) {
                auto it = mCells.find(pack(cx + dx, cz + dz));
                if (it == mCells.end()) continue;
                for (std::uint32_t j : it->second) {
                    if (j == self) continue;
                    const env::CrownVolume& o = mCrowns[j];
                    const float d =
                        glm::length(glm::vec2(o.base.x - c.base.x, o.base.z - c.base.z));
                    if (d < o.radius + c.radius) found.push_back(j);
                }
            }
        std::sort(found.begin(), found.end());
        std::vector<env::CrownVolume> out;
        out.reserve(found.size());
        for (std::uint32_t j : found)
            out.push_back(mCrowns[j]);
        return out;
    }

private:
    static std::uint64_t pack(long long x, long long z) {
        return (static_cast<std::uint64_t>(x) << 32) ^
               (static_cast<std::uint64_t>(z) & 0xFFFFFFFFull);
    }
    std::uint64_t key(const glm::vec3& p) const {
        return pack(static_cast<long long>(std::floor(p.x / mCell)),
                    static_cast<long long>(std::floor(p.z / mCell)));
    }
    const std::vector<env::CrownVolume>& mCrowns;
    float mCell;
    std::unordered_map<std::uint64_t, std::vector<std::uint32_t>> mCells;
};

constexpr float kNeighbourCore = 0.5f;

/// The cache key of one tree (see TreeCache): everything buildTree's result depends on.
std::uint64_t treeKey(std::uint64_t species, const placement::Instance& in,
                      const std::vector<env::CrownVolume>& near, const ForestScene& scene,
                      const ForestOptions& options, double cameraDistance,
                      const std::vector<skel::BranchEdit>* edits) {
    std::uint64_t h = mixSeed(species, options.obstaclesKey);
    auto mix = [&h](const void* data, std::size_t n) {
        const auto* p = static_cast<const unsigned char*>(data);
        for (std::size_t i = 0; i < n; ++i)
            h = (h ^ p[i]) * 0x100000001b3ull;
    };
    auto pod = [&mix](const auto& v) { mix(&v, sizeof v); };
    pod(in.id);
    pod(in.position);
    pod(in.rotation);
    pod(in.scale);
    pod(in.growth);
    pod(in.seed);
    pod(in.handPlaced);
    pod(in.season);
    const int season = scene.season ? static_cast<int>(*scene.season) : -1;
    pod(season);
    for (const env::CrownVolume& c : near) {
        pod(c.base);
        pod(c.radius);
        pod(c.bottom);
        pod(c.top);
    }
    pod(scene.lightDirection);
    if (options.useLod) pod(cameraDistance);
    if (edits)
        for (const skel::BranchEdit& e : *edits) {
            mix(e.branch.data(), e.branch.size() + 1);
            const glm::vec3 bend = e.bend.value_or(glm::vec3(0.0f));
            const bool bits[] = {e.prune, e.bend.has_value(), e.lock};
            mix(bits, sizeof bits);
            pod(bend);
            pod(e.length);
            pod(e.radius);
            // Where an anchored edit goes, and what a locked one puts back, are its result too.
            const bool anchored = e.anchor.has_value();
            pod(anchored);
            if (e.anchor) {
                pod(e.anchor->base);
                pod(e.anchor->direction);
                pod(e.anchor->length);
            }
            pod(e.lockedBase);
            for (const skel::LockedNode& n : e.locked) {
                pod(n.parent);
                pod(n.order);
                pod(n.radius);
                pod(n.offset);
                pod(n.orientation);
            }
            for (const skel::LockedLeaf& l : e.lockedLeaves) {
                pod(l.node);
                pod(l.size);
                pod(l.offset);
                pod(l.orientation);
            }
        }
    const bool flags[] = {options.useLod,
                          options.adapt,
                          options.neighbours,
                          options.buildMeshes,
                          scene.obstacles != nullptr,
                          options.windData};
    if (options.keepGrown) h = mixSeed(h, 0x6b67); // cached trees then carry their grown skeleton
    mix(flags, sizeof flags);
    return h;
}

/// 64-bit FNV-1a of a name: variant seeds follow the species' name, not its place in the list.
std::uint64_t nameHash(const std::string& name) {
    std::uint64_t h = 0xcbf29ce484222325ull;
    for (unsigned char c : name)
        h = (h ^ c) * 0x100000001b3ull;
    return h;
}

/// A variant's extent in its own frame: the vertical cylinder about the local y axis that holds
/// its bark (tube_mesh's ring radii) and its leaf cards.
struct Extent {
    float radius = 0.0f, bottom = 0.0f, top = 0.0f;
};

Extent variantExtent(const skel::Skeleton& s, const mesh::TreeMeshSettings& settings) {
    Extent e;
    if (s.empty()) return e;
    e.bottom = std::numeric_limits<float>::max();
    e.top = -e.bottom;
    auto add = [&e](const glm::vec3& p, float r) {
        e.radius = std::max(e.radius, glm::length(glm::vec2(p.x, p.z)) + r);
        e.bottom = std::min(e.bottom, p.y - r);
        e.top = std::max(e.top, p.y + r);
    };
    const std::vector<float> rings = mesh::tubeRadii(s, settings.tubes);
    for (std::size_t i = 0; i < s.size(); ++i)
        add(s.position[i], i < rings.size() ? rings[i] : s.radius[i]);
    // A card is leafScale·size long and aspect times as wide from its anchor: its far corner
    // is within length·(1 + aspect).
    const auto cardScale = static_cast<float>(settings.leafCards.sizeScale *
                                              (1.0 + std::abs(settings.leafCards.aspect)));
    for (const skel::Leaf& leaf : s.leaves)
        add(leaf.position, leaf.size * cardScale);
    return e;
}

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

const env::ObstacleScene& emptyScene() {
    static const env::ObstacleScene scene;
    return scene;
}

} // namespace

CrownShape measureCrown(const graph::SpeciesGraph& species, std::uint64_t seed,
                        const mesh::TubeSettings* tubes) {
    graph::Evaluator evaluator(species);
    const graph::NodeOutput& result = evaluator.evaluateNode(species.skeletonSource(), true, seed);
    CrownShape crown;
    if (!result.skeleton || result.skeleton->empty()) return crown;
    const skel::Skeleton& s = *result.skeleton;
    float radius = 0.0f, top = 0.0f, bottom = std::numeric_limits<float>::max();
    const glm::vec3 root = s.position[0];
    for (std::size_t i = 0; i < s.size(); ++i) {
        const glm::vec3 d = s.position[i] - root;
        radius = std::max(radius, glm::length(glm::vec2(d.x, d.z)));
        top = std::max(top, d.y);
        if (s.order[i] > 0) bottom = std::min(bottom, d.y);
    }
    const std::vector<float> rings = tubes ? mesh::tubeRadii(s, *tubes) : s.radius;
    for (std::size_t i = 0; i < s.size(); ++i)
        if (i == 0 || s.parent[i] == 0) crown.trunk = std::max(crown.trunk, rings[i]);
    crown.radius = std::max(radius, 0.05f);
    crown.top = std::max(top, 0.05f);
    crown.bottom =
        bottom == std::numeric_limits<float>::max() ? 0.5f * crown.top : std::max(bottom, 0.0f);
    if (species.traits.crownRadius > 0)
        crown.radius = static_cast<float>(species.traits.crownRadius);
    return crown;
}

ForestStats buildForest(const ForestScene& scene, const ForestOptions& options,
                        const TreeSink& sink, Progress& progress) {
    if (scene.species.empty()) throw InvalidInput("the scene has no species");
    requireRange("tile count", options.tileCount, 1, 1e6);
    requireRange("tile", options.tile, 0, options.tileCount - 1);
    ForestStats stats;

    // 1. Species: graphs checked, crowns measured once on a sample tree.
    auto t0 = Clock::now();
    std::vector<SpeciesPlan> plans;
    std::vector<placement::SpeciesSpec> specs;
    std::vector<std::uint64_t> speciesKeys;
    if (options.cache) options.cache->beginBuild();
    for (std::size_t i = 0; i < scene.species.size(); ++i) {
        plans.push_back(planSpecies(scene.species[i]));
        const std::uint64_t crownSeed = mixSeed(scene.seed, salt::kCrownSample + i);
        speciesKeys.push_back(options.cache ? speciesHash(scene.species[i].graph) : 0);
        const std::uint64_t crownKey = mixSeed(speciesKeys.back(), crownSeed);
        std::optional<CrownShape> cached;
        if (options.cache) cached = options.cache->findCrown(crownKey);
        const mesh::TubeSettings tubes =
            mesh::treeMeshSettingsFromParams(plans.back().meshNode->params, 0).tubes;
        plans.back().crown =
            cached ? *cached : measureCrown(scene.species[i].graph, crownSeed, &tubes);
        if (options.cache && !cached) options.cache->storeCrown(crownKey, plans.back().crown);
        // Trunks vary from tree to tree: placement keeps half again the sample's bark radius
        // from obstacles (adaptation cannot move a root whose bark starts inside one).
        specs.push_back({scene.species[i].name, plans.back().crown.radius,
                         std::min(1.5f * plans.back().crown.trunk, 1e3f)});
    }
    stats.wallMs["species"] = msSince(t0);

    // 2. Placement over the whole scene, then the tile.
    t0 = Clock::now();
    placement::PlacementParams placement;
    placement.seed = scene.seed;
    placement.ground = scene.ground.get();
    placement.obstacles = scene.obstacles.get();
    placement::PlacementResult placed = placement::placeForest(
        specs, scene.domains, scene.handPlaced, placement, options.placement);
    stats.shortfalls = placed.shortfalls;
    stats.treesInScene = placed.instances.size();
    std::vector<std::size_t> selected;
    if (options.tileCount > 1) {
        const placement::TileGrid grid =
            placement::makeTileGrid(scene.domains, scene.handPlaced, options.tileCount);
        for (std::size_t i = 0; i < placed.instances.size(); ++i)
            if (placement::tileOf(grid, placed.instances[i].position) == options.tile)
                selected.push_back(i);
    } else {
        selected.resize(placed.instances.size());
        for (std::size_t i = 0; i < selected.size(); ++i)
            selected[i] = i;
    }
    stats.trees = selected.size();

    // Every tree's crown, for its neighbours (computed over the whole scene so tiles agree).
    std::vector<env::CrownVolume> crowns(placed.instances.size());
    float maxRadius = 0.1f;
    for (std::size_t i = 0; i < crowns.size(); ++i) {
        const placement::Instance& in = placed.instances[i];
        const CrownShape& c = plans[in.species].crown;
        const float s = in.scale * in.growth;
        // A neighbour blocks with the dense core of its crown only: placement lets crowns
        // overlap at their rims (as in the reference), and treating the whole crown cylinder as
        // solid pruned ~40 % of a dense forest.
        crowns[i] = {in.position, kNeighbourCore * c.radius * s, c.bottom * s, c.top * s};
        maxRadius = std::max(maxRadius, crowns[i].radius);
    }
    const NeighbourGrid neighbourGrid(crowns, 2.0f * maxRadius);
    stats.wallMs["place"] = msSince(t0);

    // Self-organizing trees of the whole scene (all tiles, so tiles agree) grow together in one
    // shared environment per environment kind: they compete for light and space, and the
    // obstacles cast shadow and block markers. They stand upright at their placed position;
    // their size comes from the competition, not from placement's scale and growth stage.
    t0 = Clock::now();
    std::vector<std::shared_ptr<const skel::Skeleton>> standGrown(placed.instances.size());
    {
        std::vector<glm::vec3> obstacleTriangles;
        if (scene.obstacles)
            for (const env::ObstacleMesh& m : scene.obstacles->meshes())
                for (const glm::uvec3& t : m.triangles)
                    for (int k = 0; k < 3; ++k)
                        obstacleTriangles.push_back(m.vertices[t[k]]);
        std::map<int, std::vector<std::size_t>> stands; // environment kind → instances
        std::vector<growth::StandTree> standTrees(placed.instances.size());
        for (std::size_t i = 0; i < placed.instances.size(); ++i) {
            placement::Instance& in = placed.instances[i];
            const SpeciesPlan& plan = plans[in.species];
            if (!plan.selfOrganizing) continue;
            const graph::SpeciesGraph& g = scene.species[in.species].graph;
            standTrees[i].params =
                growth::selfOrganizingParamsFrom(g.findNode(plan.skeletonNode)->params);
            standTrees[i].position = in.position;
            standTrees[i].seed = in.seed;
            in.rotation = 0.0f;
            in.scale = 1.0f;
            in.growth = 1.0f;
            stands[static_cast<int>(standTrees[i].params.environment)].push_back(i);
        }
        for (const auto& [kind, members] : stands) {
            std::vector<growth::StandTree> trees;
            for (std::size_t i : members)
                trees.push_back(standTrees[i]);
            std::vector<skel::Skeleton> grown =
                growth::growStand(trees, obstacleTriangles, progress);
            for (std::size_t k = 0; k < members.size(); ++k)
                standGrown[members[k]] =
                    std::make_shared<const skel::Skeleton>(std::move(grown[k]));
        }
    }
    stats.wallMs["stand"] = msSince(t0);

    // 3. Trees, in parallel batches handed on in order.
    t0 = Clock::now();
    const int threads = std::max(1, omp_get_max_threads());
    std::vector<std::vector<std::unique_ptr<graph::Evaluator>>> evaluators(
        static_cast<std::size_t>(threads));
    for (auto& perThread : evaluators)
        for (const SceneSpecies& s : scene.species)
            perThread.push_back(std::make_unique<graph::Evaluator>(s.graph));
    std::vector<mesh::TreeMeshSettings> meshSettings;
    for (const SpeciesPlan& plan : plans)
        meshSettings.push_back(mesh::treeMeshSettingsFromParams(
            plan.meshNode->params, 0, scene.species[meshSettings.size()].graph.baseDir));
    if (scene.season)
        for (mesh::TreeMeshSettings& settings : meshSettings)
            settings.season = *scene.season;

    const env::ObstacleScene& obstacles = scene.obstacles ? *scene.obstacles : emptyScene();
    std::vector<double> cpuGenerate(static_cast<std::size_t>(threads), 0.0), cpuAdapt(cpuGenerate),
        cpuMesh(cpuGenerate);

    // Variants: K per species with a domain tree in the tile that can be instanced (not
    // self-organizing), grown at full growth in their own frame, never adapted, meshed at full
    // detail (they are seen at every distance). Listed by species, then index; firstVariant[s]
    // is species s's first.
    std::vector<ForestVariant> variants;
    std::vector<std::int32_t> firstVariant(scene.species.size(), -1);
    std::vector<std::uint32_t> variantCount(scene.species.size(), 0);
    std::vector<Extent> extents;
    std::vector<forest::SkeletonMeasure> measures; ///< per variant: its instances' metrics
    if (options.instancing) {
        requireRange("variants per species", options.variantsPerSpecies, 1, 256);
        // Only species with a domain tree in the tile: hand-placed trees are always grown
        // from their own seed and never show (nor start from) a variant, so a project of
        // hand-placed trees grows none (library.sylva: 96 variants, 20x its trees' time).
        std::vector<bool> used(scene.species.size(), false);
        for (std::size_t index : selected)
            if (!placed.instances[index].handPlaced) used[placed.instances[index].species] = true;
        for (std::size_t sp = 0; sp < scene.species.size(); ++sp) {
            if (!used[sp] || plans[sp].selfOrganizing) continue;
            const int k = scene.species[sp].variants >= 0 ? scene.species[sp].variants
                                                          : options.variantsPerSpecies;
            requireRange(("variants of species '" + scene.species[sp].name + "'").c_str(), k, 0,
                         256);
            if (k == 0) continue; // a species grown tree by tree
            firstVariant[sp] = static_cast<std::int32_t>(variants.size());
            variantCount[sp] = static_cast<std::uint32_t>(k);
            const std::uint64_t base =
                mixSeed(mixSeed(scene.seed, salt::kVariant), nameHash(scene.species[sp].name));
            for (int v = 0; v < k; ++v) {
                ForestVariant variant;
                variant.species = static_cast<std::uint32_t>(sp);
                variant.index = static_cast<std::uint32_t>(v);
                variant.name = scene.species[sp].name + "_v" + std::to_string(v);
                variant.seed = mixSeed(base, static_cast<std::uint64_t>(v));
                variants.push_back(std::move(variant));
            }
        }
        std::vector<std::exception_ptr> errors(variants.size());
#pragma omp parallel for schedule(dynamic, 1) num_threads(threads)
        for (std::ptrdiff_t k = 0; k < static_cast<std::ptrdiff_t>(variants.size()); ++k) {
            const auto slot = static_cast<std::size_t>(k);
            const auto thread = static_cast<std::size_t>(omp_get_thread_num());
            ForestVariant& variant = variants[slot];
            try {
                progress.checkCancelled();
                // Levels only where instances are meshed per tree: writers that instance
                // (meshInstances off) take the variant mesh itself. With wind data the levels
                // carry node ids as the variant's mesh does (the wind data is derived per
                // mesh): a merged wind export draws far instances coarse too (it drew every
                // one at full detail: bench-1000 with --wind, a 7 GB OBJ).
                const bool levelsWanted = options.useLod && options.meshInstances;
                std::uint64_t cacheKey = 0;
                if (options.cache) {
                    cacheKey = mixSeed(mixSeed(speciesKeys[variant.species], variant.seed),
                                       (options.buildMeshes ? (levelsWanted ? 0x4C : 0x4D) : 0x53) +
                                           (options.windData ? 0x100 : 0));
                    cacheKey = mixSeed(
                        cacheKey, static_cast<std::uint64_t>(meshSettings[variant.species].season));
                    if (std::optional<ForestVariant> cached =
                            options.cache->findVariant(cacheKey)) {
                        variant = std::move(*cached);
                        continue;
                    }
                }
                const SpeciesPlan& plan = plans[variant.species];
                graph::TreeContext ctx;
                ctx.lightDirection = scene.lightDirection;
                ctx.leafScale =
                    static_cast<float>(meshSettings[variant.species].leafCards.sizeScale);
                ctx.leafAspect = static_cast<float>(meshSettings[variant.species].leafCards.aspect);
                // Tree ids never reach 2^63: these keys are the variants' own.
                ctx.key = ~static_cast<std::uint64_t>(slot);
                auto t = Clock::now();
                const graph::NodeOutput& grown = evaluators[thread][variant.species]->evaluateTree(
                    variant.seed, ctx, noProgress(), plan.skeletonNode);
                if (!grown.skeleton)
                    throw InvalidInput("species '" + scene.species[variant.species].name +
                                       "' produced no skeleton");
                variant.skeleton = grown.skeleton;
                variant.metrics = forest::measureTree(*variant.skeleton, plan.wood, 1.0f);
                cpuGenerate[thread] += msSince(t);
                if (options.buildMeshes) {
                    t = Clock::now();
                    mesh::TreeMeshSettings settings = meshSettings[variant.species];
                    settings.seed = mixSeed(variant.seed, salt::kTreeMesh);
                    variant.meshSettings = std::make_shared<const mesh::TreeMeshSettings>(settings);
                    // With wind data the mesh keeps its vertices' nodes; the wind writer
                    // derives the per-vertex channels from them (wind::addWindData).
                    if (options.windData) settings.tubes.nodeIds = true;
                    variant.mesh = std::make_shared<const mesh::Mesh>(
                        mesh::buildTreeMesh(*variant.skeleton, settings));
                    if (levelsWanted)
                        variant.levels =
                            mesh::buildDistanceLevels(*variant.skeleton, settings, variant.mesh);
                    cpuMesh[thread] += msSince(t);
                } else {
                    variant.mesh = std::make_shared<const mesh::Mesh>();
                }
                if (cacheKey) options.cache->storeVariant(cacheKey, variant);
            } catch (...) {
                errors[slot] = std::current_exception();
            }
        }
        for (const std::exception_ptr& e : errors)
            if (e) std::rethrow_exception(e);
        for (const ForestVariant& v : variants) {
            extents.push_back(variantExtent(*v.skeleton, meshSettings[v.species]));
            measures.push_back(forest::prepareMeasure(*v.skeleton));
        }
    }
    stats.variants = variants.size();
    if (options.onVariants) options.onVariants(variants);
    stats.wallMs["variants"] = msSince(t0);
    t0 = Clock::now();

    const std::size_t batchSize = std::max<std::size_t>(1, options.batchSize);
    for (std::size_t begin = 0; begin < selected.size(); begin += batchSize) {
        progress.checkCancelled();
        const std::size_t end = std::min(selected.size(), begin + batchSize);
        std::vector<ForestTree> batch(end - begin);
        std::vector<std::exception_ptr> errors(end - begin);
#pragma omp parallel for schedule(dynamic, 1) num_threads(threads)
        for (std::ptrdiff_t k = 0; k < static_cast<std::ptrdiff_t>(end - begin); ++k) {
            // Ctrl-C/SIGTERM: the trees not started are skipped, the batch ends with the trees
            // in flight and checkCancelled() below throws (a batch of 64 takes seconds).
            if (progress.isCancelled()) continue;
            const auto slot = static_cast<std::size_t>(k);
            const std::size_t index = selected[begin + slot];
            const auto thread = static_cast<std::size_t>(omp_get_thread_num());
            try {
                const placement::Instance& in = placed.instances[index];
                const SceneSpecies& species = scene.species[in.species];
                const SpeciesPlan& plan = plans[in.species];
                ForestTree& tree = batch[slot];
                tree.instance = in;
                tree.name = species.name + "_" + std::to_string(in.id);

                std::vector<env::CrownVolume> near;
                if (options.neighbours) near = neighbourGrid.around(index);
                graph::TreeContext ctx;
                ctx.transform = in.transform();
                ctx.obstacles = options.adapt ? &obstacles : nullptr;
                ctx.neighbours = near.data();
                ctx.neighbourCount = near.size();
                ctx.lightDirection = scene.lightDirection;
                ctx.cameraDistance = glm::length(scene.camera - in.position);
                ctx.leafScale = static_cast<float>(meshSettings[in.species].leafCards.sizeScale);
                ctx.leafAspect = static_cast<float>(meshSettings[in.species].leafCards.aspect);
                ctx.key = in.id + 1;

                // A domain tree nothing would adapt (no obstacle near its variant, no
                // neighbour's crown core in its own, as adaptation sees them) shows one of its
                // species' variants, picked by its seed. Hand-placed trees are the artist's
                // own: always grown from their seed. A tree in a season of its own is grown as
                // itself too (the variants are grown in the scene's season).
                const bool ownSeason = in.season >= 0 && static_cast<mesh::Season>(in.season) !=
                                                             meshSettings[in.species].season;
                // A hand-placed tree's hand edits of single branches (never an instance).
                const std::vector<skel::BranchEdit>* edits = nullptr;
                if (in.handPlaced)
                    if (auto e = scene.branchEdits.find(in.id);
                        e != scene.branchEdits.end() && !e->second.empty())
                        edits = &e->second;
                const bool hasVariants = firstVariant[in.species] >= 0 && !in.handPlaced && !edits;
                const std::size_t v =
                    hasVariants
                        ? static_cast<std::size_t>(firstVariant[in.species]) +
                              mixSeed(in.seed, salt::kVariantPick) % variantCount[in.species]
                        : 0;
                // Shows variant v: its skeleton and settings shared, its mesh the variant's or
                // the variant's level for this tree's size on screen.
                auto showVariant = [&]() {
                    const ForestVariant& variant = variants[v];
                    tree.variant = static_cast<std::int32_t>(v);
                    tree.adaptedFrom = -1;
                    tree.instanceChecked = false;
                    tree.skeleton = variant.skeleton;
                    if (options.keepGrown) tree.grown = variant.skeleton;
                    tree.meshSettings = variant.meshSettings;
                    tree.metrics =
                        forest::measureTree(measures[v], plan.wood, in.scale * in.growth);
                    if (!options.useLod || !options.buildMeshes || !options.meshInstances ||
                        variant.levels.empty()) {
                        tree.mesh = variant.mesh; // shared: drawn with the tree's transform
                        return;
                    }
                    // The variant's level for this tree's size on screen, made once per
                    // variant (the full-detail variant drawn 1,000 times made an OBJ 13
                    // times larger): the variant stands at scale 1, the tree at scale·growth.
                    const double s = std::max(1e-3, static_cast<double>(in.scale) *
                                                        static_cast<double>(in.growth));
                    const mesh::DistanceLevel& level =
                        variant.levels[mesh::levelFor(variant.levels, ctx.cameraDistance / s)];
                    tree.mesh = level.mesh;
                    tree.meshCameraDistance = level.distance * s;
                };
                const bool clearOfObstacles =
                    hasVariants && !touchesObstacles(obstacles, in, extents[v]);
                if (hasVariants && near.empty() && !ownSeason && clearOfObstacles) {
                    showVariant();
                    continue;
                }

                // Adapted from its variant (see ForestOptions::adaptVariants): the species'
                // growth sees neither obstacles nor neighbours, so only adaptation and meshing
                // are this tree's own.
                const bool fromVariant = hasVariants && options.adaptVariants &&
                                         !plan.hasAdaptNode && !plan.selfOrganizing;
                if (fromVariant) tree.adaptedFrom = static_cast<std::int32_t>(v);

                std::uint64_t cacheKey = 0, grownKey = 0;
                if (options.cache && !plan.selfOrganizing) {
                    cacheKey = treeKey(speciesKeys[in.species], in, near, scene, options,
                                       ctx.cameraDistance, edits);
                    grownKey = treeKey(speciesKeys[in.species], in, near, scene, options,
                                       ctx.cameraDistance, nullptr);
                    if (fromVariant) cacheKey = mixSeed(cacheKey, variants[v].seed);
                    if (std::optional<ForestTree> cached = options.cache->findTree(cacheKey)) {
                        tree = std::move(*cached);
                        // Its skeleton as grown stays at hand for its next branch edit.
                        if (in.handPlaced && !plan.selfOrganizing && !plan.hasAdaptNode &&
                            tree.grown)
                            options.cache->storeGrown(grownKey, tree.grown);
                        tree.name = species.name + "_" + std::to_string(in.id);
                        continue;
                    }
                }

                auto t = Clock::now();
                graph::Evaluator& evaluator = *evaluators[thread][in.species];
                std::shared_ptr<const skel::Skeleton> skeleton;
                if (plan.selfOrganizing) {
                    skeleton = standGrown[index];
                } else if (fromVariant) {
                    skeleton = variants[v].skeleton;
                } else if (std::shared_ptr<const skel::Skeleton> kept =
                               edits && options.cache && !plan.hasAdaptNode
                                   ? options.cache->findGrown(grownKey)
                                   : nullptr) {
                    // Only its branch edits changed: the tree as grown is kept, the edits are
                    // applied to it again (a hand edit on screen at once, issue 43).
                    skeleton = std::move(kept);
                } else {
                    const graph::NodeOutput& grown =
                        evaluator.evaluateTree(in.seed, ctx, noProgress(), plan.skeletonNode);
                    skeleton = grown.skeleton;
                    if (options.cache && in.handPlaced && !plan.hasAdaptNode && skeleton)
                        options.cache->storeGrown(grownKey, skeleton);
                    // A species' own adapt node reports what it did through its stats.
                    auto stat = [&](const char* key) {
                        auto it = grown.stats.find(key);
                        return it == grown.stats.end() ? 0.0 : it->second;
                    };
                    tree.adapt.collidingBefore =
                        static_cast<std::size_t>(stat("adapt_colliding_before"));
                    tree.adapt.hiddenNodes = static_cast<std::size_t>(stat("adapt_hidden_nodes"));
                }
                if (!skeleton)
                    throw InvalidInput("species '" + species.name + "' produced no skeleton");
                if (options.keepGrown) tree.grown = skeleton;
                if (edits) {
                    // After growth, before adaptation; bends are world directions.
                    std::vector<skel::BranchEdit> local = *edits;
                    const glm::mat3 toLocal = glm::inverse(glm::mat3(ctx.transform));
                    for (skel::BranchEdit& e : local)
                        if (e.bend) e.bend = toLocal * *e.bend;
                    skel::Skeleton edited = *skeleton;
                    tree.branchEdits = skel::applyBranchEdits(edited, local);
                    skeleton = std::make_shared<const skel::Skeleton>(std::move(edited));
                }
                cpuGenerate[thread] += msSince(t);

                if (options.adapt && (!plan.hasAdaptNode || plan.selfOrganizing) &&
                    (!obstacles.empty() || (!near.empty() && !plan.selfOrganizing))) {
                    t = Clock::now();
                    env::AdaptParams params;
                    params.lightDirection = scene.lightDirection;
                    params.leafScale = ctx.leafScale;
                    params.leafAspect = ctx.leafAspect;
                    const std::vector<float> bark =
                        mesh::tubeRadii(*skeleton, meshSettings[in.species].tubes);
                    params.barkRadii = bark;
                    // Stand-grown trees already competed with their neighbours and grew around
                    // the obstacles: they are not bent, only cut where a shoot still went
                    // through an obstacle (their markers and shadows stop most, not all).
                    if (plan.selfOrganizing) {
                        params.maxBend = 0.0f;
                        near.clear();
                    }
                    env::AdaptResult adapted =
                        env::adaptTree(*skeleton, obstacles, ctx.transform, params, near);
                    tree.adapt = adapted.stats;
                    skeleton = std::make_shared<const skel::Skeleton>(std::move(adapted.skeleton));
                    cpuAdapt[thread] += msSince(t);
                    // A variant whose branches reach no neighbour's crown core (the cylinder
                    // test above is coarse: crowns are not solid cylinders) and that no
                    // obstacle is near is not changed by adaptation: the tree touches nothing
                    // and is an instance. Obstacles keep a tree unique: the variant's merged
                    // leaf clusters are not checked against them.
                    if (fromVariant && clearOfObstacles && !ownSeason &&
                        tree.adapt.collidingBefore == 0 && tree.adapt.droppedLeaves == 0) {
                        showVariant();
                        tree.instanceChecked = true;
                        if (cacheKey) options.cache->storeTree(cacheKey, tree);
                        continue;
                    }
                }

                tree.skeleton = skeleton;
                tree.metrics = forest::measureTree(*skeleton, plan.wood, in.scale * in.growth);
                if (!options.buildMeshes) {
                    tree.mesh = std::make_shared<const mesh::Mesh>();
                    if (cacheKey) options.cache->storeTree(cacheKey, tree);
                    continue;
                }
                t = Clock::now();
                mesh::TreeMeshSettings settings = meshSettings[in.species];
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
                        glm::vec3(glm::inverse(ctx.transform) * glm::vec4(scene.camera, 1.0f));
                }
                if ((options.useLod || settings.leafClusterSize > 1) && options.adapt &&
                    !obstacles.empty())
                    settings.acceptLeafCard = [&obstacles, &ctx,
                                               &skeleton](const skel::Leaf& leaf) {
                        const bool onNode = leaf.node >= 0 &&
                                            static_cast<std::size_t>(leaf.node) < skeleton->size();
                        const glm::vec3 stem =
                            onNode ? skeleton->position[static_cast<std::size_t>(leaf.node)]
                                   : leaf.position;
                        return !env::leafCardTouches(obstacles, ctx.transform, leaf, stem,
                                                     ctx.leafScale, ctx.leafAspect);
                    };
                if (options.windData) settings.tubes.nodeIds = true;
                tree.mesh =
                    std::make_shared<const mesh::Mesh>(mesh::buildTreeMesh(*skeleton, settings));
                cpuMesh[thread] += msSince(t);
                if (cacheKey) options.cache->storeTree(cacheKey, tree);
            } catch (...) {
                errors[slot] = std::current_exception();
            }
        }
        progress.checkCancelled();
        for (const std::exception_ptr& e : errors)
            if (e) std::rethrow_exception(e); // the first failing tree in instance order
        for (const ForestTree& tree : batch) {
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
        sink(batch);
        progress.report(static_cast<double>(end) / static_cast<double>(selected.size()), "trees");
    }
    auto sum = [](const std::vector<double>& v) {
        double s = 0;
        for (double x : v)
            s += x;
        return s;
    };
    stats.cpuMs["generate"] = sum(cpuGenerate);
    stats.cpuMs["adapt"] = sum(cpuAdapt);
    stats.cpuMs["mesh"] = sum(cpuMesh);
    stats.wallMs["trees"] = msSince(t0);
    if (options.cache) options.cache->endBuild();
    return stats;
}

} // namespace sylva::forest
