// Fuzzes derivation and turtle interpretation under the documented limits: a parsed grammar is
// derived for its own `generations:` (at most 1000, the parser's limit) under a symbol limit,
// so an exploding grammar must stop with LimitExceeded, quickly and within memory, and the
// word it yields must make a valid skeleton. The symbol limit is lowered from the default
// 20,000,000 to keep executions fast; the code path that enforces it is the same.
#include "engine/lsystem/derivation.h"
#include "engine/lsystem/grammar.h"
#include "engine/lsystem/turtle.h"
#include "engine/util/error.h"

#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string_view>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string_view text(reinterpret_cast<const char*>(data), size);
    try {
        const sylva::lsys::Grammar grammar = sylva::lsys::parseGrammar(text, "fuzz.lsys");
        sylva::lsys::DeriveOptions options;
        options.symbolLimit = 20'000;
        const sylva::lsys::ModuleString word = sylva::lsys::derive(grammar, options);
        if (word.size() > options.symbolLimit) std::abort();

        sylva::lsys::TurtleSettings settings;
        settings.angleDegrees = grammar.angleDegrees;
        settings.step = grammar.step;
        settings.width = grammar.width;
        settings.widthFactor = grammar.widthFactor;
        const sylva::skel::Skeleton skeleton = sylva::lsys::interpret(word, settings);
        skeleton.validate();
        if (skeleton.size() > word.size() + 1) std::abort(); // one node per F, plus a root
    } catch (const sylva::InvalidInput&) {
    } catch (const sylva::LimitExceeded&) {
    }
    return 0;
}
