// The `lsystem` node: grammar text → derived word → turtle skeleton.
#include "engine/nodes/lsystemnode.h"

#include <chrono>

#include "engine/lsystem/derivation.h"
#include "engine/lsystem/grammar.h"
#include "engine/lsystem/grammarcache.h"
#include "engine/lsystem/turtle.h"
#include "engine/nodes/paramspecs.h"
#include "engine/skeleton/radii.h"
#include "engine/util/error.h"

namespace sylva::nodes {

namespace {

double msSince(std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
        .count();
}

/// Every parameter, in panel order: the one statement of its default and range, which the
/// reading goes through (ParamReader).
const std::vector<ParamSpec>& lsystemParams() {
    static const std::vector<ParamSpec> table = [] {
        std::vector<ParamSpec> specs;
        group(
            specs, "Grammar",
            {other(
                 "grammar", ParamKind::Text,
                 "The L-system: header, axiom and rules (docs/grammar.md); replaces grammar_file"),
             other("grammar_file", ParamKind::File,
                   "A grammar file, relative to the species file (used when grammar is unset)"),
             integer("generations", nullptr, 0, 1000,
                     "n: rewriting steps; unset: the grammar's `generations:`"),
             integer("seed", nullptr, 0, kMaxSeed,
                     "Seed of stochastic rules and rand(); unset: the grammar's `seed:`"),
             number("symbol_limit", 20e6, 1, 2e9, "",
                    "Derivation stops with an error past this many modules (runaway guard)"),
             number("time_limit", lsys::kDefaultDeriveTimeLimit, 1e-3, lsys::kMaxDeriveTimeLimit,
                    "s",
                    "Derivation stops with an error after this many seconds (runaway guard)")});
        group(
            specs, "Turtle",
            {number("angle", nullptr, -360, 360, "°",
                    "δ: turn of + - & ^ \\ / without a parameter; unset: the grammar's `angle:`"),
             number("step", nullptr, 0, 1e4, "m",
                    "Length of F and f without a parameter; unset: the grammar's `step:`"),
             number("width", nullptr, 0, 1e3, "m", "Initial branch diameter; unset: the grammar's"),
             number("width_factor", nullptr, 0, 10, "",
                    "What ! without a parameter multiplies the width by"),
             number("leaf_size", nullptr, 0, 100, "m", "Length of the leaves J places")});
        group(specs, "Thickness", {taperParam(), junctionSlopeParam()});
        return specs;
    }();
    return table;
}

/// `lsystem`: grammar text (inline `grammar` or `grammar_file`) → derived word → turtle skeleton.
graph::NodeOutput evaluateLsystem(const graph::NodeContext& ctx) {
    const Value& p = ctx.params;
    graph::NodeOutput out;
    auto t0 = std::chrono::steady_clock::now();
    // Parsed once a version of the file (or once a text), not at every growth.
    std::shared_ptr<const lsys::Grammar> parsed;
    if (const Value* inline_ = p.find("grammar"); inline_ && !inline_->isNull()) {
        parsed = lsys::parsedGrammarText(inline_->toString("grammar"),
                                         ctx.sourceFile.empty() ? std::string("<grammar>")
                                                                : ctx.sourceFile);
    } else if (const Value* file = p.find("grammar_file"); file && !file->isNull()) {
        parsed = lsys::parsedGrammarFile(ctx.resolve(file->toString("grammar_file")));
    } else {
        ctx.fail("needs a 'grammar' (inline text) or a 'grammar_file' parameter");
    }
    const lsys::Grammar& grammar = *parsed;

    const nodes::ParamReader read(lsystemParams(), p);
    lsys::DeriveOptions options;
    // Unset generations and seed are the grammar's own (`generations:`, `seed:`).
    if (p.contains("generations"))
        options.generations = static_cast<int>(read.integerOr("generations", 0));
    if (ctx.seedOverridden)
        options.seed = ctx.seed;
    else if (p.contains("seed"))
        options.seed = static_cast<std::uint64_t>(read.integerOr("seed", 0));
    options.symbolLimit = static_cast<std::size_t>(read.number("symbol_limit"));
    options.timeLimitSeconds = read.number("time_limit");
    options.traceRules = ctx.traceSources;
    const lsys::ModuleString word = lsys::derive(grammar, options, ctx.progress);
    out.timingsMs["expand"] = msSince(t0);

    // Unset: the grammar's own, which must be in the parameter's range too.
    lsys::TurtleSettings turtle;
    turtle.angleDegrees = read.numberOr("angle", grammar.angleDegrees);
    turtle.step = read.numberOr("step", grammar.step);
    turtle.width = read.numberOr("width", grammar.width);
    turtle.widthFactor = read.numberOr("width_factor", grammar.widthFactor);
    read.requireIn("angle", turtle.angleDegrees);
    read.requireIn("step", turtle.step);
    read.requireIn("width", turtle.width);
    read.requireIn("width_factor", turtle.widthFactor);
    turtle.leafSize = read.numberOr("leaf_size", turtle.leafSize);

    skel::RadiusShaping shaping;
    shaping.taper = static_cast<float>(read.number("taper"));
    shaping.junctionSlope = static_cast<float>(read.number("junction_slope"));
    skel::validate(shaping);

    t0 = std::chrono::steady_clock::now();
    auto skeleton = std::make_shared<skel::Skeleton>(lsys::interpret(word, turtle, ctx.progress));
    skeleton->finalize();
    skel::shapeRadii(*skeleton, shaping);
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

void registerLsystemNode(graph::NodeRegistry& registry) {
    graph::NodeType type;
    type.name = "lsystem";
    type.doc = "Derives an L-system grammar and interprets the word with a 3D turtle";
    type.category = "Generator";
    type.role = graph::NodeRole::Generator;
    type.minInputs = type.maxInputs = 0;
    type.output = graph::PortKind::Skeleton;
    type.evaluate = evaluateLsystem;
    type.params = lsystemParams();
    registry.add(std::move(type));
}

} // namespace sylva::nodes
