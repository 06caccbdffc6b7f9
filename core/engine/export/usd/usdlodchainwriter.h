#pragma once

#include "engine/export/lodchainexport.h"

namespace sylva::exporter {

/// The chain as `<species>_lods.usda` (formatLodChainStage: a "lod" variant set).
void writeUsdLodChain(const LodChainWrite& w, GameLodFiles& files,
                      std::vector<std::filesystem::path>& written);

} // namespace sylva::exporter
