#include "engine/forest/speciesplan.h"

#include "engine/forest/treecache.h"
#include "engine/nodes/meshnodes.h"
#include "engine/util/error.h"
#include "engine/util/random.h"
#include "engine/util/seedsalts.h"

#include <algorithm>
#include <limits>
#include <optional>

namespace sylva::forest {

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

namespace build {

namespace {

/// The graph's parts and the growth policy its node types' traits give.
SpeciesPlan planOne(const SceneSpecies& s) {
    SpeciesPlan plan;
    const graph::SpeciesGraph& g = s.graph;
    plan.meshNode = graph::meshOutput(g);
    if (!plan.meshNode)
        throw InvalidInput("species '" + s.name +
                           "': a forest needs the species' output node to be a mesher (tube_mesh) "
                           "with one input (the skeleton)");
    plan.skeletonNode = g.skeletonSource();
    bool hasAdaptNode = false;
    for (const graph::NodeDesc& n : g.nodes)
        hasAdaptNode = hasAdaptNode || graph::roleOf(n.type) == graph::NodeRole::Adapt;
    const graph::NodeDesc* grow = g.findNode(plan.skeletonNode);
    plan.stand = grow ? graph::standGrowthOf(grow->type) : nullptr;
    const bool inStand = plan.stand != nullptr;
    plan.instanced = !inStand;
    plan.cached = !inStand;
    plan.seedOnly = !inStand && !hasAdaptNode;
    plan.forestAdapts = inStand || !hasAdaptNode;
    plan.adaptsToNeighbours = !inStand;
    plan.wood.densityKgM3 = g.traits.woodDensity;
    plan.wood.carbonFraction = g.traits.carbonFraction;
    return plan;
}

} // namespace

std::vector<SpeciesPlan> planSpecies(const ForestScene& scene, const ForestOptions& options) {
    std::vector<SpeciesPlan> plans;
    for (std::size_t i = 0; i < scene.species.size(); ++i) {
        const graph::SpeciesGraph& g = scene.species[i].graph;
        SpeciesPlan plan = planOne(scene.species[i]);
        const std::uint64_t crownSeed = mixSeed(scene.seed, salt::kCrownSample + i);
        plan.cacheKey = options.cache ? speciesHash(g) : 0;
        const std::uint64_t crownKey = mixSeed(plan.cacheKey, crownSeed);
        std::optional<CrownShape> cached;
        if (options.cache) cached = options.cache->findCrown(crownKey);
        const mesh::TubeSettings tubes =
            mesh::treeMeshSettingsFromParams(plan.meshNode->params, 0).tubes;
        plan.crown = cached ? *cached : measureCrown(g, crownSeed, &tubes);
        if (options.cache && !cached) options.cache->storeCrown(crownKey, plan.crown);
        plans.push_back(std::move(plan));
    }
    for (std::size_t i = 0; i < plans.size(); ++i) {
        plans[i].meshSettings = mesh::treeMeshSettingsFromParams(plans[i].meshNode->params, 0,
                                                                 scene.species[i].graph.baseDir);
        if (scene.season) plans[i].meshSettings.season = *scene.season;
    }
    return plans;
}

} // namespace build
} // namespace sylva::forest
