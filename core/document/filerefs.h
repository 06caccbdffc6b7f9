#pragma once

#include <string>

#include <QString>
#include <QStringList>

#include "document/project.h"
#include "engine/graph/fileparams.h"
#include "engine/graph/graph.h"
#include "engine/util/value.h"

namespace sylva::doc {

/// \p absolute written relative to \p baseDir (as project files store paths); absolute when
/// \p baseDir is empty.
std::string relativeTo(const QString& baseDir, const QString& absolute);

/// Rewrites the relative file parameters of an inline graph ({"nodes": [...]}) read against
/// \p fromDir so that they resolve the same against \p toDir.
void rebaseGraphFiles(sylva::Value& graph, const QString& fromDir, const QString& toDir);

/// The project with every relative path (species files, inline graphs' file parameters,
/// obstacle meshes, terrains) rewritten for \p newBaseDir, and baseDir set to it. Unchanged when
/// the folder is the same, so a save in place writes back the same text.
Project rebaseProject(const Project& project, const QString& newBaseDir);

/// Whether \p path names a project (`.sylva`, or a JSON file that is a project or the reference
/// implementation's scene description) rather than a species or grammar.
bool isProjectFile(const QString& path);

/// Appends to \p out the files that \p graph's nodes read (graph::isFileParam parameters, nested
/// ones too), resolved against the graph's folder: absolute, no duplicates.
void addSpeciesSourceFiles(const graph::SpeciesGraph& graph, QStringList& out);

/// The files a project reads, absolute: species files, their graphs' file parameters (grammar
/// files, ...), obstacle meshes and terrains. Files that cannot be read are still listed (a
/// file that appears later is worth watching); a species file that does not parse contributes
/// only itself.
QStringList projectSourceFiles(const Project& project);

} // namespace sylva::doc
