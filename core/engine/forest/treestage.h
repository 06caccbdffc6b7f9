#pragma once

// Stage 5 of buildForest: one tree of the tile, from its instance to its mesh.

#include <cstddef>
#include <memory>
#include <vector>

#include "engine/forest/placing.h"
#include "engine/forest/variants.h"
#include "engine/forest/workers.h"

namespace sylva::forest::build {

/// What every tree of the tile reads: the scene and the earlier stages' results.
struct TreeStage {
    const ForestScene& scene;
    const ForestOptions& options;
    const std::vector<SpeciesPlan>& plans;
    const Placed& placed;
    const NeighbourGrid& neighbours;
    /// Per instance its stand-grown skeleton (growStands); null for trees grown on their own.
    const std::vector<std::shared_ptr<const skel::Skeleton>>& standGrown;
    const VariantSet& variants;
    const env::ObstacleScene& obstacles; ///< the scene's, or an empty one
};

/// Builds the tree of instance \p index (into Placed::instances) on thread \p thread: an
/// instance of its species' variant when nothing would adapt it, else its skeleton (from its
/// stand, from its variant, kept from an earlier build or grown from its seed), its branch
/// edits, its adaptation to the obstacles and neighbours, its mesh at its camera distance and
/// its metrics; through ForestOptions::cache when set. A pure function of its inputs.
/// \throw InvalidInput, LimitExceeded.
ForestTree buildTree(const TreeStage& stage, std::size_t index, Workers& workers,
                     std::size_t thread);

} // namespace sylva::forest::build
