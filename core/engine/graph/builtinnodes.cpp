// Registers the engine's node types. Each module provides a register function; this file is
// the one place that knows them all, so adding a node type is one line here.
#include "engine/graph/graph.h"

#include "engine/lsystem/derivation.h"
#include "engine/lsystem/grammar.h"
#include "engine/lsystem/turtle.h"
#include "engine/util/error.h"

#include <chrono>
#include <fstream>
#include <mutex>
#include <sstream>

// --- node registrations of other modules (one include and one call each) ---
#include "engine/environment/adaptnode.h"
#include "engine/growth/selforganizingnode.h"
#include "engine/growth/spacecolonizationnode.h"
#include "engine/mesh/meshnodes.h"
// --- end of node registrations' includes ---

namespace sylva::graph {

namespace {

double msSince(std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
        .count();
}

std::string readTextFile(const std::filesystem::path& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in) throw IoError("cannot read " + path.string());
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
}

/// `lsystem`: grammar text (inline `grammar` or `grammar_file`) → derived word → turtle skeleton.
NodeOutput evaluateLsystem(const NodeContext& ctx) {
    const Value& p = ctx.params;
    std::string text;
    std::string fileName;
    if (const Value* inline_ = p.find("grammar"); inline_ && !inline_->isNull()) {
        text = inline_->toString("grammar");
        fileName = ctx.sourceFile.empty() ? std::string("<grammar>") : ctx.sourceFile;
    } else if (const Value* file = p.find("grammar_file"); file && !file->isNull()) {
        const std::filesystem::path path = ctx.resolve(file->toString("grammar_file"));
        text = readTextFile(path);
        fileName = path.string();
    } else {
        ctx.fail("needs a 'grammar' (inline text) or a 'grammar_file' parameter");
    }

    NodeOutput out;
    auto t0 = std::chrono::steady_clock::now();
    const lsys::Grammar grammar = lsys::parseGrammar(text, fileName);

    lsys::DeriveOptions options;
    if (p.contains("generations")) {
        const std::int64_t n = p.integer("generations", 0);
        requireRange("generations", static_cast<double>(n), 0, 1000);
        options.generations = static_cast<int>(n);
    }
    if (ctx.seedOverridden)
        options.seed = ctx.seed;
    else if (p.contains("seed"))
        options.seed = static_cast<std::uint64_t>(p.integer("seed", 0));
    if (p.contains("symbol_limit")) {
        const double limit = p.number("symbol_limit", 20e6);
        requireRange("symbol_limit", limit, 1, 2e9);
        options.symbolLimit = static_cast<std::size_t>(limit);
    }
    if (p.contains("time_limit")) {
        options.timeLimitSeconds = p.number("time_limit", lsys::kDefaultDeriveTimeLimit);
        requireRange("time_limit (s)", options.timeLimitSeconds, 1e-3, lsys::kMaxDeriveTimeLimit);
    }
    const lsys::ModuleString word = lsys::derive(grammar, options, ctx.progress);
    out.timingsMs["expand"] = msSince(t0);

    lsys::TurtleSettings turtle;
    turtle.angleDegrees = p.number("angle", grammar.angleDegrees);
    turtle.step = p.number("step", grammar.step);
    turtle.width = p.number("width", grammar.width);
    turtle.widthFactor = p.number("width_factor", grammar.widthFactor);
    requireRange("angle", turtle.angleDegrees, -360, 360);
    requireRange("step", turtle.step, 0, 1e4);
    requireRange("width", turtle.width, 0, 1e3);
    requireRange("width_factor", turtle.widthFactor, 0, 10);
    if (p.contains("leaf_size")) {
        turtle.leafSize = p.number("leaf_size", turtle.leafSize);
        requireRange("leaf_size", turtle.leafSize, 0, 100);
    }

    t0 = std::chrono::steady_clock::now();
    auto skeleton = std::make_shared<skel::Skeleton>(lsys::interpret(word, turtle, ctx.progress));
    skeleton->finalize();
    out.timingsMs["interpret"] = msSince(t0);

    glm::vec3 lo, hi;
    skeleton->bounds(lo, hi);
    out.stats["symbols"] = static_cast<double>(word.size());
    out.stats["segments"] = static_cast<double>(skeleton->segmentCount());
    out.stats["leaves"] = static_cast<double>(skeleton->leaves.size());
    out.stats["height"] = static_cast<double>(hi.y);
    out.skeleton = std::move(skeleton);
    return out;
}

} // namespace

void registerBuiltinNodeTypes() {
    static std::once_flag once;
    std::call_once(once, [] {
        NodeRegistry& registry = NodeRegistry::instance();
        registry.add(
            NodeType{"lsystem",
                     0,
                     0,
                     evaluateLsystem,
                     {"grammar", "grammar_file", "generations", "seed", "symbol_limit",
                      "time_limit", "angle", "step", "width", "width_factor", "leaf_size"}});
        // --- node registrations of other modules (one call each) ---
        mesh::registerMeshNodes(registry);
        env::registerAdaptNode(registry);
        growth::registerSelfOrganizingNode(registry);
        growth::registerSpaceColonizationNode(registry);
        // --- end of node registrations ---
    });
}

} // namespace sylva::graph
