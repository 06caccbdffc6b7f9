#include "engine/export/lodchainexport.h"

#include <span>
#include <system_error>

#include <nlohmann/json.hpp>

#include "engine/export/gltf/gltfbuilder.h"
#include "engine/export/gltf/gltfmesh.h"
#include "engine/export/lodexport.h"
#include "engine/export/materials.h"
#include "engine/export/objwriter.h"
#include "engine/export/sceneexport.h"
#include "engine/export/usd/usdlodchain.h"
#include "engine/util/atomicfile.h"
#include "engine/util/error.h"

namespace sylva::exporter {

namespace {

namespace fs = std::filesystem;
using Json = nlohmann::ordered_json;

Json vec3(const glm::vec3& v) {
    return Json::array({gltf::tidy(v.x), gltf::tidy(v.y), gltf::tidy(v.z)});
}

std::span<const std::byte> bytesOf(const std::string& s) {
    return {reinterpret_cast<const std::byte*>(s.data()), s.size()};
}

} // namespace

namespace {

GameLodFiles writeFiles(const fs::path& dir, const std::string& species,
                        const mesh::BudgetLodChain& chain, const mesh::LodSettings& reference,
                        const GameLodOptions& options, Progress& progress,
                        std::vector<fs::path>& written) {
    if (species.empty()) throw InvalidInput("LOD export needs a species name");
    if (chain.levels.empty()) throw InvalidInput("LOD export needs at least one level");
    const std::string base = fileSafeName(species);
    std::error_code ec;
    fs::create_directories(dir, ec);
    if (ec) throw IoError("cannot create " + dir.string() + ": " + ec.message());

    GameLodFiles files;
    std::vector<Material> materials = defaultMaterials();
    for (const mesh::BudgetLevel& level : chain.levels)
        addMaterialsOf(level.mesh, materials);
    for (std::size_t i = 0; i < chain.levels.size(); ++i) {
        const mesh::BudgetLevel& l = chain.levels[i];
        GameLodLevel level;
        level.name = base + "_LOD" + std::to_string(i);
        level.budget = l.budget;
        level.distance = l.distance;
        level.screenSize = l.screenSize;
        level.budgetMet = l.budgetMet;
        level.silhouetteIoU = l.silhouetteIoU;
        level.leafClusterPixels = l.leafClusterPixels;
        level.triangles = l.mesh.triangleCount();
        level.vertices = l.mesh.vertexCount();
        if (options.obj) level.obj = dir / (level.name + ".obj");
        files.levels.push_back(level);
    }
    files.dropped = chain.dropped;

    // The impostor's maps first: the glTF embeds the same bytes.
    std::string colorPng, normalPng, depthPng;
    if (chain.impostor) {
        colorPng = encodePng(chain.impostor->color);
        normalPng = encodePng(chain.impostor->normal);
        depthPng = encodePng(chain.impostor->depth);
        files.impostor = true;
        files.impostorDistance = chain.impostorDistance;
        files.impostorScreenSize = chain.impostorScreenSize;
        files.impostorColor = dir / (base + "_impostor_color.png");
        files.impostorNormal = dir / (base + "_impostor_normal.png");
        files.impostorDepth = dir / (base + "_impostor_depth.png");
        writeFileAtomically(files.impostorColor, colorPng);
        written.push_back(files.impostorColor);
        writeFileAtomically(files.impostorNormal, normalPng);
        written.push_back(files.impostorNormal);
        writeFileAtomically(files.impostorDepth, depthPng);
        written.push_back(files.impostorDepth);
        progress.checkCancelled();
    }

    if (options.obj) {
        files.mtl = dir / (base + ".mtl");
        writeMtlFile(files.mtl, materials);
        written.push_back(files.mtl);
        ObjOptions obj;
        obj.mtllib = files.mtl.filename().string();
        for (std::size_t i = 0; i < chain.levels.size(); ++i) {
            writeObjFile(files.levels[i].obj, {{files.levels[i].name, &chain.levels[i].mesh}}, obj);
            written.push_back(files.levels[i].obj);
            progress.checkCancelled();
        }
    }

    if (options.fbx) {
        // Assimp's FBX exporter writes no FbxLODGroup: the levels are sibling nodes named by
        // the _LOD<i> convention Unity's importer turns into an LOD Group (docs/lods.md).
        SceneDesc scene;
        scene.materials = materials;
        scene.textureSource = options.shippedTextures;
        for (std::size_t i = 0; i < chain.levels.size(); ++i) {
            scene.meshes.push_back({files.levels[i].name, &chain.levels[i].mesh});
            SceneInstance node;
            node.name = files.levels[i].name;
            node.mesh = i;
            scene.instances.push_back(node);
        }
        files.fbx = dir / (base + "_LODs.fbx");
        writeScene(files.fbx, scene, SceneFormat::Fbx);
        written.push_back(files.fbx);
        progress.checkCancelled();
    }

    const std::string impostorName = base + "_impostor";
    if (options.gltf) {
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
            Json material = {
                {"name", impostorName},
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
            n.extras = {{"sylva_lod", "impostor"},
                        {"sylva_switch_distance_m", chain.impostorDistance}};
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
    if (options.usd) {
        usd::UsdLodChainNames names;
        names.species = species;
        names.prim = base;
        for (const GameLodLevel& l : files.levels)
            names.levelNames.push_back(l.name);
        names.materials = materials;
        if (chain.impostor) {
            names.impostorName = impostorName;
            names.impostorColor = files.impostorColor.filename().string();
            names.impostorNormal = files.impostorNormal.filename().string();
            names.impostorDepth = files.impostorDepth.filename().string();
        }
        files.usd = dir / (base + "_lods.usda");
        writeFileAtomically(files.usd, usd::formatLodChainStage(chain, names, progress));
        written.push_back(files.usd);
        progress.checkCancelled();
    }
    if (!options.shippedTextures.empty() && (options.obj || options.fbx || options.usd))
        copyTextures(materials, options.shippedTextures, dir);

    // The description a game engine's importer reads.
    Json doc;
    doc["format"] = "sylva-lod-chain";
    doc["format_version"] = 1;
    doc["species"] = species;
    doc["units"] = "m";
    doc["up_axis"] = "+Y";
    doc["reference_view"] = {{"screen_height_px", reference.screenHeightPx},
                             {"fov_y_deg", reference.fovYDegrees}};
    doc["bounding_sphere"] = {{"centre", vec3(chain.centre)}, {"radius", gltf::tidy(chain.radius)}};
    doc["screen_size"] = "bounding sphere diameter / viewport height at the switch distance";
    Json levels = Json::array();
    for (const GameLodLevel& l : files.levels) {
        Json j = {{"name", l.name},
                  {"triangles", l.triangles},
                  {"vertices", l.vertices},
                  {"budget", l.budget},
                  {"budget_met", l.budgetMet},
                  {"switch_distance_m", l.distance},
                  {"screen_size", l.screenSize},
                  {"silhouette_iou", gltf::tidy(static_cast<float>(l.silhouetteIoU))},
                  {"leaf_cluster_px", l.leafClusterPixels}};
        if (!l.obj.empty()) j["obj"] = l.obj.filename().string();
        levels.push_back(j);
    }
    doc["levels"] = levels;
    // Budgets the chain left out (a tree of a few hundred triangles): a pipeline sees why its
    // LOD3 is missing instead of a level that silently breaks its budget.
    Json dropped = Json::array();
    for (const mesh::DroppedLevel& d : chain.dropped)
        dropped.push_back({{"budget", d.budget},
                           {"budget_triangles", d.budgetTriangles},
                           {"coarsest_triangles", d.coarsestTriangles},
                           {"reason", d.reason}});
    doc["dropped_levels"] = dropped;
    if (chain.impostor) {
        const mesh::Impostor& imp = *chain.impostor;
        doc["impostor"] = {
            {"name", impostorName},
            {"layout", imp.settings.hemisphere ? "hemi-octahedral" : "octahedral"},
            {"grid", imp.settings.grid},
            {"cell_pixels", imp.settings.cellPixels},
            {"atlas_pixels", imp.color.width},
            {"centre", vec3(imp.centre)},
            {"radius", gltf::tidy(imp.radius)},
            {"switch_distance_m", chain.impostorDistance},
            {"screen_size", chain.impostorScreenSize},
            {"maps",
             {{"color", files.impostorColor.filename().string()},
              {"normal", files.impostorNormal.filename().string()},
              {"depth", files.impostorDepth.filename().string()}}},
            {"encoding",
             {{"cell", "column i, row j (row 0 at the top) shows the view from "
                       "direction(i / (grid - 1), j / (grid - 1)), see docs/lods.md"},
              {"view", "orthographic, [-radius, radius]^2 of the plane through centre"},
              {"color", "sRGB albedo, alpha = coverage"},
              {"normal", "mesh-frame normal facing the viewer, rgb = n * 0.5 + 0.5"},
              {"depth", "0.5 + 0.5 * dot(p - centre, view) / radius, view toward the viewer"}}}};
    }
    Json out = Json::object();
    if (!files.glb.empty()) out["gltf"] = files.glb.filename().string();
    if (!files.fbx.empty()) out["fbx"] = files.fbx.filename().string();
    if (!files.usd.empty()) out["usd"] = files.usd.filename().string();
    if (!files.mtl.empty()) out["mtl"] = files.mtl.filename().string();
    doc["files"] = out;
    files.description = doc.dump(2) + "\n";
    files.json = dir / (base + "_lods.json");
    writeFileAtomically(files.json, files.description);
    return files;
}

} // namespace

GameLodFiles writeGameLodChain(const fs::path& dir, const std::string& species,
                               const mesh::BudgetLodChain& chain,
                               const mesh::LodSettings& reference, const GameLodOptions& options,
                               Progress& progress) {
    // A chain is one asset: stopped or failed half-way, the files this call already wrote go
    // too (each was written atomically, but a set without its glTF or description is no chain).
    std::vector<fs::path> written;
    try {
        return writeFiles(dir, species, chain, reference, options, progress, written);
    } catch (...) {
        for (const fs::path& f : written) {
            std::error_code ec;
            fs::remove(f, ec);
        }
        throw;
    }
}

GameLodFiles writeTreeLodChain(const fs::path& dir, const std::string& name,
                               const skel::Skeleton& skeleton,
                               const mesh::TreeMeshSettings& settings,
                               const mesh::LodChainSettings& chainSettings,
                               const GameLodOptions& options, Progress& progress) {
    mesh::validateLodChain(chainSettings);
    const mesh::BudgetLodChain chain =
        mesh::buildBudgetLodChain(skeleton, settings, chainSettings,
                                  mesh::ImpostorTextures(options.shippedTextures), progress);
    progress.checkCancelled();
    progress.report(0.0, "writing");
    return writeGameLodChain(dir, name, chain, settings.lod, options, progress);
}

} // namespace sylva::exporter
