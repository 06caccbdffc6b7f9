#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>

#include "engine/lsystem/grammar.h"
#include "engine/lsystem/modulestring.h"
#include "engine/util/progress.h"

namespace sylva::lsys {

/// Most module parameters (doubles) a generation may hold: twice the symbol limit, so that
/// parametric words stay within memory too (20 million modules of 8 parameters each would take
/// 3.4 GB before reaching the symbol limit).
constexpr std::size_t paramLimitOf(std::size_t symbolLimit) {
    return symbolLimit > SIZE_MAX / 2 ? SIZE_MAX : 2 * symbolLimit;
}

/// The default DeriveOptions::timeLimitSeconds (5 minutes).
inline constexpr double kDefaultDeriveTimeLimit = 300.0;
/// The largest DeriveOptions::timeLimitSeconds (a day).
inline constexpr double kMaxDeriveTimeLimit = 86400.0;

struct DeriveOptions {
    std::optional<int> generations;       ///< overrides Grammar::generations (>= 0)
    std::optional<std::uint64_t> seed;    ///< overrides Grammar::seed
    std::size_t symbolLimit = 20'000'000; ///< most modules any generation may hold
    /// Most seconds of wall-clock time the derivation may take, (0, 86400]. Within the symbol
    /// limit a grammar can still rewrite 20 million modules for 1000 generations (hours): past
    /// this it stops with LimitExceeded. Checked with the cancellation (between generations and
    /// every million modules), so the result never depends on it: a derivation either finishes
    /// with the same word or throws.
    double timeLimitSeconds = kDefaultDeriveTimeLimit;
    /// Record which rule wrote each module (ModuleString::origins), so the editor can show the
    /// rule behind a clicked branch. Same word; takes the general path (a few times slower for
    /// the grammars the table-driven path serves).
    bool traceRules = false;
};

/// Rewrites the axiom `generations` times (ABOP rule choice, see docs/grammar.md).
/// Context-free deterministic grammars without parameters take a table-driven path whose next
/// length is known exactly before any memory is spent; other grammars never hold more than
/// `symbolLimit` modules either.
/// \throw LimitExceeded naming the generation that would exceed `symbolLimit` modules or
///        paramLimitOf(symbolLimit) module parameters, or naming the time limit when the
///        derivation takes longer than `timeLimitSeconds`.
/// \throw InvalidInput with a Diagnostic at the failing expression (division by zero, a
///        non-finite value) naming the rule.
/// \throw Cancelled when \p progress asks to stop (checked between generations and every
///        million modules).
/// Stochastic choices and rand() draw from sylva::Rng seeded by mixSeed(seed, generation), so
/// the result depends only on the grammar, the generation count and the seed.
ModuleString derive(const Grammar& g, const DeriveOptions& opt = {}, Progress& p = noProgress());

/// Shortest text form without spaces: "A(4)B(3)F[+F]" (numbers in the shortest form that reads
/// back to the same double; parameters separated by ',').
std::string formatModules(const ModuleString& s);

} // namespace sylva::lsys
