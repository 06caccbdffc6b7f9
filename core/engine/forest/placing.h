#pragma once

// Stage 2 of buildForest: every tree of the scene placed, the tile's trees selected, and the
// crowns each tree's neighbours are, over the whole scene so that tiles agree.

#include <cstddef>
#include <cstdint>
#include <unordered_map>
#include <vector>

#include "engine/forest/speciesplan.h"

namespace sylva::forest::build {

/// Every tree's crown core (env::CrownVolume) in a uniform grid over the ground positions.
class NeighbourGrid {
public:
    /// The crowns of \p instances as their species' plans measured them, scaled per tree.
    NeighbourGrid(const std::vector<placement::Instance>& instances,
                  const std::vector<SpeciesPlan>& plans);
    /// Crowns other than \p self whose cylinders overlap its cylinder, in instance order.
    std::vector<env::CrownVolume> around(std::size_t self) const;

private:
    static std::uint64_t pack(long long x, long long z);
    std::uint64_t key(const glm::vec3& p) const;
    std::vector<env::CrownVolume> mCrowns;
    float mCell = 0.2f;
    std::unordered_map<std::uint64_t, std::vector<std::uint32_t>> mCells;
};

/// The scene's trees and the tile's.
struct Placed {
    std::vector<placement::Instance> instances; ///< the whole scene's
    std::vector<placement::Shortfall> shortfalls;
    std::vector<std::size_t> selected; ///< indices into instances of the tile's trees, in order
};

/// Places the whole scene (hand-placed trees first, then the domains') with the species'
/// crowns and trunks, then selects ForestOptions::tile.
Placed placeTrees(const ForestScene& scene, const ForestOptions& options,
                  const std::vector<SpeciesPlan>& plans);

} // namespace sylva::forest::build
