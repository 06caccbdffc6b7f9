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

    std::size_t size() const { return symbols.size(); }
    bool hasParams() const { return !paramCounts.empty(); }
    void clear() {
        symbols.clear();
        paramCounts.clear();
        params.clear();
    }
};

} // namespace sylva::lsys
