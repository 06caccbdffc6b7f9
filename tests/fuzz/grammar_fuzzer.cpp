// Fuzzes the grammar parser and the expression compiler/evaluator: any text either parses or
// throws InvalidInput with at least one positioned diagnostic. What parses is rewritten for one
// generation under a small symbol limit, which evaluates every expression the first step reaches.
#include "engine/lsystem/derivation.h"
#include "engine/lsystem/grammar.h"
#include "engine/util/error.h"

#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string_view>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string_view text(reinterpret_cast<const char*>(data), size);
    sylva::lsys::Grammar grammar;
    try {
        grammar = sylva::lsys::parseGrammar(text, "fuzz.lsys");
    } catch (const sylva::InvalidInput& e) {
        if (e.diagnostics().empty()) std::abort(); // parse errors always carry positions
        for (const sylva::Diagnostic& d : e.diagnostics())
            if (d.line < 0 || d.column < 0 || d.format().empty()) std::abort();
        return 0;
    }
    sylva::lsys::DeriveOptions options;
    options.generations = grammar.generations > 0 ? 1 : 0;
    options.symbolLimit = 10'000;
    try {
        const sylva::lsys::ModuleString word = sylva::lsys::derive(grammar, options);
        if (word.size() > options.symbolLimit) std::abort();
        (void)sylva::lsys::formatModules(word);
    } catch (const sylva::InvalidInput&) {
    } catch (const sylva::LimitExceeded&) {
    }
    return 0;
}
