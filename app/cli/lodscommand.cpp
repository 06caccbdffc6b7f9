#include "cliargs.h"
#include "commands.h"
#include "terminalprogress.h"
#include "usage.h"

#include "document/speciestree.h"
#include "engine/export/lodchainexport.h"
#include "engine/export/treeexport.h"
#include "engine/mesh/lodchain.h"
#include "engine/nodes/meshnodes.h"
#include "engine/util/error.h"

#include <QString>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <sstream>

namespace sylva::cli {

using exporter::resourcesDir;

namespace {

/// "1,0.35,0.12,0.04" → the numbers; InvalidInput naming the bad entry.
std::vector<double> parseBudgets(const std::string& text) {
    std::vector<double> out;
    std::stringstream in(text);
    std::string item;
    while (std::getline(in, item, ',')) {
        char* end = nullptr;
        const double v = std::strtod(item.c_str(), &end);
        if (item.empty() || !end || *end != '\0')
            throw InvalidInput("--budgets: '" + item +
                               "' is not a number (fractions of LOD0's triangles, e.g. "
                               "1,0.35,0.12,0.04)");
        out.push_back(v);
    }
    return out;
}

/// File names come from the species file's name ("english-oak"), as a pipeline names assets.
std::string speciesFileStem(const std::string& path) {
    const std::string stem = std::filesystem::path(path).stem().string();
    return stem.empty() ? std::string("tree") : stem;
}

} // namespace

int runLods(const std::vector<std::string>& argv) {
    const Args args(argv,
                    {"-o", "--output", "--seed", "--budgets", "--impostor-grid", "--impostor-cell",
                     "--impostor-pixels", "--min-silhouette"},
                    {"--json", "--no-glb", "--no-obj", "--no-fbx", "--no-usd", "--no-impostor",
                     "--octahedral"});
    if (args.positional().size() != 1) throw UsageError(commandUsageLine("lods"));
    auto dir = args.value("-o");
    if (!dir) dir = args.value("--output");
    if (!dir) throw UsageError("lods needs an output folder: -o <folder>");

    mesh::LodChainSettings chainSettings;
    if (const auto b = args.value("--budgets")) chainSettings.budgets = parseBudgets(*b);
    if (const auto g = args.integer("--impostor-grid", 2, 32))
        chainSettings.impostorSettings.grid = static_cast<int>(*g);
    if (const auto c = args.integer("--impostor-cell", 8, 2048))
        chainSettings.impostorSettings.cellPixels = static_cast<int>(*c);
    if (const auto p = args.integer("--impostor-pixels", 1, 4096))
        chainSettings.impostorPixels = static_cast<double>(*p);
    if (const auto m = args.value("--min-silhouette")) {
        char* end = nullptr;
        const double v = std::strtod(m->c_str(), &end);
        if (m->empty() || !end || *end != '\0' || !(v >= 0.0 && v <= 1.0))
            throw InvalidInput("--min-silhouette: '" + *m +
                               "' is not a number from 0 to 1 (the IoU each level keeps; 0: "
                               "no check)");
        chainSettings.minSilhouetteIoU = v;
    }
    chainSettings.impostorSettings.hemisphere = !args.flag("--octahedral");
    chainSettings.impostor = !args.flag("--no-impostor");
    mesh::validateLodChain(chainSettings);

    const auto seed = args.integer("--seed", 0, (1LL << 62));
    const doc::SpeciesTree tree = doc::growSpeciesTree(
        QString::fromStdString(args.positional()[0]),
        seed ? std::optional<std::uint64_t>(static_cast<std::uint64_t>(*seed)) : std::nullopt);
    exporter::GameLodOptions options;
    options.obj = !args.flag("--no-obj");
    options.gltf = !args.flag("--no-glb");
    options.fbx = !args.flag("--no-fbx");
    options.usd = !args.flag("--no-usd");
    const std::filesystem::path res = resourcesDir();
    if (!res.empty()) options.shippedTextures = res / "textures";
    // Ctrl-C stops the levels' search or the baking at its next mesh or view: nothing is
    // written before the chain is complete, and each file is written atomically.
    TerminalProgress progress;
    const exporter::GameLodFiles files =
        exporter::writeTreeLodChain(*dir, speciesFileStem(args.positional()[0]), *tree.skeleton,
                                    tree.settings, chainSettings, options, progress);
    progress.finish();

    if (args.flag("--json")) {
        std::fwrite(files.description.data(), 1, files.description.size(), stdout);
    } else {
        std::printf("%-32s %8s %14s %12s %12s %12s %10s\n", "level", "budget", "from (m)",
                    "screen size", "triangles", "vertices", "silhouette");
        for (const exporter::GameLodLevel& l : files.levels)
            std::printf("%-32s %7.0f%% %14.1f %12.3f %12zu %12zu %10.3f%s\n", l.name.c_str(),
                        l.budget * 100.0, l.distance, l.screenSize, l.triangles, l.vertices,
                        l.silhouetteIoU, l.budgetMet ? "" : "  (over budget)");
        for (const mesh::DroppedLevel& d : files.dropped)
            std::printf("%-32s %7.0f%%  dropped: %s\n", "(no level)", d.budget * 100.0,
                        d.reason.c_str());
        if (files.impostor)
            std::printf("%-32s %8s %14.1f %12.3f %12d %12d\n",
                        (speciesFileStem(args.positional()[0]) + "_impostor").c_str(), "",
                        files.impostorDistance, files.impostorScreenSize, 2, 4);
        if (!files.glb.empty()) std::printf("glTF: %s\n", files.glb.string().c_str());
        if (!files.fbx.empty()) std::printf("FBX: %s\n", files.fbx.string().c_str());
        if (!files.usd.empty()) std::printf("USD: %s\n", files.usd.string().c_str());
        std::printf("description: %s\n", files.json.string().c_str());
    }
    return kOk;
}

} // namespace sylva::cli
