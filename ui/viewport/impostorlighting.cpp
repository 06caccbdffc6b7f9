#include "ui/viewport/impostorlighting.h"

#include <algorithm>
#include <cmath>

#include "engine/mesh/impostor.h"

namespace sylva::ui {

glm::vec3 cameraKeyLight(const glm::vec3& forward, const glm::vec3& up, const glm::vec3& right) {
    return glm::normalize(-0.5f * forward + 0.8f * up - 0.6f * right);
}

Image litImpostorAtlas(const mesh::Impostor& imp, float occlusion) {
    const int grid = imp.settings.grid, cell = imp.settings.cellPixels;
    const Image& color = imp.color;
    const Image& normal = imp.normal;
    Image lit(color.width, color.height, 4);
    if (grid < 2 || cell <= 0 || color.channels != 4 || normal.channels != 3 ||
        color.width != grid * cell || color.height != grid * cell || normal.width != color.width ||
        normal.height != color.height)
        return lit;
    // What shaders/mesh.frag does with a leaf's albedo and normal, the per-vertex occlusion
    // as one value for the crown (see below).
    const glm::vec3 sky(0.62f, 0.70f, 0.85f), ground(0.30f, 0.25f, 0.20f);
    const glm::vec3 keyColor(1.0f, 0.96f, 0.90f);
    // The crown's occlusion, which the meshes carry per vertex, as its mean over the source
    // mesh's leaves (Impostors::crownOcclusion): a tree's impostor then measures 0.80-0.99 times
    // as bright as its mesh from the same view, where the constant 0.42 this was measured
    // 0.50-0.68 (tests/ui/test_viewportimpostor.cpp, docs/lods.md).
    const float ao = std::clamp(occlusion, 0.0f, 1.0f);
    for (int j = 0; j < grid; ++j)
        for (int i = 0; i < grid; ++i) {
            // The view toward the viewer and its frame (shaders/impostor.vert's decodeDir and
            // basis): the camera looking at the tree along it has forward = -view.
            const glm::vec3 view = mesh::impostorViewDirection(
                glm::vec2(float(i), float(j)) / float(grid - 1), imp.settings.hemisphere);
            glm::vec3 right, up;
            mesh::impostorViewBasis(view, right, up);
            const glm::vec3 light = cameraKeyLight(-view, up, right);
            for (int y = j * cell; y < (j + 1) * cell; ++y)
                for (int x = i * cell; x < (i + 1) * cell; ++x) {
                    const std::uint8_t* c = color.at(x, y);
                    const std::uint8_t* nm = normal.at(x, y);
                    glm::vec3 n = glm::vec3(nm[0], nm[1], nm[2]) / 127.5f - 1.0f;
                    const float len = glm::length(n);
                    n = len > 1e-6f ? n / len : glm::vec3(0.0f, 1.0f, 0.0f);
                    const float facing = glm::dot(n, light);
                    // mesh.frag's leaf translucency (0.35 of the light from behind), for every
                    // texel: the atlas keeps no material, and most of a crown's texels are leaves.
                    const float diffuse = std::max(facing, 0.0f) + 0.35f * std::max(-facing, 0.0f);
                    const glm::vec3 ambient = glm::mix(ground, sky, 0.5f * n.y + 0.5f);
                    const glm::vec3 srgb = glm::vec3(c[0], c[1], c[2]) / 255.0f;
                    const glm::vec3 albedo = srgb * srgb;
                    const glm::vec3 shaded =
                        albedo *
                        (0.55f * ambient * ao + 1.35f * keyColor * diffuse * (0.4f + 0.6f * ao));
                    std::uint8_t* out = lit.at(x, y);
                    for (int k = 0; k < 3; ++k)
                        out[k] = std::uint8_t(
                            std::lround(255.0f * std::sqrt(std::clamp(shaded[k], 0.0f, 1.0f))));
                    out[3] = c[3];
                }
        }
    return lit;
}

} // namespace sylva::ui
