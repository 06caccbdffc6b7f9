#pragma once

#include <filesystem>
#include <map>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "engine/export/gltf/gltfbuilder.h"
#include "engine/export/materials.h"
#include "engine/mesh/mesh.h"

namespace sylva::exporter::gltf {

/// The materials of one glTF document, each written once on first use: exporter::Material as
/// a metallic-roughness material (diffuse as base colour, the texture as baseColorTexture, leaf
/// cards double-sided and alpha-masked). Textures are embedded as bufferViews (\p embed, for
/// .glb) or referenced by their diffuseTexture path (for .gltf, the caller copies them, see
/// copyTextures); a texture file that cannot be read leaves the material with its colour only.
class MaterialTable {
public:
    /// \param materials the known materials (defaultMaterials() plus addMaterialsOf());
    /// \param shippedTextures Sylva's textures folder, for materials without a sourceFile.
    MaterialTable(GltfBuilder& builder, std::vector<Material> materials,
                  std::filesystem::path shippedTextures, bool embed);

    /// The glTF material of \p submesh (by materialName()); a name nobody described gets a
    /// plain material so nothing is dropped.
    int materialFor(const mesh::Submesh& submesh);
    /// The glTF material named \p name (one of the materials given, or a plain one).
    int material(const std::string& name);
    /// Adds the materials of \p mesh's textured submeshes (exporter::addMaterialsOf: the
    /// species' own bark and leaf), so that materialFor() finds their textures.
    void describe(const mesh::Mesh& mesh, const std::string& textureFolder = "textures");
    /// Every material known so far (for copyTextures beside a .gltf).
    const std::vector<Material>& materials() const { return mMaterials; }

private:
    int texture(const Material& material, TextureSlot slot = TextureSlot::Diffuse);

    GltfBuilder& mBuilder;
    std::vector<Material> mMaterials;
    std::filesystem::path mShipped;
    bool mEmbed;
    int mSampler = -1;
    std::map<std::string, int> mMaterialIndex; ///< name → glTF material
    std::map<std::string, int> mTextureIndex;  ///< source file → glTF texture (-1: unreadable)
};

/// Extra per-vertex attributes for addTreeMesh, already written (builder.addFloats/addVec4/...,
/// Target::ArrayBuffer, one element per mesh vertex): semantic → accessor. Application-specific
/// semantics start with '_' (`_WIND`, `_BRANCH_ORDER`).
using ExtraAttributes = std::vector<std::pair<std::string, int>>;

/// Writes \p mesh as one glTF mesh: POSITION (with bounds), NORMAL (unit length: zero normals
/// become +Y), TEXCOORD_0, plus \p extra, shared by one primitive per submesh (its indices and
/// material). Returns the mesh index. \p extras goes into the mesh's extras.
int addTreeMesh(GltfBuilder& builder, const mesh::Mesh& mesh, std::string_view name,
                MaterialTable& materials, const ExtraAttributes& extra = {},
                const Json& extras = {});

/// The MIME type glTF names for an image file by its extension ("image/png", "image/jpeg");
/// empty for formats glTF core does not allow.
std::string imageMimeType(const std::filesystem::path& file);

} // namespace sylva::exporter::gltf
