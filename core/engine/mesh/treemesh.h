#pragma once

#include <cstdint>
#include <functional>
#include <string>

#include "engine/mesh/leafcards.h"
#include "engine/mesh/leaftint.h"
#include "engine/mesh/lod.h"
#include "engine/mesh/mesh.h"
#include "engine/mesh/season.h"
#include "engine/mesh/tubemesh.h"
#include "engine/skeleton/skeleton.h"
#include "engine/util/progress.h"

// A tree's mesh from its skeleton: the one function every mesher, the forest, the LOD chain and
// the viewport's levels call (issue 42: buildTreeMesh in its own file, beside the LOD rules in
// lod.h it applies).

namespace sylva::mesh {

/// Everything that makes a tree's mesh.
struct TreeMeshSettings {
    TubeSettings tubes;
    LeafCardSettings leafCards;
    bool leaves = true;          ///< cards for the skeleton's leaves ("leaf" submesh)
    bool useLod = false;         ///< choose resolution/twigs/leaves from cameraDistance
    double cameraDistance = 0.0; ///< metres, with useLod
    /// The camera's position in the skeleton's frame, when known (a forest's project camera):
    /// thin branches far away become ribbons facing it. The LOD chain for game engines has none.
    bool hasCamera = false;
    glm::vec3 cameraLocal{0.0f};
    /// Whether a card the LOD makes (a leaf cluster) may be drawn; a forest refuses cards that
    /// would reach into an obstacle (adaptation already removed the leaves that did). Empty:
    /// every card.
    std::function<bool(const skel::Leaf&)> acceptLeafCard;
    LodSettings lod;
    std::uint64_t seed = 0; ///< leaf thinning
    /// Diffuse textures of the bark and leaf submeshes (Submesh::texture); empty: the defaults.
    std::string barkTexture;
    std::string leafTexture;
    /// The season the tree is shown in (tube_mesh's `season`, or the project's or tree's
    /// choice over it) and whether the species drops its leaves (`deciduous`): see season.h.
    Season season = Season::Summer;
    bool deciduous = false;
    /// Leaves a cluster card carries on average (engine/mesh/leafclusters.h); 0: one card a
    /// leaf. With it the leaf submesh shows leafClusterTexture (the species' cluster atlas).
    int leafClusterSize = 0;
    std::string leafClusterTexture;
    bool leafClusterCrossed = false; ///< LeafClusterSettings::crossed (tube_mesh's option)
    /// How the leaf cards' colours vary (Mesh::colors), per season; none by default.
    LeafTintSettings leafTint;
};

/// Bark tubes plus leaf cards, at the level of detail the settings ask for.
Mesh buildTreeMesh(const skel::Skeleton& skeleton, const TreeMeshSettings& settings,
                   Progress& progress = noProgress());

} // namespace sylva::mesh
