#include "engine/export/gltf/gltfmesh.h"

#include <algorithm>
#include <cctype>
#include <fstream>
#include <iterator>

#include "engine/util/error.h"
#include "engine/util/safenormalize.h"

namespace sylva::exporter::gltf {

namespace fs = std::filesystem;

std::string imageMimeType(const fs::path& file) {
    std::string ext = file.extension().string();
    for (char& c : ext)
        c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    if (ext == ".png") return "image/png";
    if (ext == ".jpg" || ext == ".jpeg") return "image/jpeg";
    return {};
}

MaterialTable::MaterialTable(GltfBuilder& builder, std::vector<Material> materials,
                             fs::path shippedTextures, bool embed)
    : mBuilder(builder), mMaterials(std::move(materials)), mShipped(std::move(shippedTextures)),
      mEmbed(embed) {}

int MaterialTable::texture(const Material& m, TextureSlot slot) {
    const fs::path file = textureSourceOf(m, mShipped, slot);
    if (file.empty()) return -1;
    const std::string mime = imageMimeType(file);
    if (mime.empty()) return -1;
    const std::string& uri = texturePath(m, slot);
    const std::string key = mEmbed ? file.string() : uri;
    if (const auto it = mTextureIndex.find(key); it != mTextureIndex.end()) return it->second;
    int image = -1;
    const std::string name = file.stem().string();
    if (mEmbed) {
        std::ifstream in(file, std::ios::binary);
        const std::string bytes((std::istreambuf_iterator<char>(in)),
                                std::istreambuf_iterator<char>());
        if (!bytes.empty())
            image =
                mBuilder.addImage(std::as_bytes(std::span(bytes.data(), bytes.size())), mime, name);
    } else {
        image = mBuilder.addImageUri(uri, name);
    }
    int tex = -1;
    if (image >= 0) {
        if (mSampler < 0)
            // Linear, trilinear mip-mapped, repeating: bark wraps around the tube in u.
            mSampler = mBuilder.addSampler(
                {{"magFilter", 9729}, {"minFilter", 9987}, {"wrapS", 10497}, {"wrapT", 10497}});
        tex = mBuilder.addTexture(image, mSampler);
    }
    mTextureIndex.emplace(key, tex);
    return tex;
}

int MaterialTable::material(const std::string& name) {
    if (const auto it = mMaterialIndex.find(name); it != mMaterialIndex.end()) return it->second;
    auto found = std::find_if(mMaterials.begin(), mMaterials.end(),
                              [&](const Material& m) { return m.name == name; });
    Material m;
    if (found != mMaterials.end())
        m = *found;
    else
        m = Material{name, glm::vec3(0.8f), "", false, false};
    const int tex = texture(m);
    Json pbr;
    if (tex >= 0)
        pbr["baseColorTexture"] = {{"index", tex}};
    else
        pbr["baseColorFactor"] = {tidy(m.diffuse.x), tidy(m.diffuse.y), tidy(m.diffuse.z), 1.0};
    pbr["metallicFactor"] = 0.0;
    // The roughness map is grey: glTF reads roughness from its green channel and metalness
    // from blue, which metallicFactor 0 turns off.
    const int roughness = texture(m, TextureSlot::Roughness);
    if (roughness >= 0) {
        pbr["roughnessFactor"] = 1.0;
        pbr["metallicRoughnessTexture"] = {{"index", roughness}};
    } else {
        pbr["roughnessFactor"] = 0.9;
    }
    Json j = {{"name", m.name}, {"pbrMetallicRoughness", std::move(pbr)}};
    // Tangent-space, +Y up as glTF defines it; no TANGENT attribute is written, so readers
    // derive MikkTSpace tangents as the specification asks.
    if (const int normal = texture(m, TextureSlot::Normal); normal >= 0)
        j["normalTexture"] = {{"index", normal}};
    if (m.alphaMask) {
        j["alphaMode"] = "MASK";
        j["alphaCutoff"] = 0.5;
    }
    if (m.twoSided) j["doubleSided"] = true;
    const int index = mBuilder.addMaterial(j);
    mMaterialIndex.emplace(name, index);
    return index;
}

void MaterialTable::describe(const mesh::Mesh& mesh, const std::string& textureFolder) {
    addMaterialsOf(mesh, mMaterials, textureFolder);
}

int MaterialTable::materialFor(const mesh::Submesh& submesh) {
    return material(materialName(submesh));
}

int addTreeMesh(GltfBuilder& builder, const mesh::Mesh& m, std::string_view name,
                MaterialTable& materials, const ExtraAttributes& extra, const Json& extras) {
    if (m.positions.empty())
        throw InvalidInput("glTF export: mesh '" + std::string(name) + "' has no vertices");
    Primitive base;
    base.attributes.emplace_back("POSITION",
                                 builder.addVec3(m.positions, Target::ArrayBuffer, true));
    if (m.normals.size() == m.positions.size()) {
        // glTF requires unit normals (the validator reports any other as an error).
        std::vector<glm::vec3> normals(m.normals.size());
        for (std::size_t i = 0; i < normals.size(); ++i)
            normals[i] = safeNormalize(m.normals[i], glm::vec3(0, 1, 0));
        base.attributes.emplace_back("NORMAL", builder.addVec3(normals));
    }
    if (m.uvs.size() == m.positions.size()) {
        // glTF's uv origin is the image's top-left, Sylva's (OBJ's, OpenGL's) its bottom-left:
        // without the flip a leaf card showed its texture upside down, and a normal map's green
        // would point the wrong way along v.
        std::vector<glm::vec2> uvs(m.uvs.size());
        for (std::size_t i = 0; i < uvs.size(); ++i)
            uvs[i] = {m.uvs[i].x, 1.0f - m.uvs[i].y};
        base.attributes.emplace_back("TEXCOORD_0", builder.addVec2(uvs));
    }
    if (m.colors.size() == m.positions.size()) {
        // Linear RGBA multipliers of the base colour, as glTF defines COLOR_0 (leaf tints).
        const auto* bytes = reinterpret_cast<const std::uint8_t*>(m.colors.data());
        base.attributes.emplace_back(
            "COLOR_0", builder.addUint8(std::span<const std::uint8_t>(bytes, 4 * m.colors.size()),
                                        4, Target::ArrayBuffer, true));
    }
    for (const auto& attribute : extra)
        base.attributes.push_back(attribute);

    std::vector<mesh::Submesh> parts = m.submeshes;
    if (parts.empty()) parts.push_back({"bark", 0, static_cast<std::uint32_t>(m.indices.size())});
    std::vector<Primitive> primitives;
    for (const mesh::Submesh& part : parts) {
        if (part.indexCount == 0) continue;
        if (std::size_t(part.firstIndex) + part.indexCount > m.indices.size())
            throw InvalidInput("glTF export: a submesh of '" + std::string(name) +
                               "' runs past the mesh's indices");
        Primitive p = base;
        p.indices = builder.addIndices(
            std::span<const std::uint32_t>(m.indices.data() + part.firstIndex, part.indexCount));
        p.material = materials.materialFor(part);
        primitives.push_back(std::move(p));
    }
    if (primitives.empty()) {
        // No triangles: the vertices as points keep the mesh valid (glTF needs a primitive).
        Primitive points = base;
        points.mode = 0;
        primitives.push_back(std::move(points));
    }
    return builder.addMesh(name, primitives, extras);
}

} // namespace sylva::exporter::gltf
