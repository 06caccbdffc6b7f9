#include "cliargs.h"
#include "clishared.h"
#include "commands.h"
#include "terminalprogress.h"
#include "usage.h"

#include "document/project.h"
#include "document/scenebuild.h"
#include "document/speciesfile.h"
#include "engine/forest/forestbuild.h"
#include "engine/forest/metrics.h"
#include "engine/util/error.h"

#include <QString>

#include <cstdio>
#include <optional>

namespace sylva::cli {

namespace {

void printTable(const forest::SceneMetrics& m, bool perTree) {
    std::printf("%-28s %14zu\n", "trees", m.trees);
    std::printf("%-28s %14.2f\n", perTree ? "height (m)" : "mean height (m)", m.meanHeightM);
    std::printf("%-28s %14.3f\n", perTree ? "DBH at 1.3 m (m)" : "mean DBH at 1.3 m (m)",
                m.meanDbhM);
    std::printf("%-28s %14.2f\n", perTree ? "crown width (m)" : "mean crown width (m)",
                m.meanCrownWidthM);
    std::printf("%-28s %14.4f\n", "wood volume (m3)", m.woodVolumeM3);
    std::printf("%-28s %14.2f\n", "dry biomass (kg)", m.dryBiomassKg);
    std::printf("%-28s %14.2f\n", "carbon (kg)", m.carbonKg);
    std::printf("%-28s %14.2f\n", "CO2 equivalent (kg)", m.co2Kg);
    std::printf("%-28s %14.2f\n", "Chave 2014 AGB (kg)", m.chaveAgbKg);
}

} // namespace

int runStats(const std::vector<std::string>& argv) {
    const Args args(argv, {"--seed"}, {"--json"});
    if (args.positional().size() != 1) throw UsageError(commandUsageLine("stats"));
    const std::string path = args.positional()[0];
    const bool isProject = path.ends_with(".sylva") || path.ends_with(".scene.json");
    forest::SceneMetrics metrics;
    std::string perTree; // JSON objects, one per tree of a project
    std::optional<forest::ForestStats> forestStats;
    if (isProject) {
        const doc::Project project = loadProjectOrScene(path);
        forest::ForestOptions options;
        options.buildMeshes = false;
        TerminalProgress progress;
        const forest::ForestStats stats = forest::buildForest(
            doc::makeForestScene(project), options,
            [&](const std::vector<forest::ForestTree>& batch) {
                for (const forest::ForestTree& t : batch) {
                    forest::SceneMetrics one;
                    one.add(t.metrics);
                    std::string obj = metricsJson(one);
                    obj.erase(0, obj.find(',') + 1); // drop "trees":1
                    // Appended piece by piece: GCC 12 warns falsely (-Wrestrict) on a + chain.
                    if (!perTree.empty()) perTree.push_back(',');
                    perTree.append("{\"name\":\"");
                    perTree.append(t.name);
                    perTree.append("\",\"id\":");
                    perTree.append(std::to_string(t.instance.id));
                    perTree.append(",\"variant\":");
                    perTree.append(std::to_string(t.variant));
                    perTree.push_back(',');
                    perTree.append(obj);
                }
            },
            progress);
        progress.finish();
        metrics = stats.metrics;
        forestStats = stats;
    } else {
        graph::registerBuiltinNodeTypes();
        const graph::SpeciesGraph species = doc::loadSpecies(QString::fromStdString(path));
        graph::Evaluator evaluator(species);
        const std::string& node = species.skeletonSource();
        const auto seed = args.integer("--seed", 0, (1LL << 62));
        const graph::NodeOutput& result = evaluator.evaluateNode(
            node, seed.has_value(), seed ? static_cast<std::uint64_t>(*seed) : 0);
        if (!result.skeleton) throw InvalidInput(path + ": the species produces no skeleton");
        forest::WoodProperties wood;
        wood.densityKgM3 = species.traits.woodDensity;
        wood.carbonFraction = species.traits.carbonFraction;
        metrics.add(forest::measureTree(*result.skeleton, wood));
    }
    if (args.flag("--json")) {
        std::string json = metricsJson(metrics);
        if (isProject) {
            json.pop_back(); // the closing brace
            json.append(",\"instanced\":" + std::to_string(forestStats->instanced));
            json.append(",\"unique\":" + std::to_string(forestStats->unique));
            json.append(",\"variants\":" + std::to_string(forestStats->variants));
            json.append(",\"per_tree\":[");
            json.append(perTree);
            json.append("]}");
        }
        json += "\n";
        std::fwrite(json.data(), 1, json.size(), stdout);
    } else {
        printTable(metrics, !isProject);
        if (forestStats) {
            std::printf("%-28s %14zu\n", "instanced trees", forestStats->instanced);
            std::printf("%-28s %14zu\n", "unique trees", forestStats->unique);
            std::printf("%-28s %14zu\n", "variants", forestStats->variants);
        }
    }
    return kOk;
}

} // namespace sylva::cli
