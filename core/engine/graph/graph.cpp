#include "engine/graph/graph.h"

#include "engine/util/error.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <functional>
#include <mutex>
#include <set>
#include <sstream>
#include <utility>

namespace sylva::graph {

const NodeDesc* SpeciesGraph::findNode(const std::string& id) const {
    for (const NodeDesc& n : nodes)
        if (n.id == id) return &n;
    return nullptr;
}

NodeDesc* SpeciesGraph::findNode(const std::string& id) {
    for (NodeDesc& n : nodes)
        if (n.id == id) return &n;
    return nullptr;
}

const std::string& SpeciesGraph::skeletonSource() const {
    const NodeDesc* out = meshOutput(*this);
    return out ? out->inputs[0] : output;
}

const NodeType* findType(const std::string& type) {
    registerBuiltinNodeTypes();
    return NodeRegistry::instance().find(type);
}

NodeRole roleOf(const std::string& type) {
    const NodeType* t = findType(type);
    return t ? t->role : NodeRole::Other;
}

const StandGrowth* standGrowthOf(const std::string& type) {
    const NodeType* t = findType(type);
    return t ? t->stand.get() : nullptr;
}

const NodeDesc* meshOutput(const SpeciesGraph& graph) {
    const NodeDesc* out = graph.findNode(graph.output);
    return out && out->inputs.size() == 1 && roleOf(out->type) == NodeRole::Mesher ? out : nullptr;
}

std::filesystem::path NodeContext::resolve(const std::string& relative) const {
    std::filesystem::path p(relative);
    if (p.is_absolute() || baseDir.empty()) return p;
    return baseDir / p;
}

void NodeContext::fail(const std::string& message) const {
    std::string prefix = sourceFile.empty() ? std::string() : sourceFile + ": ";
    throw InvalidInput(prefix + "node '" + node.id + "' (" + node.type + "): " + message);
}

NodeRegistry& NodeRegistry::instance() {
    static NodeRegistry registry;
    return registry;
}

void NodeRegistry::add(NodeType type) {
    std::string name = type.name;
    if (type.knownParams.empty())
        for (const ParamSpec& p : type.params)
            type.knownParams.push_back(p.name);
    mTypes[name] = std::move(type);
}

const ParamSpec* NodeType::findParam(const std::string& key) const {
    for (const ParamSpec& p : params)
        if (p.name == key) return &p;
    return nullptr;
}

const char* portKindName(PortKind kind) {
    return kind == PortKind::Mesh ? "mesh" : "skeleton";
}

namespace {

std::string number(double v) {
    // Whole numbers in full ("2000000", not "2e+06"): ranges are read by people.
    if (std::abs(v) < 1e16 && v == std::trunc(v)) // the bound first: no out-of-range cast
        return std::to_string(static_cast<long long>(v));
    std::ostringstream s;
    s << v;
    return s.str();
}

} // namespace

std::string ParamSpec::rangeText() const {
    std::string text;
    if (kind == ParamKind::Number || kind == ParamKind::Integer || kind == ParamKind::Vector) {
        if (min <= -1e300 && max >= 1e300) return unit;
        text = std::string(minOpen ? "(" : "[") + (min <= -1e300 ? "-inf" : number(min)) + ", " +
               (max >= 1e300 ? "inf" : number(max)) + "]";
    } else if (kind == ParamKind::Enum) {
        for (const std::string& c : choices)
            text += (text.empty() ? "" : " | ") + c;
    }
    if (!unit.empty()) text += (text.empty() ? "" : " ") + unit;
    return text;
}

std::string paramWords(std::string_view name) {
    static constexpr std::pair<std::string_view, std::string_view> kAcronyms[] = {
        {"lod", "LOD"}, {"fov", "FOV"}, {"id", "ID"}, {"ids", "IDs"}, {"uv", "UV"}, {"co2", "CO2"}};
    std::string words;
    std::size_t at = 0;
    while (at <= name.size()) {
        const std::size_t end = std::min(name.find('_', at), name.size());
        std::string_view word = name.substr(at, end - at);
        for (const auto& [lower, upper] : kAcronyms)
            if (word == lower) word = upper;
        if (!word.empty()) words += (words.empty() ? "" : " ") + std::string(word);
        at = end + 1;
    }
    return words;
}

std::string ParamSpec::label() const {
    std::string text = paramWords(name);
    if (!text.empty() && text[0] >= 'a' && text[0] <= 'z')
        text[0] = static_cast<char>(text[0] - 'a' + 'A');
    return text;
}

void checkParam(const ParamSpec& spec, const Value& value) {
    if (value.isNull()) return; // unset: the node's default
    auto inRange = [&](double v, const std::string& what) {
        const bool below = spec.minOpen ? !(v > spec.min) : !(v >= spec.min);
        if (below || !(v <= spec.max))
            throw InvalidInput(what + " must be in " + spec.rangeText() + ", got " + number(v));
    };
    switch (spec.kind) {
    case ParamKind::Number:
        inRange(value.toNumber(spec.name), spec.name);
        break;
    case ParamKind::Integer: {
        const double v = value.toNumber(spec.name);
        // The range first: a huge value is out of range, and converting it to an integer type
        // to test wholeness would be undefined (fuzz finding 13).
        inRange(v, spec.name);
        if (v != std::trunc(v))
            throw InvalidInput(spec.name + " must be a whole number, got " + number(v));
        break;
    }
    case ParamKind::Bool:
        if (!value.isBool())
            throw InvalidInput(spec.name + " must be true or false, got " + value.toJson());
        break;
    case ParamKind::Enum: {
        const std::string v = value.toString(spec.name);
        bool ok = false;
        for (const std::string& c : spec.choices)
            ok = ok || c == v;
        if (!ok)
            throw InvalidInput(spec.name + " must be one of " + spec.rangeText() + ", got \"" + v +
                               "\"");
        break;
    }
    case ParamKind::Vector: {
        if (value.isNumber()) {
            inRange(value.toNumber(), spec.name);
            break;
        }
        const Value::Array& a = value.toArray(spec.name);
        if (a.size() != 3)
            throw InvalidInput(spec.name + " must be [x, y, z], got " + value.toJson());
        for (const Value& c : a)
            inRange(c.toNumber(spec.name), spec.name + " component");
        break;
    }
    case ParamKind::File:
    case ParamKind::Text:
        value.toString(spec.name);
        break;
    case ParamKind::Curve:
        if (!value.isString()) value.toArray(spec.name);
        break;
    case ParamKind::Object:
        break; // read and checked by the node itself
    }
}

PortKind outputKind(const SpeciesGraph& graph, const std::string& id) {
    std::set<std::string> seen;
    std::string at = id;
    while (true) {
        const NodeDesc* n = graph.findNode(at);
        if (!n) throw InvalidInput("unknown node '" + at + "'");
        const NodeType* t = NodeRegistry::instance().find(n->type);
        if (!t) throw InvalidInput("node '" + at + "' has unknown type '" + n->type + "'");
        if (!t->outputFollowsInput || n->inputs.empty() || !seen.insert(at).second)
            return t->output;
        at = n->inputs.front();
    }
}

std::string connectionError(const SpeciesGraph& graph, const std::string& from,
                            const std::string& to) {
    const NodeDesc* a = graph.findNode(from);
    const NodeDesc* b = graph.findNode(to);
    if (!a) return "there is no node '" + from + "'";
    if (!b) return "there is no node '" + to + "'";
    const NodeType* tb = NodeRegistry::instance().find(b->type);
    if (!tb) return "node '" + to + "' has unknown type '" + b->type + "'";
    if (tb->maxInputs == 0) return "'" + to + "' (" + b->type + ") takes no input: it grows a tree";
    if (static_cast<int>(b->inputs.size()) >= tb->maxInputs)
        return "'" + to + "' (" + b->type + ") already has its " +
               (tb->maxInputs == 1 ? std::string("input")
                                   : std::to_string(tb->maxInputs) + " inputs") +
               "; disconnect it first";
    PortKind kind;
    try {
        kind = outputKind(graph, from);
    } catch (const InvalidInput& e) {
        return e.what();
    }
    bool accepted = false;
    for (PortKind k : tb->accepts)
        accepted = accepted || k == kind;
    if (!accepted) {
        std::string list;
        for (PortKind k : tb->accepts)
            list += (list.empty() ? "" : " or ") + std::string(portKindName(k));
        return "'" + to + "' (" + b->type + ") takes a " + list + ", but '" + from + "' (" +
               a->type + ") gives a " + portKindName(kind);
    }
    // A cycle: `to` already feeds `from`, directly or through other nodes.
    std::set<std::string> seen;
    std::vector<std::string> stack{from};
    while (!stack.empty()) {
        const std::string id = stack.back();
        stack.pop_back();
        if (id == to) return "connecting '" + from + "' to '" + to + "' would make a cycle";
        if (!seen.insert(id).second) continue;
        if (const NodeDesc* n = graph.findNode(id))
            for (const std::string& in : n->inputs)
                stack.push_back(in);
    }
    return {};
}

const NodeType* NodeRegistry::find(const std::string& name) const {
    auto it = mTypes.find(name);
    return it == mTypes.end() ? nullptr : &it->second;
}

std::vector<std::string> NodeRegistry::names() const {
    std::vector<std::string> out;
    for (const auto& [name, type] : mTypes)
        out.push_back(name);
    return out;
}

Evaluator::Evaluator(SpeciesGraph graph) : mGraph(std::move(graph)) {
    registerBuiltinNodeTypes(); // engine/nodes: the built-in types (a link-time plug-in)
    validate();
    graphChanged();
}

void Evaluator::graphChanged() {
    mParamHashes.clear();
    for (const NodeDesc& n : mGraph.nodes)
        mParamHashes.push_back(n.params.hash());
    mShared.reset();
}

std::shared_ptr<const SpeciesGraph> Evaluator::sharedGraph() const {
    if (!mShared) mShared = std::make_shared<const SpeciesGraph>(mGraph);
    return mShared;
}

void Evaluator::validate() const {
    const std::string where = mGraph.sourceFile.empty() ? std::string() : mGraph.sourceFile + ": ";
    std::set<std::string> ids;
    const NodeRegistry& registry = NodeRegistry::instance();
    for (const NodeDesc& n : mGraph.nodes) {
        if (n.id.empty()) throw InvalidInput(where + "a node has no id");
        if (!ids.insert(n.id).second)
            throw InvalidInput(where + "duplicate node id '" + n.id + "'");
        const NodeType* type = registry.find(n.type);
        if (!type) {
            std::string known;
            for (const std::string& name : registry.names())
                known += (known.empty() ? "" : ", ") + name;
            throw InvalidInput(where + "node '" + n.id + "' has unknown type '" + n.type +
                               "' (known: " + known + ")");
        }
        const int inputs = static_cast<int>(n.inputs.size());
        if (inputs > type->maxInputs)
            throw InvalidInput(where + "node '" + n.id + "' (" + n.type + ") takes " +
                               std::to_string(type->minInputs) + ".." +
                               std::to_string(type->maxInputs) + " inputs, got " +
                               std::to_string(inputs));
        if (!n.params.isObject())
            throw InvalidInput(where + "node '" + n.id + "': params must be an object");
        if (!type->knownParams.empty()) {
            for (const auto& [key, value] : n.params.toObject()) {
                bool known = false;
                for (const std::string& k : type->knownParams)
                    known = known || k == key;
                if (!known) {
                    std::string list;
                    for (const std::string& k : type->knownParams)
                        list += (list.empty() ? "" : ", ") + k;
                    throw InvalidInput(where + "node '" + n.id + "' (" + n.type +
                                       ") has no parameter '" + key + "' (known: " + list + ")");
                }
                if (const ParamSpec* spec = type->findParam(key)) {
                    try {
                        checkParam(*spec, value);
                    } catch (const InvalidInput& e) {
                        throw InvalidInput(where + "node '" + n.id + "' (" + n.type +
                                           "): " + e.what());
                    }
                }
            }
        }
    }
    for (const NodeDesc& n : mGraph.nodes)
        for (const std::string& in : n.inputs)
            if (!ids.count(in))
                throw InvalidInput(where + "node '" + n.id + "' takes input from unknown node '" +
                                   in + "'");
    if (!ids.count(mGraph.output))
        throw InvalidInput(where + "output node '" + mGraph.output + "' does not exist");
    // Nodes the output does not depend on are never evaluated: a node being wired up in the
    // editor may still lack its input. Those the tree needs must have all of theirs.
    {
        std::set<std::string> needed;
        std::vector<std::string> stack{mGraph.output};
        while (!stack.empty()) {
            const std::string id = stack.back();
            stack.pop_back();
            if (!needed.insert(id).second) continue;
            for (const std::string& in : mGraph.findNode(id)->inputs)
                stack.push_back(in);
        }
        for (const NodeDesc& n : mGraph.nodes) {
            const NodeType* type = registry.find(n.type);
            if (needed.count(n.id) && static_cast<int>(n.inputs.size()) < type->minInputs)
                throw InvalidInput(where + "node '" + n.id + "' (" + n.type + ") takes " +
                                   std::to_string(type->minInputs) + ".." +
                                   std::to_string(type->maxInputs) + " inputs, got " +
                                   std::to_string(n.inputs.size()) +
                                   "; the tree needs it, so connect its input");
        }
    }
    for (const NodeDesc& n : mGraph.nodes) {
        const NodeType* type = registry.find(n.type);
        for (const std::string& in : n.inputs) {
            const NodeDesc* from = mGraph.findNode(in);
            const NodeType* fromType = registry.find(from->type);
            // Pass-through inputs are checked where they start (cycles are found below).
            if (fromType->outputFollowsInput) continue;
            bool accepted = false;
            for (PortKind k : type->accepts)
                accepted = accepted || k == fromType->output;
            if (!accepted)
                throw InvalidInput(where + "node '" + n.id + "' (" + n.type + ") takes a " +
                                   portKindName(type->accepts.front()) + " input, but '" + in +
                                   "' (" + from->type + ") gives a " +
                                   portKindName(fromType->output));
        }
    }

    // Cycle check: depth-first with colours.
    std::map<std::string, int> colour;
    std::function<void(const std::string&)> visit = [&](const std::string& id) {
        int& c = colour[id];
        if (c == 2) return;
        if (c == 1) throw InvalidInput(where + "the graph has a cycle through node '" + id + "'");
        c = 1;
        for (const std::string& in : mGraph.findNode(id)->inputs)
            visit(in);
        colour[id] = 2;
    };
    for (const NodeDesc& n : mGraph.nodes)
        visit(n.id);
}

void Evaluator::setParam(const std::string& nodeId, const std::string& key, Value value) {
    NodeDesc* node = mGraph.findNode(nodeId);
    if (!node) {
        std::string list;
        for (const NodeDesc& n : mGraph.nodes)
            list += (list.empty() ? "" : ", ") + n.id;
        throw InvalidInput("no node '" + nodeId + "' in species '" + mGraph.name +
                           "' (nodes: " + list + ")");
    }
    SpeciesGraph copy = mGraph;
    copy.findNode(nodeId)->params.objectRef()[key] = std::move(value);
    setGraph(std::move(copy));
}

void Evaluator::setTraceSources(bool on) {
    if (on == mTraceSources) return;
    mTraceSources = on;
    mCache.clear();
}

void Evaluator::setGraph(SpeciesGraph graph) {
    SpeciesGraph previous = std::move(mGraph);
    mGraph = std::move(graph);
    try {
        validate();
    } catch (...) {
        mGraph = std::move(previous); // a rejected edit loses nothing
        throw;
    }
    graphChanged();
}

std::uint64_t Evaluator::nodeKey(const NodeDesc& node, std::uint64_t seed, bool seedOverridden,
                                 const std::vector<std::uint64_t>& inputKeys) const {
    std::uint64_t h = 1469598103934665603ull;
    auto mix = [&h](std::uint64_t v) {
        for (int i = 0; i < 8; ++i) {
            h ^= (v >> (8 * i)) & 0xFF;
            h *= 1099511628211ull;
        }
    };
    for (unsigned char c : node.type)
        mix(c);
    // The node's parameters' hash, computed when the graph was set (node is one of mGraph's).
    mix(mParamHashes[static_cast<std::size_t>(&node - mGraph.nodes.data())]);
    mix(seedOverridden ? seed : 0xFFFFFFFFFFFFFFFFull);
    for (unsigned char c : mGraph.baseDir.string())
        mix(c);
    for (std::uint64_t k : inputKeys)
        mix(k);
    mix(mTree ? mTree->key : 0);
    return h;
}

const NodeOutput& Evaluator::evaluate(Progress& progress) {
    return evaluateNode(mGraph.output, false, 0, progress);
}

const NodeOutput& Evaluator::evaluate(std::uint64_t seed, Progress& progress) {
    return evaluateNode(mGraph.output, true, seed, progress);
}

const NodeOutput& Evaluator::evaluateTree(std::uint64_t seed, const TreeContext& tree,
                                          Progress& progress, const std::string& nodeId) {
    struct Reset {
        const TreeContext*& ref;
        ~Reset() { ref = nullptr; }
    } reset{mTree};
    mTree = &tree;
    return evaluateNode(nodeId.empty() ? mGraph.output : nodeId, true, seed, progress);
}

const NodeOutput& Evaluator::evaluateNode(const std::string& nodeId, bool seedOverridden,
                                          std::uint64_t seed, Progress& progress) {
    // Post-order evaluation; the cache key chains through the inputs, so an edit upstream
    // invalidates exactly the nodes downstream of it.
    std::map<std::string, std::uint64_t> keys;
    for (auto& [id, r] : mRuns) {
        r.ran = false;
        r.error.clear();
    }
    std::function<std::uint64_t(const std::string&)> run =
        [&](const std::string& id) -> std::uint64_t {
        if (auto it = keys.find(id); it != keys.end()) return it->second;
        const NodeDesc& node = *mGraph.findNode(id);
        std::vector<std::uint64_t> inputKeys;
        for (const std::string& in : node.inputs)
            inputKeys.push_back(run(in));
        const std::uint64_t key = nodeKey(node, seed, seedOverridden, inputKeys);
        CacheEntry& entry = mCache[id];
        if (!entry.output || entry.key != key) {
            progress.checkCancelled();
            NodeContext ctx{node,           node.params,       {},       seed,  seedOverridden,
                            mGraph.baseDir, mGraph.sourceFile, progress, mTree, mTraceSources};
            for (const std::string& in : node.inputs)
                ctx.inputs.push_back(mCache[in].output.get());
            const NodeType* type = NodeRegistry::instance().find(node.type);
            NodeRun& record = mRuns[id];
            const auto start = std::chrono::steady_clock::now();
            std::shared_ptr<NodeOutput> output;
            try {
                output = std::make_shared<NodeOutput>(type->evaluate(ctx));
            } catch (const std::exception& e) {
                record.error = e.what();
                entry = {};
                throw;
            }
            record.ms =
                std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
                    .count();
            record.ran = true;
            ++record.evaluations;
            // Accumulate the inputs' stats and timings that the node did not set itself, so the
            // output node reports the whole pipeline.
            for (const NodeOutput* in : ctx.inputs) {
                for (const auto& [k, v] : in->stats)
                    output->stats.try_emplace(k, v);
                for (const auto& [k, v] : in->timingsMs)
                    output->timingsMs.try_emplace(k, v);
            }
            entry.key = key;
            entry.output = std::move(output);
            ++mEvaluations;
        }
        keys[id] = key;
        return key;
    };
    run(nodeId);
    return *mCache[nodeId].output;
}

} // namespace sylva::graph
