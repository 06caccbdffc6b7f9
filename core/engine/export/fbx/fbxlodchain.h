#pragma once

#include "engine/export/lodchainexport.h"

namespace sylva::exporter {

/// The chain's mesh levels as sibling nodes `<species>_LOD<i>` of `<species>_LODs.fbx`.
void writeFbxLodChain(const LodChainWrite& w, GameLodFiles& files,
                      std::vector<std::filesystem::path>& written);

} // namespace sylva::exporter
