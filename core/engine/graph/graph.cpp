#include "engine/graph/graph.h"

#include "engine/util/error.h"

#include <functional>
#include <mutex>
#include <set>

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
    const NodeDesc* out = findNode(output);
    return out && out->type == "tube_mesh" && out->inputs.size() == 1 ? out->inputs[0] : output;
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
    mTypes[name] = std::move(type);
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
    registerBuiltinNodeTypes();
    validate();
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
        if (inputs < type->minInputs || inputs > type->maxInputs)
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

void Evaluator::setGraph(SpeciesGraph graph) {
    SpeciesGraph previous = std::move(mGraph);
    mGraph = std::move(graph);
    try {
        validate();
    } catch (...) {
        mGraph = std::move(previous); // a rejected edit loses nothing
        throw;
    }
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
    mix(node.params.hash());
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
            NodeContext ctx{node,           node.params,       {},       seed, seedOverridden,
                            mGraph.baseDir, mGraph.sourceFile, progress, mTree};
            for (const std::string& in : node.inputs)
                ctx.inputs.push_back(mCache[in].output.get());
            const NodeType* type = NodeRegistry::instance().find(node.type);
            auto output = std::make_shared<NodeOutput>(type->evaluate(ctx));
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
