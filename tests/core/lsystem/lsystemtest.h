#pragma once

#include <optional>
#include <string>
#include <vector>

#include "engine/lsystem/derivation.h"
#include "engine/lsystem/grammar.h"
#include "engine/util/error.h"

namespace sylva::lsys::test {

/// DeriveOptions in one expression (designated initializers warn about omitted members).
inline DeriveOptions options(std::optional<int> generations,
                             std::optional<std::uint64_t> seed = std::nullopt,
                             std::size_t symbolLimit = 20'000'000) {
    DeriveOptions o;
    o.generations = generations;
    o.seed = seed;
    o.symbolLimit = symbolLimit;
    return o;
}

/// Parses \p text and returns the derived word in its printed form.
inline std::string expand(const std::string& text, std::optional<int> generations = {},
                          std::optional<std::uint64_t> seed = {}) {
    DeriveOptions opt;
    opt.generations = generations;
    opt.seed = seed;
    return formatModules(derive(parseGrammar(text, "test.lsys"), opt));
}

/// The diagnostics parseGrammar() reports for \p text (empty when it parses).
inline std::vector<Diagnostic> diagnose(const std::string& text) {
    try {
        parseGrammar(text, "test.lsys");
    } catch (const InvalidInput& e) {
        return e.diagnostics();
    }
    return {};
}

/// Counts occurrences of \p c in \p s.
inline std::size_t countOf(const std::string& s, char c) {
    std::size_t n = 0;
    for (char x : s)
        n += x == c;
    return n;
}

} // namespace sylva::lsys::test
