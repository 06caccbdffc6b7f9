#include "ui/generation/exportshown.h"

#include <vector>

#include <QFileInfo>

#include <filesystem>

#include "engine/export/treeexport.h"
#include "engine/export/windexport.h"
#include "engine/util/error.h"
#include "ui/generation/scenegenerator.h"

namespace sylva::ui {

namespace {

bool windFormat(const QString& path) {
    const QString ext = QFileInfo(path).suffix().toLower();
    return ext == QLatin1String("glb") || ext == QLatin1String("gltf") ||
           ext == QLatin1String("fbx") || ext == QLatin1String("obj");
}

} // namespace

ExportCount exportShown(const QString& path, const ShownScene& shown,
                        const ExportOptions& options) {
    const GenerationResult* source = &shown.result;
    const doc::Document* document = shown.document;
    const bool wind =
        options.projectWind && document && document->project().wind && windFormat(path);
    GenerationResult rebuilt;
    std::vector<std::size_t> chosen; // indices into source->exportTrees
    if ((options.viewportCamera || wind) && document) {
        // The same forest, with the viewport's eye as the LOD reference and/or with the node
        // ids and skeletons a wind export needs.
        doc::Project project = document->project();
        if (options.viewportCamera) {
            project.cameraPosition = shown.eye;
            project.cameraTarget = shown.target;
        }
        rebuilt = generateProject(project, document->path(), nullptr, noProgress(), wind);
        if (!rebuilt.ok()) throw IoError(rebuilt.error.toStdString());
        source = &rebuilt;
    }
    if (options.selectionOnly && document) {
        const QList<doc::TreeId> ids = document->selectedTrees();
        for (std::size_t i = 0; i < source->trees.size() && i < source->exportTrees.size(); ++i)
            if (source->trees[i].docId && ids.contains(source->trees[i].docId)) chosen.push_back(i);
        if (chosen.empty())
            throw InvalidInput("nothing to export: no hand-placed tree is selected");
    } else {
        for (std::size_t i = 0; i < source->exportTrees.size(); ++i)
            chosen.push_back(i);
    }
    std::vector<exporter::ExportTree> trees;
    for (std::size_t i : chosen)
        trees.push_back(source->exportTrees[i]);
    ExportCount count;
    count.trees = trees.size();
    const std::string out = path.toStdString();
    if (!wind || QFileInfo(path).suffix().toLower() == QLatin1String("obj")) {
        // As sylva-cli forest --wind: an OBJ is written as without wind, its table beside it.
        exporter::TreeExporter writer(out, {false, source->compactObj});
        writer.addVariants(source->exportVariants);
        writer.add(trees);
        count.files += writer.commit().size();
    }
    if (wind) {
        const doc::ProjectWind& w = *document->project().wind;
        exporter::WindExportOptions settings;
        settings.wind.direction = w.direction;
        settings.wind.strength = w.strength;
        settings.wind.gustiness = w.gustiness;
        settings.wind.frequency = w.frequency;
        exporter::WindExporter writer(out, settings);
        std::vector<exporter::WindExportTree> windy;
        for (std::size_t i : chosen) {
            const exporter::ExportTree& t = source->exportTrees[i];
            windy.push_back(
                {t.name, t.mesh, source->exportSkeletons.at(i), t.position, t.rotationY, t.scale});
        }
        writer.add(windy);
        count.files += writer.commit().size();
        count.wind = true;
    }
    return count;
}

} // namespace sylva::ui
