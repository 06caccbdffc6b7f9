#pragma once

#include "engine/export/lodchainexport.h"

namespace sylva::exporter {

/// The chain as `<species>_LODs.glb`: LOD0's node carries MSFT_lod with the coarser levels and
/// the impostor card (its maps embedded), MSFT_screencoverage in its extras.
void writeGltfLodChain(const LodChainWrite& w, GameLodFiles& files,
                       std::vector<std::filesystem::path>& written);

} // namespace sylva::exporter
