#include "ui/generation/exportshown.h"

#include <set>

#include "document/projectexport.h"
#include "engine/export/treeexport.h"
#include "engine/util/error.h"

namespace sylva::ui {

ExportCount exportShown(const QString& path, const ShownScene& shown, const ExportOptions& options,
                        Progress& progress) {
    const doc::Document* document = shown.document;
    ExportCount count;
    if (document) {
        // A project: the export every front door asks for (doc::exportProject), as sylva-cli
        // forest writes it, with the editor's choices translated into the request.
        doc::ExportRequest request;
        request.path = path.toStdString();
        if (options.viewportCamera) request.camera = shown.eye;
        if (!options.projectWind) request.wind = false;
        if (options.selectionOnly) {
            std::set<std::uint64_t> ids;
            for (doc::TreeId id : document->selectedTrees())
                ids.insert(id);
            if (ids.empty())
                throw InvalidInput("nothing to export: no hand-placed tree is selected");
            request.trees = std::move(ids);
        }
        const doc::ExportReport report = doc::exportProject(document->project(), request, progress);
        count.trees = report.written;
        count.files = report.files.size();
        count.wind = report.wind;
        return count;
    }
    // A species preview: its one tree, as sylva-cli tree writes it.
    const GenerationResult& source = shown.result;
    exporter::ForestWriterOptions writerOptions;
    writerOptions.compact = source.compactObj;
    // The species by number; its one name is the object name the tree carries (a USD stage's
    // species scope).
    writerOptions.species = {source.exportTrees.empty() ? std::string("tree")
                                                        : source.exportTrees.front().name};
    exporter::TreeExporter writer(path.toStdString(), writerOptions);
    writer.setProgress(progress);
    writer.addVariants(source.exportVariants);
    writer.add(source.exportTrees);
    count.trees = source.exportTrees.size();
    count.files = writer.commit().size();
    return count;
}

} // namespace sylva::ui
