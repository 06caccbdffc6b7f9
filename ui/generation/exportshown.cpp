#include "ui/generation/exportshown.h"

#include <vector>

#include "engine/export/treeexport.h"
#include "engine/util/error.h"
#include "ui/generation/scenegenerator.h"

namespace sylva::ui {

ExportCount exportShown(const QString& path, const ShownScene& shown,
                        const ExportOptions& options) {
    const GenerationResult* source = &shown.result;
    const doc::Document* document = shown.document;
    GenerationResult rebuilt;
    std::vector<exporter::ExportTree> trees;
    if (options.viewportCamera && document) {
        // The same forest with the viewport's eye as the LOD reference.
        doc::Project project = document->project();
        project.cameraPosition = shown.eye;
        project.cameraTarget = shown.target;
        rebuilt = generateProject(project, document->path(), nullptr);
        if (!rebuilt.ok()) throw IoError(rebuilt.error.toStdString());
        source = &rebuilt;
    }
    if (options.selectionOnly && document) {
        const QList<doc::TreeId> ids = document->selectedTrees();
        for (std::size_t i = 0; i < source->trees.size() && i < source->exportTrees.size(); ++i)
            if (source->trees[i].docId && ids.contains(source->trees[i].docId))
                trees.push_back(source->exportTrees[i]);
        if (trees.empty()) throw InvalidInput("nothing to export: no hand-placed tree is selected");
    } else {
        trees = source->exportTrees;
    }
    exporter::TreeExporter out(path.toStdString(), {false, source->compactObj});
    out.addVariants(source->exportVariants);
    out.add(trees);
    ExportCount count;
    count.files = out.commit().size();
    count.trees = trees.size();
    return count;
}

} // namespace sylva::ui
