#include "cliargs.h"
#include "clishared.h"
#include "commands.h"
#include "terminalprogress.h"
#include "usage.h"

#include "document/project.h"
#include "document/scenebuild.h"
#include "engine/export/treeexport.h"
#include "engine/export/usd/usdstagewriter.h"
#include "engine/forest/forestbuild.h"
#include "engine/placement/placement.h"
#include "engine/util/error.h"

#include <QFile>

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <omp.h>
#include <optional>

namespace sylva::cli {

using exporter::ExportTree;
using exporter::ObjChoices;
using exporter::TreeExporter;

namespace {

using Clock = std::chrono::steady_clock;

double msSince(Clock::time_point t) {
    return std::chrono::duration<double, std::milli>(Clock::now() - t).count();
}

glm::vec3 parseVec3(const std::string& text, const std::string& option) {
    glm::vec3 v;
    char extra = 0;
    if (std::sscanf(text.c_str(), "%f,%f,%f%c", &v.x, &v.y, &v.z, &extra) != 3)
        throw UsageError(option + " expects x,y,z (metres), got '" + text + "'");
    return v;
}

bool isUsda(const std::string& path) {
    std::string ext = std::filesystem::path(path).extension().string();
    for (char& c : ext)
        c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return ext == ".usda";
}

// What identifies a run for `compose`: the project file's bytes and the options that change
// trees (FNV-1a, 64 bits, as hex). Tiles written from another project or with other options
// are refused instead of composing a forest that never existed.
std::string sceneKey(const std::string& projectPath, const std::vector<std::string>& argv) {
    std::uint64_t h = 1469598103934665603ull;
    auto mix = [&h](const char* data, std::size_t n) {
        for (std::size_t i = 0; i < n; ++i) {
            h ^= static_cast<unsigned char>(data[i]);
            h *= 1099511628211ull;
        }
    };
    std::ifstream in(projectPath, std::ios::binary);
    char buf[65536];
    while (in.read(buf, sizeof buf) || in.gcount() > 0)
        mix(buf, static_cast<std::size_t>(in.gcount()));
    for (std::size_t i = 0; i < argv.size(); ++i) {
        const std::string& a = argv[i];
        const bool changesTrees =
            a == "--camera" || a == "--no-lod" || a == "--no-adapt" || a == "--no-neighbours";
        if (!changesTrees) continue;
        mix(a.data(), a.size() + 1);
        if (a == "--camera" && i + 1 < argv.size()) mix(argv[i + 1].data(), argv[i + 1].size());
    }
    char hex[17];
    std::snprintf(hex, sizeof hex, "%016llx", static_cast<unsigned long long>(h));
    return hex;
}

} // namespace

int runForest(const std::vector<std::string>& argv) {
    std::vector<std::string> valueOptions{"-o",        "--output", "--camera",
                                          "--threads", "--tile",   "--season"};
    valueOptions.insert(valueOptions.end(), kWindValueOptions.begin(), kWindValueOptions.end());
    const Args args(argv, valueOptions,
                    {"--stats", "--no-lod", "--no-adapt", "--no-neighbours", "--no-instancing",
                     "--grow-unique", "--instance-tables", "--naive-placement", "--fsync",
                     "--full-precision", "--assimp-gltf", "--wind"});
    if (args.positional().size() != 1) throw UsageError(commandUsageLine("forest"));
    auto output = args.value("-o");
    if (!output) output = args.value("--output");
    if (!output) throw UsageError("forest needs an output file: -o out.obj");
    const bool usda = isUsda(*output);
    if (usda && args.flag("--instance-tables"))
        throw UsageError("--instance-tables is for .obj, .glb and .fbx: a .usda holds its "
                         "instances itself");
    if (auto threads = args.integer("--threads", 1, 1024))
        omp_set_num_threads(static_cast<int>(*threads));
    forest::ForestOptions options;
    if (auto tile = args.value("--tile")) {
        try {
            std::tie(options.tile, options.tileCount) = placement::parseTileSpec(*tile);
        } catch (const InvalidInput& e) {
            throw UsageError(e.what());
        }
    }
    options.useLod = !args.flag("--no-lod");
    options.adapt = !args.flag("--no-adapt");
    options.neighbours = !args.flag("--no-neighbours");
    options.instancing = !args.flag("--no-instancing");
    options.adaptVariants = !args.flag("--grow-unique");
    if (args.flag("--naive-placement")) options.placement = placement::PlacementMethod::Naive;
    const bool wind = args.flag("--wind");
    if (wind && usda)
        throw UsageError("--wind writes .glb, .gltf, .fbx or .obj (with its .wind.csv), not .usda");
    const exporter::WindExportOptions windSettings = windOptions(args);
    options.windData = wind;
    const bool obj = std::filesystem::path(*output).extension() == ".obj";

    const auto start = Clock::now();
    std::optional<mesh::Season> season;
    if (auto name = args.value("--season")) season = parseSeasonOption(*name);
    doc::Project project = loadProjectOrScene(args.positional()[0]);
    if (season) {
        // The whole forest in one season: the trees' own seasons give way too.
        project.season = std::string(mesh::seasonName(*season));
        for (doc::ProjectInstance& tree : project.instances)
            tree.season.clear();
    }
    forest::ForestScene forestScene = doc::makeForestScene(project);
    if (auto camera = args.value("--camera")) forestScene.camera = parseVec3(*camera, "--camera");
    const double loadMs = msSince(start);

    // Ctrl-C is caught from here on, before the exporter creates its temporary file.
    TerminalProgress progress;
    // Forests default to compact OBJ (0.1 mm, relative indices): ~17 % less to format and write.
    // One writer by the extension: USD streams trees and instances itself; the others go through
    // TreeExporter (OBJ streamed, glTF written by our own, FBX through Assimp).
    std::optional<TreeExporter> exporter;
    std::optional<exporter::usd::UsdStageWriter> usdWriter;
    if (usda) {
        exporter::usd::UsdLayerOptions layer;
        for (const forest::SceneSpecies& s : forestScene.species)
            layer.species.push_back(s.name);
        layer.tile = options.tile;
        layer.tileCount = options.tileCount;
        layer.sceneKey = sceneKey(args.positional()[0], argv);
        layer.compact = !args.flag("--full-precision");
        layer.durability = args.flag("--fsync") ? Durability::Durable : Durability::Atomic;
        layer.shippedTextures = exporter::resourcesDir() / "textures";
        usdWriter.emplace(*output, std::move(layer));
        // Instancing writer: instances take the variants' meshes, no per-instance LOD mesh.
        options.meshInstances = false;
        // Variants come before the first batch: USD writes them as prototypes at the end.
        options.onVariants = [&](const std::vector<forest::ForestVariant>& variants) {
            std::vector<exporter::usd::UsdVariant> out;
            for (const forest::ForestVariant& v : variants)
                out.push_back({v.species, v.index, v.mesh});
            usdWriter->setVariants(std::move(out));
        };
    } else if (!wind || obj) {
        // With --wind, .glb/.gltf/.fbx go through the wind exporter (rig, clip, _WIND* data);
        // an OBJ is written as without, plus the wind table beside it.
        exporter.emplace(
            *output, exporter::ObjChoices{args.flag("--fsync"), !args.flag("--full-precision")});
        exporter->setInstanceTables(args.flag("--instance-tables"));
        exporter->setProgress(progress);
        exporter->setAssimpGltf(args.flag("--assimp-gltf"));
        // Instancing writers take the variants' meshes: no per-instance LOD mesh to make.
        options.meshInstances = !exporter->writesInstances();
        // Variants come before the first batch: glTF writes each variant's mesh once, now.
        options.onVariants = [&](const std::vector<forest::ForestVariant>& variants) {
            std::vector<exporter::ExportVariant> out;
            for (const forest::ForestVariant& v : variants)
                out.push_back({v.name, v.mesh});
            exporter->addVariants(out);
        };
    }
    std::optional<exporter::WindExporter> windExporter;
    if (wind) windExporter.emplace(*output, windSettings, progress);
    double writeMs = 0;
    forest::ForestStats stats;
    try {
        stats = forest::buildForest(
            forestScene, options,
            [&](const std::vector<forest::ForestTree>& batch) {
                const auto t = Clock::now();
                if (usdWriter) {
                    std::vector<exporter::usd::UsdTree> trees;
                    trees.reserve(batch.size());
                    for (const forest::ForestTree& tree : batch)
                        trees.push_back({tree.instance.id, tree.instance.species, tree.variant,
                                         tree.instance.position, tree.instance.rotation,
                                         tree.instance.scale * tree.instance.growth, tree.mesh,
                                         tree.meshCameraDistance});
                    usdWriter->add(trees, progress);
                } else {
                    std::vector<ExportTree> trees;
                    trees.reserve(batch.size());
                    for (const forest::ForestTree& tree : batch)
                        trees.push_back({tree.name, tree.mesh, tree.instance.position,
                                         tree.instance.rotation,
                                         tree.instance.scale * tree.instance.growth, tree.variant,
                                         tree.instance.id});
                    if (exporter) exporter->add(trees);
                }
                if (windExporter) {
                    std::vector<exporter::WindExportTree> windy;
                    for (const forest::ForestTree& tree : batch)
                        windy.push_back({tree.name, tree.mesh, tree.skeleton,
                                         tree.instance.position, tree.instance.rotation,
                                         tree.instance.scale * tree.instance.growth});
                    windExporter->add(windy);
                }
                progress.checkCancelled();
                writeMs += msSince(t);
            },
            progress);
        const auto t = Clock::now();
        if (usdWriter)
            usdWriter->commit(progress);
        else if (exporter)
            exporter->commit();
        if (windExporter) windExporter->commit();
        writeMs += msSince(t);
    } catch (const Cancelled&) {
        progress.finish();
        std::fprintf(stderr, "sylva-cli: interrupted; no output written\n");
        return kInterrupted;
    }
    progress.finish();
    for (const placement::Shortfall& s : stats.shortfalls)
        std::fprintf(
            stderr, "sylva-cli: warning: domain %zu: placed %zu of %zu '%s' (no room left)\n",
            s.domain + 1, s.placed, s.requested, forestScene.species[s.species].name.c_str());

    if (args.flag("--stats")) {
        std::string json = "{";
        appendJsonNumber(json, "trees", static_cast<double>(stats.trees));
        appendJsonNumber(json, "trees_in_scene", static_cast<double>(stats.treesInScene));
        appendJsonNumber(json, "tile", options.tile + 1);
        appendJsonNumber(json, "tiles", options.tileCount);
        appendJsonNumber(json, "threads", omp_get_max_threads());
        appendJsonNumber(json, "vertices", static_cast<double>(stats.vertices));
        appendJsonNumber(json, "triangles", static_cast<double>(stats.triangles));
        appendJsonNumber(json, "obstacle_triangles",
                         forestScene.obstacles
                             ? static_cast<double>(forestScene.obstacles->triangleCount())
                             : 0.0);
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
        if (usdWriter) {
            const exporter::usd::UsdLayerStats& u = usdWriter->stats();
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
        appendJsonNumber(json, "load", loadMs);
        for (const auto& [k, v] : stats.wallMs)
            appendJsonNumber(json, k.c_str(), v);
        appendJsonNumber(json, "write", writeMs);
        appendJsonNumber(json, "total", msSince(start), false);
        json += "},\"cpu_ms\":{";
        bool first = true;
        for (const auto& [k, v] : stats.cpuMs) {
            if (!first) json += ",";
            first = false;
            appendJsonNumber(json, k.c_str(), v, false);
        }
        json += "}}\n";
        std::fwrite(json.data(), 1, json.size(), stdout);
    }
    return kOk;
}

} // namespace sylva::cli
