#include "engine/mesh/occlusion.h"

#include <algorithm>
#include <cmath>

namespace sylva::mesh {

std::vector<float> crownOcclusion(const Mesh& mesh, float minimum) {
    std::vector<float> ao(mesh.positions.size(), 1.0f);
    glm::vec3 lo(INFINITY), hi(-INFINITY);
    bool any = false;
    const auto total = static_cast<std::uint32_t>(mesh.indices.size());
    for (const Submesh& s : mesh.submeshes) {
        if (s.material != "leaf") continue;
        const std::uint32_t end = std::min(total, s.firstIndex + s.indexCount);
        for (std::uint32_t i = s.firstIndex; i < end; ++i) {
            const std::uint32_t v = mesh.indices[i];
            if (v >= mesh.positions.size()) continue;
            lo = glm::min(lo, mesh.positions[v]);
            hi = glm::max(hi, mesh.positions[v]);
            any = true;
        }
    }
    if (!any) return ao;
    minimum = std::clamp(minimum, 0.0f, 1.0f);
    const glm::vec3 centre = 0.5f * (lo + hi);
    const glm::vec3 half = glm::max(0.5f * (hi - lo), glm::vec3(1e-3f));
    for (std::size_t v = 0; v < mesh.positions.size(); ++v) {
        const glm::vec3 d = (mesh.positions[v] - centre) / half;
        const float r = std::min(glm::length(d), 1.0f);
        // Open above the centre more than below it: skylight comes from above.
        const float height = std::clamp(0.5f * d.y + 0.5f, 0.0f, 1.0f);
        const float open = std::clamp(r * r * (3.0f - 2.0f * r) * (0.8f + 0.2f * height) +
                                          0.2f * height * (1.0f - r),
                                      0.0f, 1.0f);
        ao[v] = minimum + (1.0f - minimum) * open;
    }
    return ao;
}

} // namespace sylva::mesh
