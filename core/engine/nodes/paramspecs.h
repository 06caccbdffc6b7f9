#pragma once

// Short builders for the node types' parameter metadata (graph::ParamSpec), so that each
// node's table reads as one line per parameter.

#include <string>
#include <utility>
#include <vector>

#include "engine/graph/graph.h"

namespace sylva::nodes {

using graph::ParamKind;
using graph::ParamSpec;
using sylva::Value;

inline constexpr double kMaxSeed = 9007199254740992.0; // 2^53: exact in a JSON number

inline ParamSpec number(std::string name, Value def, double lo, double hi, std::string unit,
                        std::string doc, bool minOpen = false) {
    ParamSpec p;
    p.name = std::move(name);
    p.kind = ParamKind::Number;
    p.defaultValue = std::move(def);
    p.min = lo;
    p.max = hi;
    p.minOpen = minOpen;
    p.unit = std::move(unit);
    p.doc = std::move(doc);
    return p;
}

inline ParamSpec integer(std::string name, Value def, double lo, double hi, std::string doc) {
    ParamSpec p = number(std::move(name), std::move(def), lo, hi, "", std::move(doc));
    p.kind = ParamKind::Integer;
    return p;
}

inline ParamSpec boolean(std::string name, bool def, std::string doc) {
    ParamSpec p;
    p.name = std::move(name);
    p.kind = ParamKind::Bool;
    p.defaultValue = def;
    p.doc = std::move(doc);
    return p;
}

inline ParamSpec choice(std::string name, std::string def, std::vector<std::string> choices,
                        std::string doc) {
    ParamSpec p;
    p.name = std::move(name);
    p.kind = ParamKind::Enum;
    p.defaultValue = std::move(def);
    p.choices = std::move(choices);
    p.doc = std::move(doc);
    return p;
}

inline ParamSpec vector(std::string name, Value def, double lo, double hi, std::string unit,
                        std::string doc) {
    ParamSpec p = number(std::move(name), std::move(def), lo, hi, std::move(unit), std::move(doc));
    p.kind = ParamKind::Vector;
    return p;
}

inline ParamSpec other(std::string name, ParamKind kind, std::string doc) {
    ParamSpec p;
    p.name = std::move(name);
    p.kind = kind;
    p.doc = std::move(doc);
    return p;
}

inline Value vec(double x, double y, double z) {
    return Value(Value::Array{x, y, z});
}

/// The final radius pass's two parameters (skel::RadiusShaping), the same on every generator.
inline ParamSpec taperParam() {
    return number("taper", 0.1, 0, 1, "1/m",
                  "Least taper of an axis: a node at least 1 + taper x length times the one "
                  "above it (a clear trunk tapers); 0: off");
}
inline ParamSpec junctionSlopeParam() {
    return number("junction_slope", 0.08, 0, 10, "",
                  "Steepest thinning of an axis above a fork (m per m): no step or collar where "
                  "a branch leaves; 0: off");
}

/// Sets the panel section of every spec in \p specs and appends them to \p out.
inline void group(std::vector<ParamSpec>& out, const std::string& name,
                  std::vector<ParamSpec> specs) {
    for (ParamSpec& p : specs) {
        p.group = name;
        out.push_back(std::move(p));
    }
}

} // namespace sylva::nodes
