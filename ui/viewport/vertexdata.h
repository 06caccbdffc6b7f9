#pragma once

#include <cstddef>
#include <vector>

#include <glm/glm.hpp>

namespace sylva::mesh {
struct Mesh;
}

namespace sylva::ui {

/// Floats per vertex the viewport uploads: position, normal, attribute colour, uv, crown
/// occlusion (the mesh shader's attributes 0..4).
inline constexpr int kVertexFloats = 12;

/// The vertices of \p m as the viewport uploads them: position, normal (area-weighted smooth
/// normals when the mesh has none), attribute colour (zero when \p colors does not match the
/// vertices), uv (zero without uvs) and the crown's ambient occlusion. Pure, so any thread can
/// make it: the species preview makes it on its worker beside the mesh, and the GUI thread only
/// copies it to the GPU. Triangles with an index out of range are skipped for the normals.
std::vector<float> interleaveVertices(const mesh::Mesh& m, const std::vector<glm::vec3>& colors);

} // namespace sylva::ui
