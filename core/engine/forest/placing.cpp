#include "engine/forest/placing.h"

#include <algorithm>
#include <cmath>

namespace sylva::forest::build {

namespace {

/// A neighbour blocks with the dense core of its crown only: placement lets crowns overlap at
/// their rims (as in the reference), and treating the whole crown cylinder as solid pruned
/// ~40 % of a dense forest.
constexpr float kNeighbourCore = 0.5f;

} // namespace

NeighbourGrid::NeighbourGrid(const std::vector<placement::Instance>& instances,
                             const std::vector<SpeciesPlan>& plans)
    : mCrowns(instances.size()) {
    float maxRadius = 0.1f;
    for (std::size_t i = 0; i < mCrowns.size(); ++i) {
        const placement::Instance& in = instances[i];
        const CrownShape& c = plans[in.species].crown;
        const float s = in.scale * in.growth;
        mCrowns[i] = {in.position, kNeighbourCore * c.radius * s, c.bottom * s, c.top * s};
        maxRadius = std::max(maxRadius, mCrowns[i].radius);
    }
    mCell = 2.0f * maxRadius;
    for (std::size_t i = 0; i < mCrowns.size(); ++i)
        mCells[key(mCrowns[i].base)].push_back(static_cast<std::uint32_t>(i));
}

std::vector<env::CrownVolume> NeighbourGrid::around(std::size_t self) const {
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
                const float d = glm::length(glm::vec2(o.base.x - c.base.x, o.base.z - c.base.z));
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

std::uint64_t NeighbourGrid::pack(long long x, long long z) {
    return (static_cast<std::uint64_t>(x) << 32) ^ (static_cast<std::uint64_t>(z) & 0xFFFFFFFFull);
}

std::uint64_t NeighbourGrid::key(const glm::vec3& p) const {
    return pack(static_cast<long long>(std::floor(p.x / mCell)),
                static_cast<long long>(std::floor(p.z / mCell)));
}

Placed placeTrees(const ForestScene& scene, const ForestOptions& options,
                  const std::vector<SpeciesPlan>& plans) {
    std::vector<placement::SpeciesSpec> specs;
    for (std::size_t i = 0; i < plans.size(); ++i)
        // Trunks vary from tree to tree: placement keeps half again the sample's bark radius
        // from obstacles (adaptation cannot move a root whose bark starts inside one).
        specs.push_back({scene.species[i].name, plans[i].crown.radius,
                         std::min(1.5f * plans[i].crown.trunk, 1e3f)});
    placement::PlacementParams params;
    params.seed = scene.seed;
    params.ground = scene.ground.get();
    params.obstacles = scene.obstacles.get();
    placement::PlacementResult result =
        placement::placeForest(specs, scene.domains, scene.handPlaced, params, options.placement);
    Placed placed;
    placed.instances = std::move(result.instances);
    placed.shortfalls = std::move(result.shortfalls);
    if (options.tileCount > 1) {
        const placement::TileGrid grid =
            placement::makeTileGrid(scene.domains, scene.handPlaced, options.tileCount);
        for (std::size_t i = 0; i < placed.instances.size(); ++i)
            if (placement::tileOf(grid, placed.instances[i].position) == options.tile)
                placed.selected.push_back(i);
    } else {
        placed.selected.resize(placed.instances.size());
        for (std::size_t i = 0; i < placed.selected.size(); ++i)
            placed.selected[i] = i;
    }
    return placed;
}

} // namespace sylva::forest::build
