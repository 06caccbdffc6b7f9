#include "ui/generation/exportlodchain.h"

#include <QFileInfo>

#include "document/speciestree.h"
#include "engine/export/exportnames.h"
#include "engine/export/treeexport.h"
#include "engine/util/error.h"

namespace sylva::ui {

std::optional<LodChainSource> lodChainSource(const ShownScene& shown) {
    const GenerationResult& result = shown.result;
    if (!shown.document) {
        if (result.path.isEmpty() || !result.skeleton) return std::nullopt;
        LodChainSource s;
        s.speciesFile = result.path;
        s.name = QFileInfo(result.path).completeBaseName().toStdString();
        if (s.name.empty()) s.name = "tree";
        return s;
    }
    const QList<doc::TreeId> ids = shown.document->selectedTrees();
    if (ids.size() != 1) return std::nullopt;
    for (const DrawnTree& tree : result.trees) {
        if (tree.docId != ids.front() || !tree.lod.skeleton || !tree.lod.settings) continue;
        LodChainSource s;
        const auto& species = shown.document->project().species;
        const std::string speciesName =
            tree.species < species.size() ? species[tree.species].name : std::string("tree");
        s.name = exporter::fileSafeName(speciesName) + "_tree" + std::to_string(tree.docId);
        s.skeleton = tree.lod.skeleton;
        s.settings = tree.lod.settings;
        return s;
    }
    return std::nullopt;
}

exporter::GameLodFiles exportLodChain(const std::filesystem::path& dir,
                                      const LodChainSource& source, Progress& progress) {
    exporter::GameLodOptions options;
    if (const std::filesystem::path res = exporter::resourcesDir(); !res.empty())
        options.shippedTextures = res / "textures";
    const mesh::LodChainSettings chain; // sylva-cli lods' defaults
    if (!source.speciesFile.isEmpty()) {
        progress.report(0.0, "grow");
        const doc::SpeciesTree tree =
            doc::growSpeciesTree(source.speciesFile, std::nullopt, progress);
        return exporter::writeTreeLodChain(dir, source.name, *tree.skeleton, tree.settings, chain,
                                           options, progress);
    }
    if (!source.skeleton || !source.settings)
        throw InvalidInput("the selected tree was not kept with its skeleton");
    return exporter::writeTreeLodChain(dir, source.name, *source.skeleton, *source.settings, chain,
                                       options, progress);
}

} // namespace sylva::ui
