#pragma once

// Short builders for the node types' parameter metadata (graph::ParamSpec), so that each
// node's table reads as one line per parameter, and the one way a node reads its parameters
// (ParamReader): through that table, so a default and a range are stated once.

#include <cstdint>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "engine/graph/graph.h"
#include "engine/graph/vectorparam.h"

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

/// Reads a node's parameter values through its specs: an absent value is the spec's default,
/// stated once in the node's table; the range was checked against the same spec when the graph
/// was validated (graph::Evaluator::validate, checkParam). Asking for a name the table lacks,
/// or for the default of a spec without one, is a programming error (std::logic_error).
class ParamReader {
public:
    ParamReader(const std::vector<ParamSpec>& specs, const Value& values)
        : mSpecs(specs), mValues(values) {}

    /// A Number or Integer parameter; a given value is checked against the spec's range (as
    /// validation did) for a node evaluated without it.
    double number(const std::string& name) const {
        checked(name);
        return mValues.number(name, defaultOf(name).toNumber(name));
    }
    std::int64_t integer(const std::string& name) const {
        checked(name);
        return mValues.integer(name, static_cast<std::int64_t>(defaultOf(name).toNumber(name)));
    }
    bool boolean(const std::string& name) const {
        return mValues.boolean(name, defaultOf(name).toBool(name));
    }
    /// An Enum (checked against its choices) or text parameter.
    std::string text(const std::string& name) const {
        checked(name);
        return mValues.string(name, defaultOf(name).toString(name));
    }
    /// A Vector parameter, [x, y, z] (graph::vec3Of), each component in the spec's range.
    glm::vec3 vector(const std::string& name) const {
        checked(name);
        const Value* v = mValues.find(name);
        return graph::vec3Of(v && !v->isNull() ? *v : defaultOf(name), name);
    }
    /// A parameter the node reads itself (Object, File): its value, or nullptr when unset.
    const Value* given(const std::string& name) const {
        spec(name);
        const Value* v = mValues.find(name);
        return v && !v->isNull() ? v : nullptr;
    }
    /// A parameter whose spec has no default (unset: the node derives it, e.g. from the
    /// grammar): the value, or \p fallback.
    double numberOr(const std::string& name, double fallback) const {
        checked(name);
        return mValues.number(name, fallback);
    }
    std::int64_t integerOr(const std::string& name, std::int64_t fallback) const {
        checked(name);
        return mValues.integer(name, fallback);
    }
    /// Checks a value that did not come from the parameters (a grammar's own angle) against
    /// the spec's range.
    void requireIn(const std::string& name, double value) const {
        graph::checkParam(spec(name), Value(value));
    }
    const Value& values() const { return mValues; }

    const ParamSpec& spec(const std::string& name) const {
        for (const ParamSpec& p : mSpecs)
            if (p.name == name) return p;
        throw std::logic_error("parameter '" + name + "' is not in the node's table");
    }

private:
    void checked(const std::string& name) const {
        const ParamSpec& p = spec(name);
        if (const Value* v = mValues.find(name); v && !v->isNull()) graph::checkParam(p, *v);
    }
    const Value& defaultOf(const std::string& name) const {
        const ParamSpec& p = spec(name);
        if (p.defaultValue.isNull())
            throw std::logic_error("parameter '" + name + "' has no default: use numberOr");
        return p.defaultValue;
    }
    const std::vector<ParamSpec>& mSpecs;
    const Value& mValues;
};

} // namespace sylva::nodes
