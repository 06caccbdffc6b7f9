#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace sylva::lsys {

/// A derived L-system word in compact form. Each module is one byte in `symbols`; its actual
/// parameters are the next `paramCounts[i]` values of `params`, in module order.
/// `paramCounts` is empty when no module carries parameters (the fast context-free path);
/// otherwise it has one entry per symbol.
struct ModuleString {
    std::string symbols;
    std::vector<std::uint8_t> paramCounts;
    std::vector<double> params;
    /// Only when derived with DeriveOptions::traceRules (else empty): per module, the 1-based
    /// grammar line of the rule that last wrote it, or of the axiom for a module no rule wrote. A
    /// module no rule rewrites keeps its line from one generation to the next.
    std::vector<std::int32_t> origins;

    std::size_t size() const { return symbols.size(); }
    bool hasParams() const { return !paramCounts.empty(); }
    void clear() {
        symbols.clear();
        paramCounts.clear();
        params.clear();
        origins.clear();
    }
};

} // namespace sylva::lsys
