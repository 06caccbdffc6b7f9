#pragma once

// Stage 3 of buildForest: the trees whose generator grows in a stand (graph::StandGrowth).

#include <memory>
#include <vector>

#include "engine/forest/speciesplan.h"

namespace sylva::forest::build {

/// Grows the stand trees of the whole scene (all tiles, so that tiles agree) together, one
/// stand per StandGrowth::standOf key, among the scene's obstacles: they compete for light
/// and space. Each stands upright at its placed position with scale and growth 1 (\p instances
/// is changed so): its size comes from the competition, not from placement.
/// \return per instance its stand-grown skeleton; null for a tree that grows on its own.
std::vector<std::shared_ptr<const skel::Skeleton>>
growStands(const ForestScene& scene, const std::vector<SpeciesPlan>& plans,
           std::vector<placement::Instance>& instances, Progress& progress);

} // namespace sylva::forest::build
