#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include <glm/glm.hpp>

namespace sylva::exporter {

/// A material as the exporters write it (OBJ's MTL, glTF/FBX through Assimp).
struct Material {
    std::string name;           ///< matches mesh::Submesh::material ("bark", "leaf")
    glm::vec3 diffuse{0.8f};    ///< linear RGB 0..1, used where the texture is missing
    std::string diffuseTexture; ///< path relative to the exported file, "" for none
    bool twoSided = false;      ///< leaf cards are seen from both sides
    bool alphaMask = false;     ///< cut out by the texture's alpha (leaf silhouettes)
};

/// Sylva's bark and leaf materials, their textures under \p textureFolder (relative to the
/// exported file; the PNGs ship in resources/textures/).
std::vector<Material> defaultMaterials(const std::string& textureFolder = "textures");

/// MTL text: one `newmtl` per material with Kd, map_Kd and (for alphaMask) map_d.
std::string formatMtl(const std::vector<Material>& materials);

/// Writes formatMtl() atomically. \throw IoError
void writeMtlFile(const std::filesystem::path& path, const std::vector<Material>& materials);

/// Copies every material texture from \p sourceDir (looked up by file name) into
/// \p exportDir / texture path, creating folders. Missing sources are skipped; returns how many
/// files were copied. \throw IoError when a copy fails.
std::size_t copyTextures(const std::vector<Material>& materials,
                         const std::filesystem::path& sourceDir,
                         const std::filesystem::path& exportDir);

} // namespace sylva::exporter
