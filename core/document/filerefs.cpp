#include "document/filerefs.h"

#include <QDir>
#include <QFile>
#include <QFileInfo>

#include <filesystem>

#include "document/speciesfile.h"

namespace sylva::doc {

using sylva::Value;

std::string relativeTo(const QString& baseDir, const QString& absolute) {
    if (baseDir.isEmpty()) return absolute.toStdString();
    return QDir(baseDir).relativeFilePath(absolute).toStdString();
}

namespace {

template <typename F> void forEachFileParam(Value& graph, F&& f) {
    if (!graph.isObject()) return;
    Value::Object& g = graph.objectRef();
    auto nodes = g.find("nodes");
    if (nodes == g.end() || !nodes->second.isArray()) return;
    for (Value& node : nodes->second.arrayRef()) {
        if (!node.isObject()) continue;
        auto params = node.objectRef().find("params");
        if (params == node.objectRef().end() || !params->second.isObject()) continue;
        graph::forEachFileIn(params->second, f);
    }
}

QString rebased(const std::string& path, const QString& fromDir, const QString& toDir) {
    const QString p = QString::fromStdString(path);
    if (QFileInfo(p).isAbsolute() || fromDir.isEmpty()) return p;
    const QString absolute = QDir::cleanPath(QDir(fromDir).filePath(p));
    return QString::fromStdString(relativeTo(toDir, absolute));
}

} // namespace

void rebaseGraphFiles(Value& graph, const QString& fromDir, const QString& toDir) {
    if (QDir(fromDir) == QDir(toDir)) return;
    forEachFileParam(
        graph, [&](Value& v) { v = Value(rebased(v.toString(), fromDir, toDir).toStdString()); });
}

Project rebaseProject(const Project& project, const QString& newBaseDir) {
    Project out = project;
    out.baseDir = newBaseDir;
    if (!project.baseDir.isEmpty() && QDir(project.baseDir) == QDir(newBaseDir)) return out;
    const QString from = project.baseDir;
    auto move = [&](std::string& path) {
        if (!path.empty()) path = rebased(path, from, newBaseDir).toStdString();
    };
    for (ProjectSpecies& s : out.species) {
        move(s.file);
        if (s.graph) rebaseGraphFiles(*s.graph, from, newBaseDir);
    }
    for (ProjectObstacle& o : out.obstacles)
        move(o.file);
    for (PlacementDomain& d : out.domains)
        move(d.terrain);
    return out;
}

bool isProjectFile(const QString& path) {
    if (path.endsWith(QStringLiteral(".sylva"), Qt::CaseInsensitive)) return true;
    if (!path.endsWith(QStringLiteral(".json"), Qt::CaseInsensitive)) return false;
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly)) return false;
    const QByteArray head = file.read(1 << 16);
    return head.contains("\"sylva-project\"") ||
           (!head.contains("\"format\"") && head.contains("\"plants\""));
}

void addSpeciesSourceFiles(const graph::SpeciesGraph& graph, QStringList& out) {
    for (const graph::NodeDesc& node : graph.nodes) {
        Value params = node.params; // forEachFileIn() walks a mutable value
        graph::forEachFileIn(params, [&](const Value& value) {
            std::filesystem::path p(value.toString());
            if (p.is_relative() && !graph.baseDir.empty()) p = graph.baseDir / p;
            const QString file = QFileInfo(QString::fromStdString(p.string())).absoluteFilePath();
            if (!out.contains(file)) out << file;
        });
    }
}

QStringList projectSourceFiles(const Project& project) {
    QStringList out;
    auto add = [&out](const QString& path) {
        const QString absolute = QFileInfo(path).absoluteFilePath();
        if (!out.contains(absolute)) out << absolute;
    };
    for (const ProjectSpecies& s : project.species) {
        Value graph;
        QString graphDir = project.baseDir;
        if (s.graph) {
            graph = *s.graph;
        } else {
            const QString file = project.resolve(s.file);
            add(file);
            try {
                const graph::SpeciesGraph g = loadSpecies(file);
                graphDir = QString::fromStdString(g.baseDir.string());
                Value::Array nodes;
                for (const graph::NodeDesc& n : g.nodes)
                    nodes.push_back(Value::Object{{"id", n.id}, {"params", n.params}});
                graph = Value::Object{{"nodes", Value(std::move(nodes))}};
            } catch (const std::exception&) {
                continue; // the species itself is watched; its error shows on generation
            }
        }
        forEachFileParam(graph, [&](Value& v) {
            const QString p = QString::fromStdString(v.toString());
            add(QFileInfo(p).isAbsolute() ? p : QDir(graphDir).filePath(p));
        });
    }
    for (const ProjectObstacle& o : project.obstacles)
        add(project.resolve(o.file));
    for (const PlacementDomain& d : project.domains)
        if (!d.terrain.empty()) add(project.resolve(d.terrain));
    return out;
}

} // namespace sylva::doc
