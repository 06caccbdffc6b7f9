#pragma once

#include "engine/export/lodchainexport.h"

namespace sylva::exporter {

/// The chain's mesh levels as `<species>_LOD<i>.obj`, one object each named like the file,
/// sharing `<species>.mtl`.
void writeObjLodChain(const LodChainWrite& w, GameLodFiles& files,
                      std::vector<std::filesystem::path>& written);

} // namespace sylva::exporter
