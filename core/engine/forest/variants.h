#pragma once

// Stage 4 of buildForest: each species' K variants with their levels of detail.

#include <cstdint>
#include <vector>

#include "engine/forest/placing.h"
#include "engine/forest/workers.h"

namespace sylva::forest::build {

/// A variant's extent in its own frame: the vertical cylinder about the local y axis that holds
/// its bark (the mesher's ring radii) and its leaf cards.
struct Extent {
    float radius = 0.0f, bottom = 0.0f, top = 0.0f;
};

/// The tile's variants, listed by species, then index.
struct VariantSet {
    std::vector<ForestVariant> variants;
    std::vector<std::int32_t> first;               ///< per species: its first variant; -1: none
    std::vector<std::uint32_t> count;              ///< per species: K (0: none)
    std::vector<Extent> extents;                   ///< per variant
    std::vector<forest::SkeletonMeasure> measures; ///< per variant: its instances' metrics

    /// The variant a domain tree of \p species with \p seed shows (the species has variants).
    std::size_t pick(std::uint32_t species, std::uint64_t seed) const;
};

/// With ForestOptions::instancing, grows K variants of every instanced species with a domain
/// tree in the tile (SpeciesPlan::instanced): at full growth in their own frame, never
/// adapted, meshed at full detail (they are seen at every distance), with their distance
/// levels where instances are meshed per tree. In parallel; the same on any thread count.
VariantSet buildVariants(const ForestScene& scene, const ForestOptions& options,
                         const std::vector<SpeciesPlan>& plans, const Placed& placed,
                         Workers& workers, Progress& progress);

} // namespace sylva::forest::build
