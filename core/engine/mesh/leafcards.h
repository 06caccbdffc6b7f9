#pragma once

#include <vector>

#include "engine/mesh/mesh.h"
#include "engine/skeleton/skeleton.h"

namespace sylva::mesh {

/// Shape of the leaf cards.
struct LeafCardSettings {
    double aspect = 0.5;    ///< card width / card length, (0, 4]
    double sizeScale = 1.0; ///< multiplies every Leaf::size, (0, 100]
};

/// Appends one card (4 vertices, 2 triangles) per leaf as a "leaf" submesh. A card starts at
/// Leaf::position and extends Leaf::size metres along the leaf's heading, aspect·size wide
/// along its left axis; its normal is the leaf's up axis. UVs: u = 0..1 across, v = 0 at the
/// stem to 1 at the tip, so a leaf texture stands upright. When \p skeleton is given and the
/// mesh carries wind attributes, leaves take their node's branch order and flexibility 1. When
/// the mesh carries node ids (Mesh::node), each card's vertices get its leaf's node.
void appendLeafCards(Mesh& out, const std::vector<skel::Leaf>& leaves,
                     const LeafCardSettings& settings, const skel::Skeleton* skeleton = nullptr);

/// Where appended cards go: \p out grown by \p cards quads (4 vertices, 6 indices each; the
/// bark submesh closed first, wind and node attributes extended when the mesh carries them).
struct CardSpan {
    std::size_t firstVertex = 0, firstIndex = 0;
    bool wind = false; ///< the mesh carries branchOrder / flexibility
    bool ids = false;  ///< the mesh carries Mesh::node
};
CardSpan growForCards(Mesh& out, std::size_t cards);
/// growForCards with the positions, normals, uvs and indices reserved, not grown: the caller
/// appends the cards' (push_back), in card order.
CardSpan reserveForCards(Mesh& out, std::size_t cards);

} // namespace sylva::mesh
