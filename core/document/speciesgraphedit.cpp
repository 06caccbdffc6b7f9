#include "document/speciesgraphedit.h"

#include <algorithm>

#include "document/filerefs.h"
#include "document/speciesfile.h"
#include "engine/graph/graph.h"
#include "engine/util/error.h"

namespace sylva::doc {

using sylva::Value;

namespace {

Value::Array& nodesOf(Value& graph) {
    return graph.objectRef()["nodes"].arrayRef();
}

InvalidInput noSuchNode(const std::string& species, const std::string& id) {
    return InvalidInput("species '" + species + "' has no node '" + id + "'");
}

} // namespace

const Value* findGraphNode(const Value& graph, const std::string& id) {
    const Value* nodes = graph.find("nodes");
    if (!nodes || !nodes->isArray()) return nullptr;
    for (const Value& n : nodes->toArray())
        if (n.isObject() && n.string("id", "") == id) return &n;
    return nullptr;
}

Value* findGraphNode(Value& graph, const std::string& id) {
    Value::Object& g = graph.objectRef();
    auto nodes = g.find("nodes");
    if (nodes == g.end() || !nodes->second.isArray()) return nullptr;
    for (Value& n : nodes->second.arrayRef())
        if (n.isObject() && n.string("id", "") == id) return &n;
    return nullptr;
}

Value& graphNode(Value& graph, const std::string& species, const std::string& id) {
    Value* n = findGraphNode(graph, id);
    if (!n) throw noSuchNode(species, id);
    return *n;
}

const Value::Array& graphNodes(const Value& graph) {
    static const Value::Array none;
    const Value* list = graph.find("nodes");
    return list && list->isArray() ? list->toArray() : none;
}

std::vector<std::string> nodeInputs(const Value& node) {
    std::vector<std::string> out;
    if (const Value* in = node.find("inputs"); in && in->isArray())
        for (const Value& v : in->toArray())
            out.push_back(v.toString("an input id"));
    return out;
}

void setNodeInputs(Value& node, const std::vector<std::string>& inputs) {
    Value::Array a;
    for (const std::string& s : inputs)
        a.emplace_back(s);
    if (a.empty())
        node.objectRef().erase("inputs");
    else
        node.objectRef()["inputs"] = Value(std::move(a));
}

std::optional<glm::dvec2> nodeEditorPosition(const Value& node) {
    const Value* p = node.find("editor_position");
    if (!p || !p->isArray() || p->toArray().size() != 2) return std::nullopt;
    return glm::dvec2(p->toArray()[0].toNumber(), p->toArray()[1].toNumber());
}

std::pair<std::string, std::string> splitParamPath(const std::string& path) {
    const auto dot = path.find('.');
    if (dot == std::string::npos || dot == 0 || dot + 1 == path.size())
        throw InvalidInput("a parameter is named \"node.param\", got \"" + path + "\"");
    return {path.substr(0, dot), path.substr(dot + 1)};
}

Value nodeParam(const Value& graph, const std::string& species, const std::string& node,
                const std::string& key) {
    const Value* n = findGraphNode(graph, node);
    if (!n) throw noSuchNode(species, node);
    const Value* params = n->find("params");
    const Value* v = params ? params->find(key) : nullptr;
    return v ? *v : Value();
}

void setNodeParam(Value& graph, const std::string& species, const std::string& node,
                  const std::string& key, const Value& value) {
    Value::Object& params = graphNode(graph, species, node).objectRef()["params"].objectRef();
    if (value.isNull())
        params.erase(key);
    else
        params[key] = value;
    if (key == "grammar" && !value.isNull()) params.erase("grammar_file");
}

void requireNodeType(const std::string& type) {
    graph::registerBuiltinNodeTypes();
    if (graph::NodeRegistry::instance().find(type)) return;
    std::string known;
    for (const std::string& n : graph::NodeRegistry::instance().names())
        known += (known.empty() ? "" : ", ") + n;
    throw InvalidInput("unknown node type '" + type + "' (known: " + known + ")");
}

std::string freshNodeId(const Value& graph, const std::string& type) {
    std::string id = type;
    for (int k = 2; findGraphNode(graph, id); ++k)
        id = type + std::to_string(k);
    return id;
}

void addGraphNode(Value& graph, const std::string& species, const std::string& id,
                  const std::string& type, const Value& params, glm::vec2 position) {
    if (findGraphNode(graph, id))
        throw InvalidInput("species '" + species + "' already has a node '" + id + "'");
    Value::Object node{
        {"id", id},
        {"type", type},
        {"params", params.isNull() ? Value(Value::Object{}) : params},
        {"editor_position", Value(Value::Array{double(position.x), double(position.y)})}};
    nodesOf(graph).emplace_back(std::move(node));
}

void removeGraphNode(Value& graph, const std::string& species, const std::string& id) {
    graphNode(graph, species, id);
    if (graph.string("output", "") == id)
        throw InvalidInput("'" + id +
                           "' is the species' output (the tree); make another node the output "
                           "first");
    Value::Array& nodes = nodesOf(graph);
    for (auto it = nodes.begin(); it != nodes.end();) {
        if (it->string("id", "") == id) {
            it = nodes.erase(it);
            continue;
        }
        std::vector<std::string> in = nodeInputs(*it);
        std::erase(in, id);
        setNodeInputs(*it, in);
        ++it;
    }
}

void connectGraphNodes(Value& graph, const std::string& species, const std::string& from,
                       const std::string& to, const QString& baseDir) {
    graph::registerBuiltinNodeTypes();
    Value& target = graphNode(graph, species, to);
    graphNode(graph, species, from);
    std::vector<std::string> in = nodeInputs(target);
    if (std::find(in.begin(), in.end(), from) != in.end()) return; // already
    const graph::NodeType* t = graph::NodeRegistry::instance().find(target.string("type", ""));
    // A node with one input has it replaced: drop the old edge before checking.
    if (t && t->maxInputs == 1 && in.size() == 1) in.clear();
    setNodeInputs(target, in);
    const std::string why =
        graph::connectionError(speciesFromGraph(species, graph, std::nullopt, baseDir), from, to);
    if (!why.empty()) throw InvalidInput(why);
    in.push_back(from);
    setNodeInputs(target, in);
}

void disconnectGraphNodes(Value& graph, const std::string& species, const std::string& from,
                          const std::string& to) {
    Value& target = graphNode(graph, species, to);
    std::vector<std::string> in = nodeInputs(target);
    if (std::find(in.begin(), in.end(), from) == in.end())
        throw InvalidInput("'" + from + "' is not connected to '" + to + "'");
    std::erase(in, from);
    setNodeInputs(target, in);
}

void setGraphOutput(Value& graph, const std::string& species, const std::string& id) {
    graphNode(graph, species, id);
    graph.objectRef()["output"] = Value(id);
}

void setNodeEditorPosition(Value& graph, const std::string& species, const std::string& id,
                           glm::vec2 position) {
    graphNode(graph, species, id).objectRef()["editor_position"] =
        Value(Value::Array{double(position.x), double(position.y)});
}

Value standaloneGraph(Value graph,
                      const std::function<std::string(const std::string& node)>& grammarOf) {
    for (Value& n : nodesOf(graph)) {
        Value& params = n.objectRef()["params"];
        if (const Value* file = params.find("grammar_file"); file && file->isString()) {
            const std::string text = grammarOf(n.string("id", ""));
            params.objectRef().erase("grammar_file");
            params.objectRef()["grammar"] = Value(text);
        }
        n.objectRef().erase("editor_position");
    }
    return graph;
}

ProjectSpecies inlineSpeciesFile(const std::string& name, const QString& file,
                                 const QString& projectBaseDir) {
    const graph::SpeciesGraph g = loadSpecies(file);
    // Through the file's own serialisation, so that the inline JSON holds what the file means
    // (a bare grammar file becomes its lsystem -> tube_mesh graph, defaults written out).
    const Value root = Value::parseJson(serializeSpecies(g).toStdString(), file.toStdString());
    ProjectSpecies out;
    out.name = name;
    out.graph = *root.find("graph");
    out.traits = *root.find("traits");
    rebaseGraphFiles(*out.graph, QString::fromStdString(g.baseDir.string()), projectBaseDir);
    return out;
}

} // namespace sylva::doc
