#include "ui/generation/vertexdata.h"

#include "engine/mesh/mesh.h"
#include "engine/mesh/occlusion.h"

namespace sylva::ui {

namespace {

std::vector<glm::vec3> smoothNormals(const mesh::Mesh& mesh) {
    std::vector<glm::vec3> normals(mesh.positions.size(), glm::vec3(0.0f));
    const std::size_t n = mesh.positions.size();
    for (std::size_t i = 0; i + 2 < mesh.indices.size(); i += 3) {
        const std::uint32_t a = mesh.indices[i], b = mesh.indices[i + 1], c = mesh.indices[i + 2];
        if (a >= n || b >= n || c >= n) continue;
        // Area-weighted: the unnormalised cross product.
        const glm::vec3 nrm = glm::cross(mesh.positions[b] - mesh.positions[a],
                                         mesh.positions[c] - mesh.positions[a]);
        normals[a] += nrm;
        normals[b] += nrm;
        normals[c] += nrm;
    }
    return normals;
}

} // namespace

std::vector<ViewVertex> interleaveVertices(const mesh::Mesh& m,
                                           const std::vector<glm::vec3>& colors) {
    const std::size_t vertexCount = m.positions.size();
    const std::vector<glm::vec3> computed =
        m.normals.size() == vertexCount ? std::vector<glm::vec3>{} : smoothNormals(m);
    const std::vector<glm::vec3>& normals = computed.empty() ? m.normals : computed;
    const bool colored = colors.size() == vertexCount;
    const bool tinted = m.colors.size() == vertexCount;
    const bool hasUvs = m.uvs.size() == vertexCount;
    const std::vector<float> occlusion = mesh::crownOcclusion(m);
    std::vector<ViewVertex> out(vertexCount);
    for (std::size_t i = 0; i < vertexCount; ++i)
        out[i] = {m.positions[i], normals[i],
                  colored  ? colors[i]
                  : tinted ? glm::vec3(m.colors[i]) / 255.0f
                           : glm::vec3(1.0f),
                  hasUvs ? m.uvs[i] : glm::vec2(0.0f), occlusion[i]};
    return out;
}

} // namespace sylva::ui
