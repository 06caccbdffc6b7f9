#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace sylva::exporter::usd {

/// What a tile layer says of itself in its `customLayerData` (written by UsdStageWriter).
struct TileHeader {
    int tile = 0;  ///< 1-based
    int tiles = 0; ///< the run's tile count
    std::string scene;
};

/// Reads the layer metadata at the top of a Sylva `.usda` layer (only the first few kilobytes).
/// \throw IoError when it cannot be read; InvalidInput when it is not a Sylva tile layer.
TileHeader readTileHeader(const std::filesystem::path& layer);

/// Writes the root layer of a farm run: stage metadata (`upAxis = "Y"`, `metersPerUnit = 1`,
/// `defaultPrim = "Forest"`) and `subLayers` naming \p tiles (paths relative to \p root), in
/// tile order, so that the composed stage is the single run's forest, tree for tree. Checks that
/// the tiles are the N tiles of one run, each once (InvalidInput names what is missing or
/// repeated); written atomically. \throw InvalidInput, IoError
void writeRootLayer(const std::filesystem::path& root,
                    const std::vector<std::filesystem::path>& tiles);

} // namespace sylva::exporter::usd
