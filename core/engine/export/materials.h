#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "engine/mesh/mesh.h"

namespace sylva::exporter {

/// A material as the exporters write it (OBJ's MTL, glTF/FBX through Assimp).
struct Material {
    std::string name;           ///< matches mesh::Submesh::material ("bark", "leaf")
    glm::vec3 diffuse{0.8f};    ///< linear RGB 0..1, used where the texture is missing
    std::string diffuseTexture; ///< path relative to the exported file, "" for none
    bool twoSided = false;      ///< leaf cards are seen from both sides
    bool alphaMask = false;     ///< cut out by the texture's alpha (leaf silhouettes)
    /// Where the texture is read from (absolute, or relative to the working folder) to copy or
    /// embed it; empty: Sylva's shipped textures folder, by diffuseTexture's file name.
    std::string sourceFile{};
    /// Tangent-space normal map (OpenGL convention: +X along u, +Y along v, "green up"),
    /// relative to the exported file like diffuseTexture; "" for none. Read from
    /// normalSourceFile, else the shipped textures folder by file name.
    std::string normalTexture{};
    std::string normalSourceFile{};
    /// Grey roughness map (0 smooth .. 1 rough; glTF reads its green channel), as normalTexture.
    std::string roughnessTexture{};
    std::string roughnessSourceFile{};
};

/// The textures a material can carry.
enum class TextureSlot { Diffuse, Normal, Roughness };
inline constexpr TextureSlot kTextureSlots[] = {TextureSlot::Diffuse, TextureSlot::Normal,
                                                TextureSlot::Roughness};
/// The texture of \p slot as written into a file (relative path, "" for none).
const std::string& texturePath(const Material& material, TextureSlot slot);
std::string& texturePath(Material& material, TextureSlot slot);

/// The normal or roughness map drawn for \p texture (\p kind "normal" or "roughness"):
/// "<stem>_<kind>.png" beside it when that file exists. A season's leaf
/// ("oak_leaf_autumn.png") shares its summer leaf's maps ("oak_leaf_normal.png"). Empty when
/// there is none.
std::string companionTexture(const std::string& texture, const std::string& kind);

/// Sylva's bark and leaf materials, their textures under \p textureFolder (relative to the
/// exported file; the PNGs ship in resources/textures/).
std::vector<Material> defaultMaterials(const std::string& textureFolder = "textures");

/// The material name exporters give \p submesh: its material ("bark", "leaf") when it has no
/// texture of its own, else the texture's file stem ("english-oak_bark").
std::string materialName(const mesh::Submesh& submesh);

/// Appends to \p materials (if not there yet, by name) one material per textured submesh of
/// \p mesh: the kind's colour and flags (a leaf is two-sided and alpha-masked), its texture as
/// \p textureFolder/<file name>, read from Submesh::texture.
void addMaterialsOf(const mesh::Mesh& mesh, std::vector<Material>& materials,
                    const std::string& textureFolder = "textures");

/// The file a material's texture of \p slot is read from: its source file, else \p shippedDir /
/// the file name of its path; empty when the material has no such texture.
std::filesystem::path textureSourceOf(const Material& material,
                                      const std::filesystem::path& shippedDir,
                                      TextureSlot slot = TextureSlot::Diffuse);

/// MTL text: one `newmtl` per material with Kd, map_Kd and (for alphaMask) map_d; a normal map
/// as `norm` (the PBR extension: Assimp's normal map) and `map_Bump` (Blender's importer),
/// roughness as `map_Pr`.
std::string formatMtl(const std::vector<Material>& materials);

/// Writes formatMtl() atomically. \throw IoError
void writeMtlFile(const std::filesystem::path& path, const std::vector<Material>& materials);

/// Copies every material texture, normal and roughness maps included (textureSourceOf, \p sourceDir
/// being the shipped textures) into \p exportDir / texture path, creating folders. Missing sources
/// are skipped; returns how many files were copied. \throw IoError when a copy fails.
std::size_t copyTextures(const std::vector<Material>& materials,
                         const std::filesystem::path& sourceDir,
                         const std::filesystem::path& exportDir);

/// Folder of Sylva's shipped resources (textures): $SYLVA_RESOURCES_DIR, the source tree next
/// to the build folder, or the installed share/sylva/resources; empty when none is found.
std::filesystem::path resourcesDir();

} // namespace sylva::exporter
