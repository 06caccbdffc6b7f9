#pragma once

#include <cstdint>
#include <memory>

#include <glm/glm.hpp>

#include "ui/generation/treelodsource.h"

namespace sylva::mesh {
struct Mesh;
}

namespace sylva::ui {

/// One tree of a forest as the viewport draws it: its own mesh in its own frame, placed by
/// \p transform (rotation, uniform scale, translation). What the viewport, picking, the trees
/// pass and the impostors' scheduling share, so that none of them includes the widget.
struct ViewTree {
    std::uint32_t id = 0; ///< the document's tree id; 0 for trees scattered by a domain
    std::shared_ptr<const mesh::Mesh> mesh;
    glm::mat4 transform{1.0f};
    /// What coarser levels are made from when the tree is small on screen (empty: none); its
    /// skeleton also gives the mesh's wind data (Viewport::setWindEnabled()).
    TreeLodSource lod;
    /// Where in the wind's loop this tree plays, 0..1 of the period (windPhaseOf(its id)).
    float windPhase = 0.0f;
};

} // namespace sylva::ui
