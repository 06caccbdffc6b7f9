#pragma once

#include <optional>
#include <string>

#include <QString>

#include "engine/graph/graph.h"

namespace sylva::doc {

/// Current version of the species file format ("format": "sylva-species").
inline constexpr int kSpeciesFormatVersion = 1;

/// Loads a species file (JSON) into a graph whose baseDir is the file's folder. Also accepts a
/// bare grammar file (.lsys or the legacy format), wrapped into an lsystem -> tube_mesh graph.
/// Throws sylva::InvalidInput (with file/line/column where known) or sylva::IoError.
graph::SpeciesGraph loadSpecies(const QString& path);

/// Parses species JSON text; \p fileName and \p baseDir are used for messages and paths.
graph::SpeciesGraph parseSpecies(const QByteArray& json, const QString& fileName,
                                 const QString& baseDir);

/// The same from JSON already parsed (e.g. a graph inlined in a project file).
graph::SpeciesGraph speciesFromValue(sylva::Value root, const QString& fileName,
                                     const QString& baseDir);

/// Serialises a graph back to species JSON (stable key order).
QByteArray serializeSpecies(const graph::SpeciesGraph& graph);

/// The species file's envelope around a graph as JSON: "format", "format_version", "name",
/// "graph" and, when given, "traits". The one builder of it: species files, the document's
/// inline species, "Save species as" and projects all wrap a graph with it.
sylva::Value speciesEnvelope(const std::string& name, sylva::Value graph,
                             const std::optional<sylva::Value>& traits);

/// An inline species (a project's graph JSON and traits) as the engine reads it; relative files
/// resolve from \p baseDir. \throw InvalidInput as parseSpecies.
graph::SpeciesGraph speciesFromGraph(const std::string& name, const sylva::Value& graph,
                                     const std::optional<sylva::Value>& traits,
                                     const QString& baseDir);

/// Writes species JSON (an envelope) to \p path atomically, pretty-printed. \throw IoError.
void writeSpeciesFile(const QString& path, const sylva::Value& root);

} // namespace sylva::doc
