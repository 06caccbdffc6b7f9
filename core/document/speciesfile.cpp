#include "document/speciesfile.h"

#include "document/formatupgrade.h"
#include "engine/nodes/builtinnodes.h"
#include "engine/util/atomicfile.h"
#include "engine/util/error.h"

#include <QFile>
#include <QFileInfo>

namespace sylva::doc {

namespace {

using sylva::Value;

/// Species format upgrades (none yet: version 1 is the first). Add steps here, never checks in
/// the parser below.
const std::vector<UpgradeStep>& speciesUpgrades() {
    static const std::vector<UpgradeStep> steps;
    return steps;
}

graph::SpeciesGraph wrapGrammar(const QString& path) {
    const QFileInfo info(path);
    // The built-in generator and mesher: nodes/ names them.
    graph::SpeciesGraph g = nodes::grammarSpecies(info.fileName().toStdString());
    g.name = info.completeBaseName().toStdString();
    g.baseDir = info.absolutePath().toStdString();
    g.sourceFile = path.toStdString();
    return g;
}

} // namespace

graph::SpeciesGraph parseSpecies(const QByteArray& json, const QString& fileName,
                                 const QString& baseDir) {
    return speciesFromValue(Value::parseJson(json.toStdString(), fileName.toStdString()), fileName,
                            baseDir);
}

graph::SpeciesGraph speciesFromValue(sylva::Value root, const QString& fileName,
                                     const QString& baseDir) {
    const std::string file = fileName.toStdString();
    const std::string where = file.empty() ? std::string() : file + ": ";
    if (!root.isObject()) throw InvalidInput(where + "a species file must hold a JSON object");
    Value::Object& obj = root.objectRef();
    upgradeFormat(obj, "sylva-species", kSpeciesFormatVersion, speciesUpgrades(), file, true);

    graph::SpeciesGraph g;
    g.sourceFile = file;
    g.baseDir = baseDir.toStdString();
    g.name = root.string("name", QFileInfo(fileName).completeBaseName().toStdString());
    const Value* graphValue = root.find("graph");
    if (!graphValue || !graphValue->isObject())
        throw InvalidInput(where +
                           "\"graph\" (an object with \"nodes\" and \"output\") is missing");
    const Value* nodes = graphValue->find("nodes");
    if (!nodes || !nodes->isArray() || nodes->toArray().empty())
        throw InvalidInput(where + "\"graph.nodes\" must be a non-empty array");
    for (const Value& n : nodes->toArray()) {
        if (!n.isObject()) throw InvalidInput(where + "each node must be an object");
        graph::NodeDesc node;
        node.id = n.string("id", "");
        node.type = n.string("type", "");
        if (node.id.empty() || node.type.empty())
            throw InvalidInput(where + "each node needs an \"id\" and a \"type\"");
        if (const Value* params = n.find("params")) {
            if (!params->isObject())
                throw InvalidInput(where + "node '" + node.id + "': \"params\" must be an object");
            node.params = *params;
        }
        if (const Value* inputs = n.find("inputs")) {
            for (const Value& in : inputs->toArray("node '" + node.id + "' inputs"))
                node.inputs.push_back(in.toString("an input id"));
        }
        g.nodes.push_back(std::move(node));
    }
    g.output = graphValue->string("output", g.nodes.back().id);
    if (const Value* traits = root.find("traits")) {
        if (!traits->isObject()) throw InvalidInput(where + "\"traits\" must be an object");
        try {
            g.traits.woodDensity = traits->number("wood_density", g.traits.woodDensity);
            g.traits.carbonFraction = traits->number("carbon_fraction", g.traits.carbonFraction);
            g.traits.crownRadius = traits->number("crown_radius", g.traits.crownRadius);
            requireRange("traits.wood_density (kg/m3)", g.traits.woodDensity, 1, 2000);
            requireRange("traits.carbon_fraction", g.traits.carbonFraction, 0.01, 1);
            requireRange("traits.crown_radius (m)", g.traits.crownRadius, 0, 500);
        } catch (const InvalidInput& e) {
            throw InvalidInput(where + e.what());
        }
    }
    return g;
}

graph::SpeciesGraph loadSpecies(const QString& path) {
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly))
        throw IoError("cannot read " + path.toStdString() + ": " +
                      file.errorString().toStdString());
    const QByteArray bytes = file.readAll();
    const QFileInfo info(path);
    const QString suffix = info.suffix().toLower();
    if (suffix == "json" || suffix == "sylva-species" || bytes.trimmed().startsWith('{'))
        return parseSpecies(bytes, path, info.absolutePath());
    return wrapGrammar(path);
}

QByteArray serializeSpecies(const graph::SpeciesGraph& g) {
    Value::Array nodes;
    for (const graph::NodeDesc& n : g.nodes) {
        Value::Object o{{"id", n.id}, {"type", n.type}, {"params", n.params}};
        if (!n.inputs.empty()) {
            Value::Array inputs;
            for (const std::string& in : n.inputs)
                inputs.emplace_back(in);
            o["inputs"] = Value(std::move(inputs));
        }
        nodes.emplace_back(std::move(o));
    }
    const Value root =
        speciesEnvelope(g.name, Value::Object{{"nodes", std::move(nodes)}, {"output", g.output}},
                        Value(Value::Object{{"wood_density", g.traits.woodDensity},
                                            {"carbon_fraction", g.traits.carbonFraction},
                                            {"crown_radius", g.traits.crownRadius}}));
    return QByteArray::fromStdString(root.toJson() + "\n");
}

Value speciesEnvelope(const std::string& name, Value graph, const std::optional<Value>& traits) {
    Value::Object root{{"format", "sylva-species"},
                       {"format_version", kSpeciesFormatVersion},
                       {"name", name},
                       {"graph", std::move(graph)}};
    if (traits) root["traits"] = *traits;
    return Value(std::move(root));
}

graph::SpeciesGraph speciesFromGraph(const std::string& name, const Value& graph,
                                     const std::optional<Value>& traits, const QString& baseDir) {
    return speciesFromValue(speciesEnvelope(name, graph, traits), QString::fromStdString(name),
                            baseDir);
}

void writeSpeciesFile(const QString& path, const Value& root) {
    // The writer of every document (projects, autosave): atomic, and durable before the rename.
    writeFileAtomically(path.toStdString(), root.toPrettyJson() + "\n");
}

} // namespace sylva::doc
