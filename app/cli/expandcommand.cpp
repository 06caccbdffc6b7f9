#include "cliargs.h"
#include "commands.h"
#include "usage.h"

#include "engine/lsystem/derivation.h"
#include "engine/lsystem/grammar.h"
#include "engine/util/error.h"

#include <cstdio>
#include <fstream>
#include <sstream>

namespace sylva::cli {

int runExpand(const std::vector<std::string>& argv) {
    const Args args(argv, {"-n", "--generations", "--seed", "--limit", "--time-limit"}, {});
    if (args.positional().size() != 1) throw UsageError(commandUsageLine("expand"));
    const std::string& path = args.positional()[0];
    std::ifstream in(path, std::ios::binary);
    if (!in) throw IoError("cannot read " + path);
    std::ostringstream text;
    text << in.rdbuf();

    const lsys::Grammar grammar = lsys::parseGrammar(text.str(), path);
    lsys::DeriveOptions options;
    auto n = args.integer("-n", 0, 1000);
    if (!n) n = args.integer("--generations", 0, 1000);
    if (n) options.generations = static_cast<int>(*n);
    if (auto seed = args.integer("--seed", 0, (1LL << 62)))
        options.seed = static_cast<std::uint64_t>(*seed);
    if (auto limit = args.integer("--limit", 1, 2'000'000'000))
        options.symbolLimit = static_cast<std::size_t>(*limit);
    if (auto seconds = args.integer("--time-limit", 1, 86400))
        options.timeLimitSeconds = static_cast<double>(*seconds);

    const std::string word = lsys::formatModules(lsys::derive(grammar, options));
    std::fwrite(word.data(), 1, word.size(), stdout);
    std::fputc('\n', stdout);
    return kOk;
}

} // namespace sylva::cli
