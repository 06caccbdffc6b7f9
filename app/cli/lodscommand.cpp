#include "cliargs.h"
#include "commands.h"
#include "usage.h"

#include "document/speciesfile.h"
#include "engine/export/lodexport.h"
#include "engine/export/treeexport.h"
#include "engine/nodes/meshnodes.h"
#include "engine/util/error.h"

#include <QString>

#include <cstdio>

namespace sylva::cli {

using exporter::resourcesDir;

int runLods(const std::vector<std::string>& argv) {
    const Args args(argv, {"-o", "--output", "--seed"}, {"--json", "--no-glb", "--no-obj"});
    if (args.positional().size() != 1) throw UsageError(commandUsageLine("lods"));
    auto dir = args.value("-o");
    if (!dir) dir = args.value("--output");
    if (!dir) throw UsageError("lods needs an output folder: -o <folder>");

    graph::registerBuiltinNodeTypes();
    const graph::SpeciesGraph species =
        doc::loadSpecies(QString::fromStdString(args.positional()[0]));
    const graph::NodeDesc* out = species.findNode(species.output);
    if (!out || out->type != "tube_mesh" || out->inputs.size() != 1)
        throw InvalidInput("lods needs a species whose output is a tube_mesh node");
    graph::Evaluator evaluator(species);
    const auto seed = args.integer("--seed", 0, (1LL << 62));
    const graph::NodeOutput& grown = evaluator.evaluateNode(
        species.skeletonSource(), seed.has_value(), seed ? static_cast<std::uint64_t>(*seed) : 0);
    if (!grown.skeleton) throw InvalidInput("the species produces no skeleton");

    const mesh::TreeMeshSettings settings =
        mesh::treeMeshSettingsFromParams(out->params, 0, species.baseDir);
    exporter::LodExportOptions options;
    options.obj = !args.flag("--no-obj");
    options.glb = !args.flag("--no-glb");
    if (const auto res = resourcesDir(); !res.empty()) options.textureSource = res / "textures";
    const exporter::LodChainFiles files =
        exporter::writeLodChain(*dir, species.name, *grown.skeleton, settings, options);

    if (args.flag("--json")) {
        std::string json = "{\"levels\":[";
        for (std::size_t i = 0; i < files.levels.size(); ++i) {
            const exporter::LodFileLevel& l = files.levels[i];
            char buf[256];
            std::snprintf(
                buf, sizeof buf,
                "%s{\"name\":\"%s\",\"distance_m\":%g,\"triangles\":%zu,\"vertices\":%zu}",
                i ? "," : "", l.name.c_str(), l.distance, l.triangles, l.vertices);
            json += buf;
        }
        json += "]}\n";
        std::fwrite(json.data(), 1, json.size(), stdout);
    } else {
        std::printf("%-32s %14s %12s %12s\n", "level", "from (m)", "triangles", "vertices");
        for (const exporter::LodFileLevel& l : files.levels)
            std::printf("%-32s %14.1f %12zu %12zu\n", l.name.c_str(), l.distance, l.triangles,
                        l.vertices);
        if (!files.glbPath.empty()) std::printf("glTF: %s\n", files.glbPath.string().c_str());
    }
    return kOk;
}

} // namespace sylva::cli
