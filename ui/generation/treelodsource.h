#pragma once

#include <cstdint>
#include <memory>
#include <vector>

#include "engine/mesh/lodchain.h"

namespace sylva::mesh {
struct TreeMeshSettings;
}
namespace sylva::skel {
struct Skeleton;
}

namespace sylva::ui {

// Plain data the generation hands on with each tree; here rather than beside ViewLod so that
// ui/generation includes nothing of ui/viewport (the viewport reads the generation's results).
/// What the viewport needs to make coarser meshes of a tree than the one it draws near: the
/// skeleton the mesh was made from and the species' meshing settings (seeded as the forest
/// seeds the tree). Trees without one are always drawn at full detail.
/// One of a forest's variants as the viewport draws its instances (issue 32): its levels of
/// detail, made once by the engine (forest::ForestVariant::levels; level 0 the full mesh), one
/// GPU buffer set each, drawn by every instance with instanced draw calls, and one impostor
/// atlas baked from its coarsest level for the variant's instances and the unique trees of its
/// species that it stands in for far away.
struct ViewVariant {
    std::uint32_t species = 0;
    std::vector<mesh::DistanceLevel> levels; ///< distances increasing; never empty
    float height = 0.0f;                     ///< of the full mesh, metres at scale 1
    /// The reference view the levels' distances are for (mesh::LodSettings).
    double referenceHeightPx = 1080.0;
    double referenceFovYDegrees = 60.0;
};

struct TreeLodSource {
    std::shared_ptr<const skel::Skeleton> skeleton;
    std::shared_ptr<const mesh::TreeMeshSettings> settings;
    /// The camera distance (tree frame, metres) the full mesh was already built for by the
    /// project's camera LOD; levels that would not be coarser than that reuse the full mesh.
    double builtDistance = 0.0;
    /// The variant this tree is an instance of (\ref instance: its mesh is one of the
    /// variant's levels, drawn at the level its size on screen asks for), or, for a tree grown
    /// for its place, the variant of its species nearest its height, whose impostor stands in
    /// for it when it is a few dozen pixels high. Null: the tree bakes its own impostor.
    std::shared_ptr<const ViewVariant> variant;
    bool instance = false;
    /// The variant's impostor scaled to this tree's height (a unique tree; 1 for instances).
    float impostorScale = 1.0f;
};

} // namespace sylva::ui
