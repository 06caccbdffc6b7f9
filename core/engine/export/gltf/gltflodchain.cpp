#include "engine/export/gltf/gltflodchain.h"

#include <span>

#include <nlohmann/json.hpp>

#include "engine/export/gltf/gltfbuilder.h"
#include "engine/export/gltf/gltfmesh.h"

namespace sylva::exporter {

namespace fs = std::filesystem;

namespace {

using Json = nlohmann::ordered_json;

Json vec3(const glm::vec3& v) {
    return Json::array({gltf::tidy(v.x), gltf::tidy(v.y), gltf::tidy(v.z)});
}

std::span<const std::byte> bytesOf(const std::string& s) {
    return {reinterpret_cast<const std::byte*>(s.data()), s.size()};
}

} // namespace

void writeGltfLodChain(const LodChainWrite& w, GameLodFiles& files,
                       std::vector<fs::path>& written) {
    const fs::path& dir = w.dir;
    const std::string& base = w.base;
    const mesh::BudgetLodChain& chain = w.chain;
    const std::vector<Material>& materials = w.materials;
    Progress& progress = w.progress;
    const GameLodOptions& options = w.options;
    const std::string& impostorName = w.impostorName;
    const std::string& colorPng = w.colorPng;
    const std::string& normalPng = w.normalPng;
    const std::string& depthPng = w.depthPng;
    files.glb = dir / (base + "_LODs.glb");
    gltf::GltfBuilder builder(files.glb, gltf::GltfFormat::Glb, progress);
    gltf::MaterialTable table(builder, materials, options.shippedTextures, true);
    std::vector<int> meshes;
    for (std::size_t i = 0; i < chain.levels.size(); ++i) {
        table.describe(chain.levels[i].mesh);
        meshes.push_back(
            gltf::addTreeMesh(builder, chain.levels[i].mesh, files.levels[i].name, table));
    }
    std::vector<int> lower;
    for (std::size_t i = 1; i < chain.levels.size(); ++i) {
        gltf::Node n;
        n.name = files.levels[i].name;
        n.mesh = meshes[i];
        n.extras = {{"sylva_lod", i}, {"sylva_switch_distance_m", chain.levels[i].distance}};
        lower.push_back(builder.addNode(n));
    }
    Json coverage = Json::array();
    for (std::size_t i = 1; i < chain.levels.size(); ++i)
        coverage.push_back(chain.levels[i].screenSize);
    if (chain.impostor) {
        const mesh::Impostor& imp = *chain.impostor;
        const Json sampler = {
            {"magFilter", 9729}, {"minFilter", 9987}, {"wrapS", 33071}, {"wrapT", 33071}};
        const int s = builder.addSampler(sampler);
        const int color = builder.addTexture(
            builder.addImage(bytesOf(colorPng), "image/png", impostorName + "_color"), s);
        const int normal = builder.addTexture(
            builder.addImage(bytesOf(normalPng), "image/png", impostorName + "_normal"), s);
        const int depth = builder.addTexture(
            builder.addImage(bytesOf(depthPng), "image/png", impostorName + "_depth"), s);
        Json material = {{"name", impostorName},
                         {"pbrMetallicRoughness",
                          {{"baseColorTexture", {{"index", color}}},
                           {"metallicFactor", 0.0},
                           {"roughnessFactor", 1.0}}},
                         {"alphaMode", "MASK"},
                         {"alphaCutoff", 0.5},
                         {"doubleSided", true},
                         {"extras",
                          {{"sylva_impostor",
                            {{"layout", imp.settings.hemisphere ? "hemi-octahedral" : "octahedral"},
                             {"grid", imp.settings.grid},
                             {"cell_pixels", imp.settings.cellPixels},
                             {"centre", vec3(imp.centre)},
                             {"radius", gltf::tidy(imp.radius)},
                             {"color_texture", color},
                             {"normal_texture", normal},
                             {"depth_texture", depth},
                             {"spec", "docs/lods.md"}}}}}};
        const int materialIndex = builder.addMaterial(material);
        mesh::Mesh card = mesh::impostorCard(imp);
        for (glm::vec2& uv : card.uvs) // glTF's uv origin is the image's top-left
            uv.y = 1.0f - uv.y;
        gltf::Primitive prim;
        prim.attributes = {
            {"POSITION", builder.addVec3(card.positions, gltf::Target::ArrayBuffer, true)},
            {"NORMAL", builder.addVec3(card.normals)},
            {"TEXCOORD_0", builder.addVec2(card.uvs)}};
        prim.indices = builder.addIndices(card.indices);
        prim.material = materialIndex;
        gltf::Node n;
        n.name = impostorName;
        n.mesh = builder.addMesh(impostorName, {prim});
        n.extras = {{"sylva_lod", "impostor"}, {"sylva_switch_distance_m", chain.impostorDistance}};
        lower.push_back(builder.addNode(n));
        coverage.push_back(chain.impostorScreenSize);
    }
    coverage.push_back(0.0); // never culled
    gltf::Node top;
    top.name = files.levels[0].name;
    top.mesh = meshes[0];
    if (!lower.empty()) {
        top.extensions["MSFT_lod"] = {{"ids", lower}};
        top.extras = {{"MSFT_screencoverage", coverage}};
        builder.useExtension("MSFT_lod");
    }
    const int topIndex = builder.addNode(top);
    builder.addScene(base, {topIndex});
    builder.root()["asset"]["extras"] = {{"sylva_lod_description", base + "_lods.json"}};
    builder.finish();
    written.push_back(files.glb);
}

} // namespace sylva::exporter
