#pragma once

#include <cstdint>
#include <functional>
#include <vector>

#include <glm/glm.hpp>

#include "engine/mesh/mesh.h"
#include "engine/skeleton/skeleton.h"
#include "engine/wind/windmodel.h"

namespace sylva::wind {

/// One sway element: an axis of the skeleton (a node and the children that continue it with the
/// same branch order, the tube mesher's rule) at hierarchy level 0 (a root's axis), 1 (laterals
/// of it) or 2 (laterals of those). Deeper axes have no element of their own: they move rigidly
/// with their level-2 ancestor at the point where they are attached.
struct WindElement {
    glm::vec3 pivot{0.0f};        ///< the attachment (the parent's node) or the root's position
    glm::vec3 direction{0, 1, 0}; ///< unit, pivot towards the farthest node of the axis
    float length = 0.0f;          ///< arc length of the axis from the pivot, metres
    float radius = 0.0f;          ///< base radius, metres
    float stiffness = 0.0f;       ///< elementStiffness(level, radius, length)
    float phase = 0.0f;           ///< 0..1, from the axis' first node (stable across meshings)
    int level = 0;
    std::int32_t parent = -1; ///< parent element, -1 for a root's axis
    float attachU = 0.0f;     ///< bend fraction on the parent where this element is attached
    std::int32_t firstNode = -1;
    std::int32_t tipNode = -1; ///< the node of the axis farthest along it
};

/// The elements of a skeleton and where every node sits in them.
struct WindElements {
    std::vector<WindElement> elements;     ///< parents before children
    std::vector<std::int32_t> nodeElement; ///< per node: its element (-1: hidden)
    std::vector<float> nodeU;              ///< per node: bend fraction on its element, 0..1
    /// Per node, per level 0..2: the element and fraction of that level in its ancestry
    /// (element -1 where the node's hierarchy is shallower).
    void levelsOf(std::size_t node, std::int32_t element[3], float u[3]) const;
};

/// Splits \p skeleton into sway elements. Pure and deterministic.
WindElements buildWindElements(const skel::Skeleton& skeleton);

/// The wind data of one node (what a vertex made for that node carries, leaf flutter aside).
mesh::WindVertex windVertexOf(const WindElements& elements, std::size_t node);

/// Calls \p weight(vertex, flutter) for every vertex of \p mesh's leaf cards (the "leaf"
/// submeshes' 4-vertex cards: triangles b, b+1, b+2, b, b+2, b+3, the stem at b): the flutter
/// weight is the distance from the stem along the card, so the stem stays on its twig. The one
/// rule of the exports' `_WIND` data and the viewport's.
void forEachLeafFlutter(const mesh::Mesh& mesh,
                        const std::function<void(std::uint32_t vertex, float flutter)>& weight);

/// Fills \p mesh.wind from \p skeleton (docs/wind.md). Needs Mesh::node (TubeSettings::nodeIds):
/// each vertex takes its node's elements; leaf-card vertices (the "leaf" submeshes) also get a
/// flutter weight, their distance from the card's stem, so that the stem stays on its twig.
/// Vertices without a node stand still. \throw InvalidInput when the mesh has no node ids.
void addWindData(mesh::Mesh& mesh, const skel::Skeleton& skeleton);

/// Where a skeleton node is at \p frame (the model applied to the node's own position): the
/// rig and the tests follow the nodes with it.
glm::vec3 displaceNode(const WindElements& elements, const skel::Skeleton& skeleton,
                       std::size_t node, const WindFrame& frame);

} // namespace sylva::wind
