#pragma once

#include <functional>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <QString>

#include <glm/glm.hpp>

#include "document/project.h"
#include "engine/util/value.h"

namespace sylva::doc {

// A species graph as the project keeps it and the editor edits it: JSON
// {"nodes": [{"id", "type", "params", "inputs", "editor_position"}], "output": id}. These free
// functions are the one room for reading and changing it: the Document's edits (which wrap them
// in undoable commands) and the node editor's drawing go through them; the engine's
// SpeciesGraph is made from the result by speciesFromGraph (speciesfile.h). Edits throw
// InvalidInput naming \p species and the node; they change \p graph in place, so callers edit a
// copy and keep it only when the whole edit succeeded.

/// The node with id \p id, or null.
const sylva::Value* findGraphNode(const sylva::Value& graph, const std::string& id);
sylva::Value* findGraphNode(sylva::Value& graph, const std::string& id);
/// The node with id \p id. \throw InvalidInput "species '<species>' has no node '<id>'".
sylva::Value& graphNode(sylva::Value& graph, const std::string& species, const std::string& id);
/// The graph's nodes (empty when it has none).
const sylva::Value::Array& graphNodes(const sylva::Value& graph);

/// The ids a node takes its inputs from, in order. \throw InvalidInput for an id that is not a
/// string.
std::vector<std::string> nodeInputs(const sylva::Value& node);
/// Replaces a node's inputs ("inputs" is left out when there are none).
void setNodeInputs(sylva::Value& node, const std::vector<std::string>& inputs);
/// Where the node editor draws a node; nullopt when it has no position yet.
std::optional<glm::dvec2> nodeEditorPosition(const sylva::Value& node);

/// "node.param" split at its dot. \throw InvalidInput for another shape.
std::pair<std::string, std::string> splitParamPath(const std::string& path);
/// A node's parameter (null when unset). \throw InvalidInput for an unknown node.
sylva::Value nodeParam(const sylva::Value& graph, const std::string& species,
                       const std::string& node, const std::string& key);
/// Sets a node's parameter; a null \p value removes it. A grammar text replaces a grammar_file.
void setNodeParam(sylva::Value& graph, const std::string& species, const std::string& node,
                  const std::string& key, const sylva::Value& value);

/// \throw InvalidInput listing the known types when \p type is not a registered node type.
void requireNodeType(const std::string& type);
/// An id for a new node of \p type that the graph does not use yet: the type, then type2, ...
std::string freshNodeId(const sylva::Value& graph, const std::string& type);
/// Appends a node without inputs. \throw InvalidInput when \p id is taken.
void addGraphNode(sylva::Value& graph, const std::string& species, const std::string& id,
                  const std::string& type, const sylva::Value& params, glm::vec2 position);
/// Removes a node and the edges from it. \throw InvalidInput for the output node.
void removeGraphNode(sylva::Value& graph, const std::string& species, const std::string& id);
/// Feeds \p from into \p to (a node that takes one input has it replaced; an existing edge is
/// kept as it is). \throw InvalidInput with graph::connectionError's reason, checked on the
/// graph as the engine reads it from \p baseDir.
void connectGraphNodes(sylva::Value& graph, const std::string& species, const std::string& from,
                       const std::string& to, const QString& baseDir);
/// Removes the edge \p from → \p to. \throw InvalidInput when there is none.
void disconnectGraphNodes(sylva::Value& graph, const std::string& species, const std::string& from,
                          const std::string& to);
/// Makes \p id the output node.
void setGraphOutput(sylva::Value& graph, const std::string& species, const std::string& id);
/// Sets where the node editor draws a node.
void setNodeEditorPosition(sylva::Value& graph, const std::string& species, const std::string& id,
                           glm::vec2 position);

/// The graph as a self-contained species file holds it: each grammar_file replaced by its text
/// (\p grammarOf, given a node id) and the editor positions left out.
sylva::Value standaloneGraph(sylva::Value graph,
                             const std::function<std::string(const std::string& node)>& grammarOf);

/// A species file read into an inline project species named \p name: its graph and traits as
/// JSON, relative files rebased from the file's folder to \p projectBaseDir.
/// \throw InvalidInput / IoError as loadSpecies.
ProjectSpecies inlineSpeciesFile(const std::string& name, const QString& file,
                                 const QString& projectBaseDir);

} // namespace sylva::doc
