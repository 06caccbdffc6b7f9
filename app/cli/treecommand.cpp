#include "cliargs.h"
#include "clishared.h"
#include "commands.h"
#include "terminalprogress.h"
#include "usage.h"

#include "document/speciesfile.h"
#include "engine/export/treeexport.h"
#include "engine/graph/graph.h"
#include "engine/mesh/season.h"
#include "engine/util/error.h"

#include <QString>

#include <chrono>
#include <cstdio>
#include <filesystem>

namespace sylva::cli {

using exporter::ExportTree;
using exporter::TreeExporter;

namespace {

/// "node.param=value" → (node, param, value). Values are JSON when they parse as JSON
/// (numbers, true/false, arrays, objects), plain strings otherwise.
void applySet(graph::Evaluator& evaluator, const std::string& assignment) {
    const auto eq = assignment.find('=');
    const auto dot = assignment.find('.');
    if (eq == std::string::npos || dot == std::string::npos || dot > eq || dot == 0 ||
        dot + 1 == eq)
        throw UsageError("--set expects node.param=value, got '" + assignment + "'");
    evaluator.setParam(assignment.substr(0, dot), assignment.substr(dot + 1, eq - dot - 1),
                       sylva::Value::parseLoose(assignment.substr(eq + 1)));
}

} // namespace

int runTree(const std::vector<std::string>& argv) {
    std::vector<std::string> valueOptions{"-o",     "--output", "-n",      "--generations",
                                          "--seed", "--set",    "--season"};
    valueOptions.insert(valueOptions.end(), windValueOptions().begin(), windValueOptions().end());
    const Args args(argv, valueOptions, {"--stats", "--fsync", "--compact", "--wind"});
    if (args.positional().size() != 1) throw UsageError(commandUsageLine("tree"));
    auto output = args.value("-o");
    if (!output) output = args.value("--output");
    if (!output) throw UsageError("tree needs an output file: -o out.obj");

    graph::registerBuiltinNodeTypes();
    graph::SpeciesGraph species = doc::loadSpecies(QString::fromStdString(args.positional()[0]));
    graph::Evaluator evaluator(std::move(species));

    auto n = args.integer("-n", 0, 1000);
    if (!n) n = args.integer("--generations", 0, 1000);
    if (n) {
        bool any = false;
        // Every generator that counts generations (the type declares the parameter).
        for (const graph::NodeDesc& node : evaluator.graph().nodes)
            if (const graph::NodeType* type = graph::findType(node.type);
                type && type->findParam("generations")) {
                evaluator.setParam(node.id, "generations", sylva::Value(static_cast<double>(*n)));
                any = true;
            }
        if (!any)
            throw UsageError("-n applies to L-system species; this species has no lsystem node");
    }
    for (const std::string& s : args.values("--set"))
        applySet(evaluator, s);
    const bool wind = args.flag("--wind");
    const exporter::WindExportOptions windSettings = windOptions(args);
    if (wind)
        for (const graph::NodeDesc& node : evaluator.graph().nodes)
            if (graph::roleOf(node.type) == graph::NodeRole::Mesher)
                evaluator.setParam(node.id, "wind_data", sylva::Value(true));
    if (auto name = args.value("--season")) {
        // The season is the meshing node's parameter: --season autumn is --set mesh.season=autumn
        // on the output node.
        const mesh::Season season = parseSeasonOption(*name);
        const graph::NodeDesc* out = graph::meshOutput(evaluator.graph());
        if (!out) throw UsageError("--season needs a species whose output node is a tube_mesh");
        evaluator.setParam(out->id, "season", sylva::Value(std::string(mesh::seasonName(season))));
    }

    const auto seed = args.integer("--seed", 0, (1LL << 62));
    const graph::NodeOutput& result =
        seed ? evaluator.evaluate(static_cast<std::uint64_t>(*seed)) : evaluator.evaluate();
    if (!result.mesh)
        throw InvalidInput("the species' output node '" + evaluator.graph().output +
                           "' produces no mesh; end the graph with a tube_mesh node");

    const auto t0 = std::chrono::steady_clock::now();
    // Ctrl-C and SIGTERM from here on stop the writer and remove its temporary (before, the
    // default action ends the process with nothing on disk yet).
    TerminalProgress progress;
    const std::string name = exporter::objectNameFor(evaluator.graph().name);
    // The geometry by the format table's row; with wind, a format that carries the rig goes
    // through the wind exporter alone, one with the table only (OBJ) as without plus its table.
    if (!wind || exporter::formatFor(*output).wind != exporter::WindSupport::Rig) {
        exporter::ForestWriterOptions options;
        options.species = {name};
        options.fsync = args.flag("--fsync");
        options.compact = args.flag("--compact");
        TreeExporter exporter(*output, options);
        exporter.add({ExportTree{name, result.mesh}});
        exporter.setProgress(progress);
        exporter.commit();
    }
    if (wind) {
        if (!result.skeleton) throw InvalidInput("--wind needs the species' skeleton");
        exporter::WindExporter windExporter(*output, windSettings, progress);
        windExporter.add({{name, result.mesh, result.skeleton}});
        windExporter.commit();
    }
    const double writeMs =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();

    if (args.flag("--stats")) {
        auto stat = [&](const char* key) {
            auto it = result.stats.find(key);
            return it == result.stats.end() ? 0.0 : it->second;
        };
        std::string json = "{";
        appendJsonNumber(json, "symbols", stat("symbols"));
        appendJsonNumber(json, "segments", stat("segments"));
        appendJsonNumber(json, "leaves", stat("leaves"));
        appendJsonNumber(json, "vertices", static_cast<double>(result.mesh->vertexCount()));
        appendJsonNumber(json, "triangles", static_cast<double>(result.mesh->triangleCount()));
        // Height from the skeleton itself, whatever node grew it.
        glm::vec3 lo(0.0f), hi(0.0f);
        if (result.skeleton) result.skeleton->bounds(lo, hi);
        appendJsonNumber(json, "height", result.skeleton ? hi.y - lo.y : stat("height"));
        // Self-organizing growth: metamers, those shed over the run, and those the next cycle
        // would shed (light per internode below the threshold; red in the editor's light view).
        for (const char* key : {"internodes", "cycles", "shed", "starved"})
            if (result.stats.count(key) != 0) appendJsonNumber(json, key, stat(key));
        json += "\"timings_ms\":{";
        for (const auto& [k, v] : result.timingsMs)
            appendJsonNumber(json, k.c_str(), v);
        appendJsonNumber(json, "write", writeMs, false);
        json += "}}\n";
        std::fwrite(json.data(), 1, json.size(), stdout);
    }
    return kOk;
}

} // namespace sylva::cli
