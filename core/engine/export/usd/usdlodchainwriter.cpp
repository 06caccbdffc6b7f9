#include "engine/export/usd/usdlodchainwriter.h"

#include "engine/export/usd/usdlodchain.h"
#include "engine/util/atomicfile.h"

namespace sylva::exporter {

namespace fs = std::filesystem;

void writeUsdLodChain(const LodChainWrite& w, GameLodFiles& files, std::vector<fs::path>& written) {
    const fs::path& dir = w.dir;
    const std::string& base = w.base;
    const mesh::BudgetLodChain& chain = w.chain;
    const std::vector<Material>& materials = w.materials;
    Progress& progress = w.progress;
    const std::string& species = w.species;
    const std::string& impostorName = w.impostorName;
    usd::UsdLodChainNames names;
    names.species = species;
    names.prim = base;
    for (const GameLodLevel& l : files.levels)
        names.levelNames.push_back(l.name);
    names.materials = materials;
    if (chain.impostor) {
        names.impostorName = impostorName;
        names.impostorColor = files.impostorColor.filename().string();
        names.impostorNormal = files.impostorNormal.filename().string();
        names.impostorDepth = files.impostorDepth.filename().string();
    }
    files.usd = dir / (base + "_lods.usda");
    writeFileAtomically(files.usd, usd::formatLodChainStage(chain, names, progress));
    written.push_back(files.usd);
    progress.checkCancelled();
}

} // namespace sylva::exporter
