#include "ui/generation/treegenerator.h"

#include "document/errormessage.h"
#include "document/filerefs.h"

#include <algorithm>
#include <exception>
#include <filesystem>
#include <limits>

#include <QElapsedTimer>
#include <QFileInfo>
#include <QObject>
#include <QStringList>

#include "document/speciesfile.h"
#include "engine/graph/graph.h"
#include "engine/mesh/mesh.h"
#include "engine/skeleton/skeleton.h"
#include "engine/util/error.h"
#include "ui/generation/windvertexdata.h"

namespace sylva::ui {

std::size_t GenerationResult::vertexCount() const {
    std::size_t n = mesh ? mesh->vertexCount() : 0;
    for (const DrawnTree& t : trees)
        n += t.mesh ? t.mesh->vertexCount() : 0;
    return n;
}

std::size_t GenerationResult::triangleCount() const {
    std::size_t n = mesh ? mesh->triangleCount() : 0;
    for (const DrawnTree& t : trees)
        n += t.mesh ? t.mesh->triangleCount() : 0;
    return n;
}

double GenerationResult::height() const {
    if (auto it = stats.find("height"); it != stats.end()) return it->second;
    if (!mesh || mesh->empty()) return 0.0;
    float lo = std::numeric_limits<float>::max();
    float hi = std::numeric_limits<float>::lowest();
    for (const auto& p : mesh->positions) {
        lo = std::min(lo, p.y);
        hi = std::max(hi, p.y);
    }
    return double(hi - lo);
}

double GenerationResult::segments() const {
    if (auto it = stats.find("segments"); it != stats.end()) return it->second;
    return skeleton ? double(skeleton->segmentCount()) : 0.0;
}

GenerationResult generateTree(const QString& path, Progress& progress) {
    return runGuarded(path, [&](GenerationResult& result) {
        graph::SpeciesGraph species = doc::loadSpecies(path);
        doc::addSpeciesSourceFiles(species, result.sources);
        stampSources(result); // before the evaluation reads the grammar files
        if (!species.name.empty()) result.speciesName = QString::fromStdString(species.name);
        // The viewport colours the tree by node attributes and sways it in the wind: ask the
        // mesher which node each vertex belongs to.
        requestNodeIds(species);
        graph::Evaluator evaluator(std::move(species));
        const graph::NodeOutput& output = evaluator.evaluate(progress);
        result.mesh = output.mesh;
        result.skeleton = output.skeleton;
        result.stats = output.stats;
        result.timingsMs = output.timingsMs;
        result.exportTrees = {
            exporter::ExportTree{exporter::objectNameFor(evaluator.graph().name), output.mesh}};
        if (!result.mesh || result.mesh->empty())
            result.error = QObject::tr("%1: the species' output node produced no mesh")
                               .arg(QFileInfo(path).fileName());
    });
}

void stampSources(GenerationResult& result) {
    for (qsizetype i = result.sourceStamps.size(); i < result.sources.size(); ++i) {
        const QFileInfo info(result.sources[i]);
        result.sourceStamps << (info.exists() ? info.lastModified() : QDateTime());
    }
}

GenerationResult runGuarded(const QString& path,
                            const std::function<void(GenerationResult&)>& body) {
    GenerationResult result;
    result.path = path;
    result.sources << QFileInfo(path).absoluteFilePath();
    stampSources(result);
    result.speciesName = QFileInfo(path).completeBaseName();
    QElapsedTimer timer;
    timer.start();
    try {
        graph::registerBuiltinNodeTypes();
        body(result);
    } catch (...) {
        const doc::ErrorReport report =
            doc::describeError(std::current_exception(), QFileInfo(path).fileName().toStdString());
        if (report.kind == doc::ErrorReport::Kind::Cancelled)
            result.cancelled = true;
        else
            result.error = QString::fromStdString(report.message);
    }
    result.elapsedMs = double(timer.nsecsElapsed()) * 1e-6;
    return result;
}

} // namespace sylva::ui
