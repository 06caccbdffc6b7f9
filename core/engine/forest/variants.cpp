#include "engine/forest/variants.h"

#include "engine/forest/treecache.h"
#include "engine/mesh/treemesh.h"
#include "engine/util/error.h"
#include "engine/util/random.h"
#include "engine/util/seedsalts.h"

#include <algorithm>
#include <cmath>
#include <exception>
#include <limits>
#include <string>

#include <omp.h>

namespace sylva::forest::build {

namespace {

/// 64-bit FNV-1a of a name: variant seeds follow the species' name, not its place in the list.
std::uint64_t nameHash(const std::string& name) {
    std::uint64_t h = 0xcbf29ce484222325ull;
    for (unsigned char c : name)
        h = (h ^ c) * 0x100000001b3ull;
    return h;
}

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

/// The variants of the species that have some, listed by species, then index, without their
/// geometry yet.
VariantSet listVariants(const ForestScene& scene, const ForestOptions& options,
                        const std::vector<SpeciesPlan>& plans, const Placed& placed) {
    VariantSet set;
    set.first.assign(scene.species.size(), -1);
    set.count.assign(scene.species.size(), 0);
    if (!options.instancing) return set;
    requireRange("variants per species", options.variantsPerSpecies, 1, 256);
    // Only species with a domain tree in the tile: hand-placed trees are always grown from
    // their own seed and never show (nor start from) a variant, so a project of hand-placed
    // trees grows none (library.sylva: 96 variants, 20x its trees' time).
    std::vector<bool> used(scene.species.size(), false);
    for (std::size_t index : placed.selected)
        if (!placed.instances[index].handPlaced) used[placed.instances[index].species] = true;
    for (std::size_t sp = 0; sp < scene.species.size(); ++sp) {
        if (!used[sp] || !plans[sp].instanced) continue;
        const int k = scene.species[sp].variants >= 0 ? scene.species[sp].variants
                                                      : options.variantsPerSpecies;
        requireRange(("variants of species '" + scene.species[sp].name + "'").c_str(), k, 0, 256);
        if (k == 0) continue; // a species grown tree by tree
        set.first[sp] = static_cast<std::int32_t>(set.variants.size());
        set.count[sp] = static_cast<std::uint32_t>(k);
        const std::uint64_t base =
            mixSeed(mixSeed(scene.seed, salt::kVariant), nameHash(scene.species[sp].name));
        for (int v = 0; v < k; ++v) {
            ForestVariant variant;
            variant.species = static_cast<std::uint32_t>(sp);
            variant.index = static_cast<std::uint32_t>(v);
            variant.name = scene.species[sp].name + "_v" + std::to_string(v);
            variant.seed = mixSeed(base, static_cast<std::uint64_t>(v));
            set.variants.push_back(std::move(variant));
        }
    }
    return set;
}

/// Grows and meshes one variant (through the cache when there is one).
void growVariant(ForestVariant& variant, std::size_t slot, const ForestScene& scene,
                 const ForestOptions& options, const SpeciesPlan& plan, Workers& workers,
                 std::size_t thread) {
    // Levels only where instances are meshed per tree: writers that instance (meshInstances
    // off) take the variant mesh itself. With wind data the levels carry node ids as the
    // variant's mesh does (the wind data is derived per mesh): a merged wind export draws far
    // instances coarse too (it drew every one at full detail: bench-1000 with --wind, a 7 GB
    // OBJ).
    const bool levelsWanted = options.useLod && options.meshInstances;
    std::uint64_t cacheKey = 0;
    if (options.cache) {
        cacheKey = mixSeed(mixSeed(plan.cacheKey, variant.seed),
                           (options.buildMeshes ? (levelsWanted ? 0x4C : 0x4D) : 0x53) +
                               (options.windData ? 0x100 : 0));
        cacheKey = mixSeed(cacheKey, static_cast<std::uint64_t>(plan.meshSettings.season));
        if (std::optional<ForestVariant> cached = options.cache->findVariant(cacheKey)) {
            variant = std::move(*cached);
            return;
        }
    }
    graph::TreeContext ctx;
    ctx.lightDirection = scene.lightDirection;
    ctx.leafScale = static_cast<float>(plan.meshSettings.leafCards.sizeScale);
    ctx.leafAspect = static_cast<float>(plan.meshSettings.leafCards.aspect);
    // Tree ids never reach 2^63: these keys are the variants' own.
    ctx.key = ~static_cast<std::uint64_t>(slot);
    auto t = Clock::now();
    const graph::NodeOutput& grown =
        workers.evaluator(thread, variant.species)
            .evaluateTree(variant.seed, ctx, noProgress(), plan.skeletonNode);
    if (!grown.skeleton)
        throw InvalidInput("species '" + scene.species[variant.species].name +
                           "' produced no skeleton");
    variant.skeleton = grown.skeleton;
    variant.metrics = forest::measureTree(*variant.skeleton, plan.wood, 1.0f);
    workers.generateMs[thread] += msSince(t);
    if (options.buildMeshes) {
        t = Clock::now();
        mesh::TreeMeshSettings settings = plan.meshSettings;
        settings.seed = mixSeed(variant.seed, salt::kTreeMesh);
        variant.meshSettings = std::make_shared<const mesh::TreeMeshSettings>(settings);
        // With wind data the mesh keeps its vertices' nodes; the wind writer derives the
        // per-vertex channels from them (wind::addWindData).
        if (options.windData) settings.tubes.nodeIds = true;
        variant.mesh =
            std::make_shared<const mesh::Mesh>(mesh::buildTreeMesh(*variant.skeleton, settings));
        if (levelsWanted)
            variant.levels = mesh::buildDistanceLevels(*variant.skeleton, settings, variant.mesh);
        workers.meshMs[thread] += msSince(t);
    } else {
        variant.mesh = std::make_shared<const mesh::Mesh>();
    }
    if (cacheKey) options.cache->storeVariant(cacheKey, variant);
}

} // namespace

std::size_t VariantSet::pick(std::uint32_t species, std::uint64_t seed) const {
    return static_cast<std::size_t>(first[species]) +
           mixSeed(seed, salt::kVariantPick) % count[species];
}

VariantSet buildVariants(const ForestScene& scene, const ForestOptions& options,
                         const std::vector<SpeciesPlan>& plans, const Placed& placed,
                         Workers& workers, Progress& progress) {
    VariantSet set = listVariants(scene, options, plans, placed);
    if (!options.instancing) return set;
    std::vector<std::exception_ptr> errors(set.variants.size());
#pragma omp parallel for schedule(dynamic, 1) num_threads(workers.threads)
    for (std::ptrdiff_t k = 0; k < static_cast<std::ptrdiff_t>(set.variants.size()); ++k) {
        const auto slot = static_cast<std::size_t>(k);
        const auto thread = static_cast<std::size_t>(omp_get_thread_num());
        ForestVariant& variant = set.variants[slot];
        try {
            progress.checkCancelled();
            growVariant(variant, slot, scene, options, plans[variant.species], workers, thread);
        } catch (...) {
            errors[slot] = std::current_exception();
        }
    }
    for (const std::exception_ptr& e : errors)
        if (e) std::rethrow_exception(e);
    for (const ForestVariant& v : set.variants) {
        set.extents.push_back(variantExtent(*v.skeleton, plans[v.species].meshSettings));
        set.measures.push_back(forest::prepareMeasure(*v.skeleton));
    }
    return set;
}

} // namespace sylva::forest::build
