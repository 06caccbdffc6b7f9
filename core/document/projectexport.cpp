#include "document/projectexport.h"

#include <chrono>
#include <cstdio>

#include "document/scenebuild.h"
#include "document/statsjson.h"
#include "engine/export/treeexport.h"
#include "engine/export/usd/usdforestwriter.h"
#include "engine/util/error.h"
#include "engine/wind/windmodel.h"

namespace sylva::doc {

namespace {

using Clock = std::chrono::steady_clock;

double msSince(Clock::time_point t) {
    return std::chrono::duration<double, std::milli>(Clock::now() - t).count();
}

/// The extensions a wind export writes: ".glb, .gltf, .fbx or .obj" (the table's rows with wind).
std::string windFormats() {
    return exporter::extensionList(
               [](const exporter::FormatRow& r) { return r.wind == exporter::WindSupport::Rig; },
               ", ", ", ") +
           " or " + exporter::extensionList([](const exporter::FormatRow& r) {
               return r.wind == exporter::WindSupport::Table;
           });
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
    // The format table says what the output's format can carry.
    const exporter::FormatRow& format = exporter::formatFor(request.path);
    if (request.instanceTables && !format.instanceTables)
        throw InvalidInput(
            std::string("instance tables are for ") +
            exporter::extensionList([](const exporter::FormatRow& r) { return r.instanceTables; }) +
            ": a " + format.extension + " holds its instances itself");
    const bool windable = format.wind != exporter::WindSupport::None;
    if (request.wind.value_or(false) && !windable)
        throw InvalidInput("a wind export writes " + windFormats() + " (with its .wind.csv), not " +
                           format.extension);
    // The project's wind is the default of every front door; the request's settings override it.
    const bool windOn = request.wind.value_or(project.wind.has_value() && windable);
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

    // One writer by the format table's row (obj/, gltf/, usd/, fbx/), fed species and variants
    // as numbers; with wind, a format that carries the rig (.glb, .gltf, .fbx) goes through the
    // wind exporter (rig, clip, _WIND* data) instead, and one that carries the table only (OBJ)
    // is written as without, plus its wind table.
    std::optional<exporter::TreeExporter> writer;
    if (!wind || format.wind != exporter::WindSupport::Rig) {
        exporter::ForestWriterOptions o;
        for (const forest::SceneSpecies& s : scene.species)
            o.species.push_back(s.name);
        o.fsync = request.fsync;
        o.compact = !request.fullPrecision;
        o.tile = request.tile;
        o.tileCount = request.tileCount;
        if (format.tileLayers) o.sceneKey = sceneKey(project, request);
        o.assimpGltf = request.assimpGltf;
        writer.emplace(request.path, std::move(o));
        writer->setInstanceTables(request.instanceTables);
        writer->setProgress(progress);
        options.meshInstances = !writer->writesInstances();
        options.onVariants = [&](const std::vector<forest::ForestVariant>& variants) {
            std::vector<exporter::ExportVariant> out;
            for (const forest::ForestVariant& v : variants)
                out.push_back({v.name, v.mesh, v.species, v.index});
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
            if (writer) {
                std::vector<exporter::ExportTree> trees;
                trees.reserve(batch.size());
                for (const forest::ForestTree& tree : batch)
                    trees.push_back(
                        {tree.name, tree.mesh, tree.instance.position, tree.instance.rotation,
                         tree.instance.scale * tree.instance.growth, tree.variant, tree.instance.id,
                         tree.instance.species, tree.meshCameraDistance});
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
    if (writer) {
        report.files = writer->commit();
        if (const auto* usd = dynamic_cast<const exporter::UsdForestWriter*>(&writer->writer()))
            report.usd = usd->stats();
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
