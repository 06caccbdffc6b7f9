#include "cliargs.h"
#include "commands.h"
#include "usage.h"

#include "engine/export/usd/usdcompose.h"

#include <cstdio>

namespace sylva::cli {

int runCompose(const std::vector<std::string>& argv) {
    const Args args(argv, {}, {});
    if (args.positional().size() < 2) throw UsageError(commandUsageLine("compose"));
    std::vector<std::filesystem::path> tiles(args.positional().begin() + 1,
                                             args.positional().end());
    exporter::usd::writeRootLayer(args.positional()[0], tiles);
    std::fprintf(stderr, "sylva-cli: %s composes %zu tiles\n", args.positional()[0].c_str(),
                 tiles.size());
    return kOk;
}

} // namespace sylva::cli
