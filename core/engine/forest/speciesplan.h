#pragma once

// Stage 1 of buildForest: what the build needs to know about each species, decided once.

#include <cstdint>
#include <string>
#include <vector>

#include "engine/forest/forestbuild.h"

namespace sylva::forest::build {

/// One species as the build's stages read it. The growth policy (the flags) is decided here,
/// once, from the traits its graph's node types declare (graph::NodeType::role and ::stand);
/// no later stage asks what kind of generator a species has.
struct SpeciesPlan {
    const graph::NodeDesc* meshNode = nullptr; ///< the output node (graph::meshOutput)
    std::string skeletonNode;                  ///< its input: yields the (adapted) skeleton
    /// The generator's stand growth: its trees of the whole scene grow together in the stand
    /// stage (growStands) and take their skeleton from there. Null: each tree grows from its
    /// own seed.
    const graph::StandGrowth* stand = nullptr;
    /// Its domain trees may show one of K variants (no stand: a variant cannot stand in for a
    /// tree whose shape came from its neighbours).
    bool instanced = true;
    /// Its trees are kept in ForestOptions::cache (a stand tree depends on the whole stand).
    bool cached = true;
    /// A tree's grown skeleton is a function of its seed alone (no adapt node, no stand): a
    /// tree that must be adapted may start from its variant's skeleton, and a hand-placed
    /// tree's grown skeleton is kept for its next branch edit.
    bool seedOnly = true;
    /// The build adapts its trees to the obstacles (no adapt node of its own, or a stand).
    bool forestAdapts = true;
    /// Adaptation bends branches and avoids the neighbours' crowns. Off for stand trees: they
    /// already competed with their neighbours and grew around the obstacles, so they are only
    /// cut where a shoot still went through an obstacle (markers and shadows stop most).
    bool adaptsToNeighbours = true;
    CrownShape crown;
    forest::WoodProperties wood;
    /// The species' meshing settings (seed 0), in the scene's season when it has one.
    mesh::TreeMeshSettings meshSettings;
    std::uint64_t cacheKey = 0; ///< speciesHash of its graph with a cache, else 0
};

/// Checks every species' graph (a mesher output with one skeleton input), decides its growth
/// policy and measures its crown on one sample tree (through ForestOptions::cache when set).
/// \throw InvalidInput for a graph the forest cannot build.
std::vector<SpeciesPlan> planSpecies(const ForestScene& scene, const ForestOptions& options);

} // namespace sylva::forest::build
