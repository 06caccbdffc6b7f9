// `sylva-cli nodes`: the node types and their parameters, read from the engine's metadata
// (the same ParamSpecs that validate species files and build the editor's panels).
#include "cliargs.h"
#include "commands.h"

#include "engine/graph/graph.h"

#include <cstdio>
#include <string>

namespace sylva::cli {

namespace {

using graph::NodeType;
using graph::ParamKind;
using graph::ParamSpec;

const char* kindName(ParamKind kind) {
    switch (kind) {
    case ParamKind::Number:
        return "number";
    case ParamKind::Integer:
        return "integer";
    case ParamKind::Bool:
        return "bool";
    case ParamKind::Enum:
        return "enum";
    case ParamKind::Vector:
        return "vector";
    case ParamKind::File:
        return "file";
    case ParamKind::Curve:
        return "curve";
    case ParamKind::Text:
        return "text";
    case ParamKind::Object:
        return "object";
    }
    return "?";
}

std::string defaultText(const ParamSpec& p) {
    return p.defaultValue.isNull() ? std::string("unset") : p.defaultValue.toJson();
}

std::string inputsText(const NodeType& t) {
    if (t.maxInputs == 0) return "none";
    std::string kinds;
    for (graph::PortKind k : t.accepts)
        kinds += (kinds.empty() ? "" : " or ") + std::string(graph::portKindName(k));
    return (t.minInputs == 0 ? "optional " : "") + kinds;
}

std::string outputText(const NodeType& t) {
    return t.outputFollowsInput ? "same as input" : graph::portKindName(t.output);
}

void printMarkdown(const NodeType& t) {
    std::printf("### `%s` (%s)\n\n%s. Input: %s; output: %s.\n\n", t.name.c_str(),
                t.category.c_str(), t.doc.c_str(), inputsText(t).c_str(), outputText(t).c_str());
    std::printf("| parameter | type | default | range | meaning |\n|---|---|---|---|---|\n");
    std::string group;
    for (const ParamSpec& p : t.params) {
        if (p.group != group) {
            group = p.group;
            std::printf("| **%s** | | | | |\n", group.c_str());
        }
        std::string range = p.rangeText();
        for (std::size_t i = 0; (i = range.find('|', i)) != std::string::npos; i += 2)
            range.replace(i, 1, "\\|");
        std::printf("| `%s` | %s | `%s` | %s | %s |\n", p.name.c_str(), kindName(p.kind),
                    defaultText(p).c_str(), range.c_str(), p.doc.c_str());
    }
    std::printf("\n");
}

void printText(const NodeType& t) {
    std::printf("%s (%s): %s\n  input: %s; output: %s\n", t.name.c_str(), t.category.c_str(),
                t.doc.c_str(), inputsText(t).c_str(), outputText(t).c_str());
    std::string group;
    for (const ParamSpec& p : t.params) {
        if (p.group != group) {
            group = p.group;
            std::printf("  %s\n", group.c_str());
        }
        const std::string range = p.rangeText();
        std::printf("    %-24s %-8s %-10s %-22s %s\n", p.name.c_str(), kindName(p.kind),
                    defaultText(p).c_str(), range.c_str(), p.doc.c_str());
    }
}

sylva::Value toJson(const NodeType& t) {
    using sylva::Value;
    Value::Array params;
    for (const ParamSpec& p : t.params) {
        Value::Object o{{"name", p.name},
                        {"kind", kindName(p.kind)},
                        {"default", p.defaultValue},
                        {"unit", p.unit},
                        {"doc", p.doc},
                        {"group", p.group}};
        if (p.kind == ParamKind::Number || p.kind == ParamKind::Integer ||
            p.kind == ParamKind::Vector) {
            if (p.min > -1e300) o["min"] = p.min;
            if (p.max < 1e300) o["max"] = p.max;
            o["min_exclusive"] = p.minOpen;
        }
        if (!p.choices.empty()) {
            Value::Array c;
            for (const std::string& s : p.choices)
                c.emplace_back(s);
            o["choices"] = Value(std::move(c));
        }
        params.emplace_back(std::move(o));
    }
    Value::Array accepts;
    for (graph::PortKind k : t.accepts)
        accepts.emplace_back(graph::portKindName(k));
    return Value(Value::Object{{"name", t.name},
                               {"doc", t.doc},
                               {"category", t.category},
                               {"min_inputs", t.minInputs},
                               {"max_inputs", t.maxInputs},
                               {"accepts", Value(std::move(accepts))},
                               {"output", outputText(t)},
                               {"params", Value(std::move(params))}});
}

} // namespace

int runNodes(const std::vector<std::string>& argv) {
    const Args args(argv, {}, {"--markdown", "--json"});
    graph::registerBuiltinNodeTypes();
    const graph::NodeRegistry& registry = graph::NodeRegistry::instance();
    std::vector<std::string> names = registry.names();
    if (args.positional().size() > 1) throw UsageError("nodes takes at most one node type");
    if (args.positional().size() == 1) {
        if (!registry.find(args.positional()[0])) {
            std::string known;
            for (const std::string& n : names)
                known += (known.empty() ? "" : ", ") + n;
            throw UsageError("unknown node type '" + args.positional()[0] + "' (known: " + known +
                             ")");
        }
        names = {args.positional()[0]};
    }
    if (args.flag("--json")) {
        sylva::Value::Array all;
        for (const std::string& n : names)
            all.push_back(toJson(*registry.find(n)));
        std::printf("%s\n", sylva::Value(std::move(all)).toPrettyJson().c_str());
        return kOk;
    }
    for (const std::string& n : names) {
        if (args.flag("--markdown"))
            printMarkdown(*registry.find(n));
        else
            printText(*registry.find(n));
    }
    return kOk;
}

} // namespace sylva::cli
