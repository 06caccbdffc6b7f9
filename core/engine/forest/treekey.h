#pragma once

// The TreeCache key of one tree of buildForest.

#include <cstdint>
#include <vector>

#include "engine/forest/forestbuild.h"

namespace sylva::forest::build {

/// Everything one tree's result depends on (see TreeCache): its species' hash, its instance,
/// the crowns near it, the scene's season and light, its camera distance with the LOD, its
/// branch edits (\p edits, may be null) and the build's switches.
std::uint64_t treeKey(std::uint64_t species, const placement::Instance& in,
                      const std::vector<env::CrownVolume>& near, const ForestScene& scene,
                      const ForestOptions& options, double cameraDistance,
                      const std::vector<skel::BranchEdit>* edits);

} // namespace sylva::forest::build
