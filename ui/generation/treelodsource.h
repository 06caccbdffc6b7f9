#pragma once

#include <memory>

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
struct TreeLodSource {
    std::shared_ptr<const skel::Skeleton> skeleton;
    std::shared_ptr<const mesh::TreeMeshSettings> settings;
    /// The camera distance (tree frame, metres) the full mesh was already built for by the
    /// project's camera LOD; levels that would not be coarser than that reuse the full mesh.
    double builtDistance = 0.0;
};

} // namespace sylva::ui
