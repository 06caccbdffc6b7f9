#pragma once

#include <cstddef>
#include <vector>

#include <glm/glm.hpp>

namespace sylva::mesh {
struct Mesh;
}

namespace sylva::ui {

/// One vertex as the viewport uploads it (the mesh shader's attributes 0..4), in floats. A
/// 32-byte layout (normals as 10-bit integers, colour and occlusion as 16-bit) was measured
/// and not kept: packing took 5.0 ms for a 300k-triangle tree against 2.6 ms for these 48
/// bytes (bench_preview's BM_PreviewViewVertices, the same run).
struct ViewVertex {
    glm::vec3 position;
    glm::vec3 normal; ///< not normalised (the fragment shader normalises)
    /// The attribute colour, else the mesh's tint (Mesh::colors, linear), else white
    glm::vec3 color;
    glm::vec2 uv;
    float occlusion; ///< the crown's ambient occlusion, 0..1
};
static_assert(sizeof(ViewVertex) == 48, "the viewport's vertex layout is 12 floats");

/// The vertices of \p m as the viewport uploads them: position, normal (area-weighted smooth
/// normals when the mesh has none), uv (zero without uvs), attribute colour (when \p colors
/// matches the vertices; else the mesh's leaf tint, else white: what the material's colour is
/// multiplied by) and the crown's ambient occlusion.
/// Pure, so any thread can make them: the species preview makes them on its worker beside the
/// mesh, and the GUI thread only copies them to the GPU. Triangles with an index out of range
/// are left out of the normals.
std::vector<ViewVertex> interleaveVertices(const mesh::Mesh& m,
                                           const std::vector<glm::vec3>& colors);

} // namespace sylva::ui
