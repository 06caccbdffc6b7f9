#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "engine/wind/windelements.h"
#include "engine/wind/windmodel.h"

namespace sylva::mesh {
struct Mesh;
}
namespace sylva::graph {
struct SpeciesGraph;
}

namespace sylva::ui {

/// The wind data of one vertex as the viewport uploads it (the mesh shader's attributes 5..7,
/// ui/viewport/shaders/wind.glsl), 12 bytes beside the 48 of ViewVertex. Only what differs
/// between the vertices of one element is here; the element itself (pivot, direction,
/// stiffness, phase, parent, level) is fetched from the tree's element table
/// (windElementTexels), the form Pivot Painter gives engines. The engine's mesh::WindVertex
/// (128 bytes: every level's pivot and direction per vertex) is what this unpacks to.
struct ViewWindVertex {
    std::uint32_t element = 0; ///< the vertex's innermost sway element + 1; 0: stands still
    /// The leaf flutter's phase × 2^24: the engine's phases are whole multiples of 2^-24, so
    /// this is exact (the flutter's whole number of cycles is rounded from it).
    std::uint32_t flutterPhase = 0;
    std::uint16_t u = 0;       ///< bend fraction on that element, unsigned normalised (0..1)
    std::uint16_t flutter = 0; ///< leaf flutter weight in metres, a half float (0 on bark)
};
static_assert(sizeof(ViewWindVertex) == 12, "the viewport's wind vertex is 12 bytes");

/// The element table the shader fetches (a buffer texture, RGBA32F): one texel per element,
/// pivot xyz and the parent element (−1: a root). Made once per skeleton.
std::vector<glm::vec4> windElementTexels(const wind::WindElements& elements);

/// Appends, per element of \p elements, its rotation at the tip at \p frame
/// (wind::elementRotation: the gusts from its root's phase, the element's own sway, the
/// saturation) in xyz, and in w the bend fraction on its parent where it hangs. Computed once
/// per tree and frame on the CPU (a few hundred elements a tree) rather than per vertex on the
/// GPU, which then only bends each vertex by it: what a software renderer's vertex stage,
/// which runs on the GUI thread, can afford.
void appendWindRotations(const wind::WindElements& elements, const wind::WindFrame& frame,
                         std::vector<glm::vec4>& out);

/// The wind data of each vertex of \p m, from its node ids (Mesh::node) and the elements of
/// the skeleton it was made from; the leaf cards' flutter weight as wind::addWindData gives it.
/// Empty when \p m has no node ids. Pure: any thread can make it.
std::vector<ViewWindVertex> windVertices(const mesh::Mesh& m, const wind::WindElements& elements);

/// The shader's displacement (wind.glsl) on the CPU, step for step, from the packed vertex,
/// the element table and the frame's rotations (appendWindRotations, at offset 0): what a
/// vertex of rest \p position and \p normal shows at \p frame. The tests hold it against
/// wind::displace, so the viewport shows what the exports play.
glm::vec3 displacePacked(const std::vector<glm::vec4>& texels,
                         const std::vector<glm::vec4>& rotations, const ViewWindVertex& v,
                         const glm::vec3& position, glm::vec3* normal,
                         const wind::WindFrame& frame);

/// A tree's place in the wind's loop, 0..1 of the period, from its stable id: the viewport
/// plays each tree that much later (instances of one variant would otherwise sway in step).
/// Tree 0 (a species on its own) plays at 0, as the exports do.
float windPhaseOf(std::uint64_t treeId);

/// Asks every tube_mesh node of \p graph for node ids (the wind data and the colouring by
/// node attributes need them). Changes no output but Mesh::node.
void requestNodeIds(graph::SpeciesGraph& graph);

} // namespace sylva::ui
