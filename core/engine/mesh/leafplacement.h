#pragma once

#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "engine/skeleton/skeleton.h"

namespace sylva::mesh {

/// Arrangement of leaves around an axis.
enum class Phyllotaxis {
    Alternate, ///< one leaf per position, 180° apart
    Opposite,  ///< two per position, successive pairs turned 90° (decussate)
    Whorled,   ///< whorlCount per position, successive whorls offset by half a gap
    Spiral,    ///< one per position, 137.5° apart (golden angle)
};

/// Where and how the leaves node places leaf cards.
struct LeafPlacement {
    bool alongBranches = true;      ///< on young branches (radius <= maxBranchRadius)
    bool atTips = true;             ///< clusters at branch tips
    bool keepGrammarLeaves = false; ///< keep the skeleton's J leaves as well
    Phyllotaxis phyllotaxis = Phyllotaxis::Spiral;
    int whorlCount = 3;            ///< 2..12, for Whorled
    double size = 0.12;            ///< card length, metres (0, 100]
    double sizeVariation = 0.2;    ///< 0..1: size × (1 ± variation), uniform
    double density = 8.0;          ///< leaf positions per metre of young branch, 0..1000
    int tipCount = 3;              ///< leaves per tip, 0..32
    double maxBranchRadius = 0.02; ///< metres: thicker segments carry no leaves
    double petioleAngle = 50.0;    ///< degrees between the branch and the leaf, 0..90
    /// Orientation blend of the card normal: branch normal (radial), world up, light direction.
    double normalWeight = 0.4;
    double upWeight = 0.4;
    double lightWeight = 0.2;
    glm::vec3 lightDirection{0.3f, 1.0f, 0.2f}; ///< towards the light; normalised internally
    std::uint64_t seed = 0;
};

/// Returns leaves for \p skeleton (hidden nodes carry none). Deterministic for a seed: every
/// node draws from its own Rng(mixSeed(seed, node)), independent of the rest.
/// \throw InvalidInput for parameters out of range (the message names the range).
std::vector<skel::Leaf> placeLeaves(const skel::Skeleton& skeleton, const LeafPlacement& p);

} // namespace sylva::mesh
