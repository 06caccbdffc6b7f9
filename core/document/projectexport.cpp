#include "document/projectexport.h"

#include <chrono>
#include <cstdio>

#include "document/scenebuild.h"
#include "document/statsjson.h"
#include "engine/export/treeexport.h"
#include "engine/util/error.h"
#include "engine/wind/windmodel.h"

namespace sylva::doc {

namespace {

using Clock = std::chrono::steady_clock;

double msSince(Clock::time_point t) {
    return std::chrono::duration<double, std::milli>(Clock::now() - t).count();
}

bool hasExtension(const std::filesystem::path& path, const char* extension) {
    std::string ext = path.extension().string();
    for (char& c : ext)
        c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return ext == extension;
}

/// The project as one export writes it: the request's season over the trees' own.
Project withSeason(const Project& original, const ExportRequest& request) {
    Project project = original;
    if (request.season) {
        project.season = std::string(mesh::seasonName(*request.season));
        for (ProjectInstance& tree : project.instances)
            tree.season.clear();
    }
    return project;
}

forest::ForestOptions forestOptions(const ExportRequest& r) {
    forest::ForestOptions o;
    o.tile = r.tile;
    o.tileCount = r.tileCount;
    o.useLod = r.lod;
    o.adapt = r.adapt;
    o.neighbours = r.neighbours;
    o.instancing = r.instancing;
    o.adaptVariants = r.adaptVariants;
    if (r.naivePlacement) o.placement = placement::PlacementMethod::Naive;
    return o;
}

} // namespace

exporter::WindExportOptions exportWind(const std::optional<wind::WindSettings>& projectWind,
                                       const WindOverride& override) {
    exporter::WindExportOptions o;
    if (projectWind) o.wind = *projectWind; // its period is the default: a clip's is below
    if (override.direction) o.wind.direction = *override.direction;
    if (override.strength) o.wind.strength = *override.strength;
    if (override.gustiness) o.wind.gustiness = *override.gustiness;
    if (override.frequency) o.wind.frequency = *override.frequency;
    if (override.clipLength) o.wind.period = *override.clipLength;
    if (override.clipFps) o.rig.fps = *override.clipFps;
    if (override.bones) o.rig.maxBones = *override.bones;
    wind::validate(o.wind);
    wind::validate(o.rig);
    return o;
}

std::string sceneKey(const Project& project, const ExportRequest& request) {
    std::uint64_t h = 1469598103934665603ull;
    auto mix = [&h](const char* data, std::size_t n) {
        for (std::size_t i = 0; i < n; ++i) {
            h ^= static_cast<unsigned char>(data[i]);
            h *= 1099511628211ull;
        }
    };
    const QByteArray bytes = serializeProject(withSeason(project, request));
    mix(bytes.constData(), static_cast<std::size_t>(bytes.size()));
    auto flag = [&mix](const char* name) { mix(name, std::char_traits<char>::length(name) + 1); };
    if (request.camera) {
        char text[96];
        const int n = std::snprintf(text, sizeof text, "%.9g,%.9g,%.9g", double(request.camera->x),
                                    double(request.camera->y), double(request.camera->z));
        flag("--camera");
        mix(text, static_cast<std::size_t>(n));
    }
    if (!request.lod) flag("--no-lod");
    if (!request.adapt) flag("--no-adapt");
    if (!request.neighbours) flag("--no-neighbours");
    char hex[17];
    std::snprintf(hex, sizeof hex, "%016llx", static_cast<unsigned long long>(h));
    return hex;
}

ExportReport exportProject(const Project& project, const ExportRequest& request,
                           Progress& progress) {
    const auto start = Clock::now();
    forest::ForestScene scene = makeForestScene(withSeason(project, request));
    ExportReport report = exportForest(std::move(scene), project, request, progress);
    report.loadMs += msSince(start) - report.totalMs;
    report.totalMs = msSince(start);
    return report;
}

ExportReport exportForest(forest::ForestScene scene, const Project& project,
                          const ExportRequest& request, Progress& progress) {
    const auto start = Clock::now();
    const bool usda = hasExtension(request.path, ".usda");
    const bool obj = hasExtension(request.path, ".obj");
    if (usda && request.instanceTables)
        throw InvalidInput("instance tables are for .obj, .glb and .fbx: a .usda holds its "
                           "instances itself");
    if (request.wind.value_or(false) && usda)
        throw InvalidInput("a wind export writes .glb, .gltf, .fbx or .obj (with its .wind.csv), "
                           "not .usda");
    // The project's wind is the default of every front door; the request's settings override it.
    const bool windOn = request.wind.value_or(project.wind.has_value() && !usda);
    const std::optional<exporter::WindExportOptions> wind =
        windOn ? std::optional(exportWind(project.wind, request.windOverride)) : std::nullopt;
    if (request.camera) scene.camera = *request.camera;
    forest::ForestOptions options = forestOptions(request);
    options.windData = windOn;

    ExportReport report;
    report.tile = request.tile + 1;
    report.tiles = request.tileCount;
    for (const forest::SceneSpecies& s : scene.species)
        report.species.push_back(s.name);
    report.obstacleTriangles = scene.obstacles ? scene.obstacles->triangleCount() : 0;

    // One writer by the extension: USD streams trees and instances itself (with its tile); the
    // others go through TreeExporter (OBJ streamed, glTF written by our own, FBX through
    // Assimp); with wind, .glb/.gltf/.fbx through the wind exporter (rig, clip, _WIND* data)
    // and an OBJ as without, plus its wind table.
    std::optional<exporter::TreeExporter> writer;
    std::optional<exporter::usd::UsdStageWriter> usdWriter;
    if (usda) {
        exporter::usd::UsdLayerOptions layer;
        for (const forest::SceneSpecies& s : scene.species)
            layer.species.push_back(s.name);
        layer.tile = request.tile;
        layer.tileCount = request.tileCount;
        layer.sceneKey = sceneKey(project, request);
        layer.compact = !request.fullPrecision;
        layer.durability = request.fsync ? Durability::Durable : Durability::Atomic;
        layer.shippedTextures = exporter::resourcesDir() / "textures";
        usdWriter.emplace(request.path, std::move(layer));
        options.meshInstances = false; // instances take the variants' meshes
        options.onVariants = [&](const std::vector<forest::ForestVariant>& variants) {
            std::vector<exporter::usd::UsdVariant> out;
            for (const forest::ForestVariant& v : variants)
                out.push_back({v.species, v.index, v.mesh});
            usdWriter->setVariants(std::move(out));
        };
    } else if (!wind || obj) {
        writer.emplace(request.path, exporter::ObjChoices{request.fsync, !request.fullPrecision});
        writer->setInstanceTables(request.instanceTables);
        writer->setProgress(progress);
        writer->setAssimpGltf(request.assimpGltf);
        options.meshInstances = !writer->writesInstances();
        options.onVariants = [&](const std::vector<forest::ForestVariant>& variants) {
            std::vector<exporter::ExportVariant> out;
            for (const forest::ForestVariant& v : variants)
                out.push_back({v.name, v.mesh});
            writer->addVariants(out);
        };
    }
    std::optional<exporter::WindExporter> windWriter;
    if (wind) windWriter.emplace(request.path, *wind, progress);
    report.loadMs = msSince(start);

    double writeMs = 0.0;
    report.stats = forest::buildForest(
        scene, options,
        [&](const std::vector<forest::ForestTree>& all) {
            const auto t = Clock::now();
            std::vector<forest::ForestTree> chosen;
            if (request.trees)
                for (const forest::ForestTree& tree : all)
                    if (request.trees->count(tree.instance.id)) chosen.push_back(tree);
            const std::vector<forest::ForestTree>& batch = request.trees ? chosen : all;
            report.written += batch.size();
            if (usdWriter) {
                std::vector<exporter::usd::UsdTree> trees;
                trees.reserve(batch.size());
                for (const forest::ForestTree& tree : batch)
                    trees.push_back({tree.instance.id, tree.instance.species, tree.variant,
                                     tree.instance.position, tree.instance.rotation,
                                     tree.instance.scale * tree.instance.growth, tree.mesh,
                                     tree.meshCameraDistance});
                usdWriter->add(trees, progress);
            } else if (writer) {
                std::vector<exporter::ExportTree> trees;
                trees.reserve(batch.size());
                for (const forest::ForestTree& tree : batch)
                    trees.push_back({tree.name, tree.mesh, tree.instance.position,
                                     tree.instance.rotation,
                                     tree.instance.scale * tree.instance.growth, tree.variant,
                                     tree.instance.id});
                writer->add(trees);
            }
            if (windWriter) {
                std::vector<exporter::WindExportTree> windy;
                for (const forest::ForestTree& tree : batch)
                    windy.push_back({tree.name, tree.mesh, tree.skeleton, tree.instance.position,
                                     tree.instance.rotation,
                                     tree.instance.scale * tree.instance.growth});
                windWriter->add(windy);
            }
            progress.checkCancelled();
            writeMs += msSince(t);
        },
        progress);
    const auto t = Clock::now();
    if (usdWriter) {
        usdWriter->commit(progress);
        report.files.push_back(request.path);
        report.usd = usdWriter->stats();
    } else if (writer) {
        report.files = writer->commit();
    }
    if (windWriter)
        for (const std::filesystem::path& f : windWriter->commit())
            report.files.push_back(f);
    report.writeMs = writeMs + msSince(t);
    report.totalMs = msSince(start);
    report.wind = windOn;
    return report;
}

std::string exportStatsJson(const ExportReport& report, int threads) {
    const forest::ForestStats& stats = report.stats;
    std::string json = "{";
    appendJsonNumber(json, "trees", static_cast<double>(stats.trees));
    appendJsonNumber(json, "trees_in_scene", static_cast<double>(stats.treesInScene));
    appendJsonNumber(json, "tile", report.tile);
    appendJsonNumber(json, "tiles", report.tiles);
    appendJsonNumber(json, "threads", threads);
    appendJsonNumber(json, "vertices", static_cast<double>(stats.vertices));
    appendJsonNumber(json, "triangles", static_cast<double>(stats.triangles));
    appendJsonNumber(json, "obstacle_triangles", static_cast<double>(report.obstacleTriangles));
    appendJsonNumber(json, "colliding_trees", static_cast<double>(stats.collidingTrees));
    appendJsonNumber(json, "pruned_nodes", static_cast<double>(stats.prunedNodes));
    appendJsonNumber(json, "instanced", static_cast<double>(stats.instanced));
    appendJsonNumber(json, "unique", static_cast<double>(stats.unique));
    appendJsonNumber(json, "adapted_variants", static_cast<double>(stats.adaptedVariants));
    appendJsonNumber(json, "instanced_by_check", static_cast<double>(stats.instancedByCheck));
    appendJsonNumber(json, "variants", static_cast<double>(stats.variants));
    std::size_t missing = 0;
    for (const placement::Shortfall& s : stats.shortfalls)
        missing += s.requested - s.placed;
    appendJsonNumber(json, "shortfall", static_cast<double>(missing));
    if (report.usd) {
        const exporter::usd::UsdLayerStats& u = *report.usd;
        json += "\"usd\":{";
        appendJsonNumber(json, "unique_trees", static_cast<double>(u.uniqueTrees));
        appendJsonNumber(json, "instances", static_cast<double>(u.instances));
        appendJsonNumber(json, "instancers", static_cast<double>(u.instancers));
        appendJsonNumber(json, "prototypes", static_cast<double>(u.prototypes));
        appendJsonNumber(json, "meshes", static_cast<double>(u.meshes));
        appendJsonNumber(json, "materials", static_cast<double>(u.materials), false);
        json += "},";
    }
    json += "\"metrics\":" + metricsJson(stats.metrics) + ",";
    json += "\"timings_ms\":{";
    appendJsonNumber(json, "load", report.loadMs);
    for (const auto& [k, v] : stats.wallMs)
        appendJsonNumber(json, k.c_str(), v);
    appendJsonNumber(json, "write", report.writeMs);
    appendJsonNumber(json, "total", report.totalMs, false);
    json += "},\"cpu_ms\":{";
    bool first = true;
    for (const auto& [k, v] : stats.cpuMs) {
        if (!first) json += ",";
        first = false;
        appendJsonNumber(json, k.c_str(), v, false);
    }
    return json + "}}";
}

} // namespace sylva::doc
