#include "engine/export/lodchainexport.h"

#include <system_error>

#include <nlohmann/json.hpp>

#include "engine/export/exportnames.h"
#include "engine/export/formats.h"
#include "engine/export/gltf/gltfmesh.h"
#include "engine/export/materials.h"
#include "engine/util/atomicfile.h"
#include "engine/util/error.h"

namespace sylva::exporter {

namespace {

namespace fs = std::filesystem;
using Json = nlohmann::ordered_json;

Json vec3(const glm::vec3& v) {
    return Json::array({gltf::tidy(v.x), gltf::tidy(v.y), gltf::tidy(v.z)});
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
        if (options.obj) level.obj = dir / (level.name + formatRow(Format::Obj).extension);
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

    // Each format's folder writes its files (the format table's rows with a LOD chain).
    const std::string impostorName = base + "_impostor";
    const LodChainWrite w{dir,     species,  base,      impostorName, chain,   materials,
                          options, colorPng, normalPng, depthPng,     progress};
    for (const FormatRow& row : formatTable())
        if (row.lodChain && options.wants(row.format)) row.lodChain(w, files, written);
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
