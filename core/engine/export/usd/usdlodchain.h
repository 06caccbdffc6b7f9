#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "engine/export/materials.h"
#include "engine/mesh/lodchain.h"
#include "engine/util/progress.h"

namespace sylva::exporter::usd {

/// What the LOD chain's stage names besides the chain itself.
struct UsdLodChainNames {
    std::string species;                 ///< sylva:species; the root prim is primName(prim)
    std::string prim;                    ///< the root prim's name before primName()
    std::vector<std::string> levelNames; ///< one per mesh level ("oak_LOD0"), for sylva:name
    std::string impostorName;            ///< "oak_impostor"
    /// The impostor's maps, relative to the layer (empty: the chain has no impostor).
    std::string impostorColor, impostorNormal, impostorDepth;
    /// The mesh levels' materials (defaultMaterials + addMaterialsOf), textures relative to the
    /// layer; the caller copies them.
    std::vector<Material> materials;
};

/// The LOD chain as one USD stage (text): the root prim (kind component, the default prim)
/// carries a variant set "lod" with the variants LOD0..LODn (each the level's meshes under an
/// Xform of the variant's name) and "impostor" (the fallback card, impostorCard(), with a
/// UsdPreviewSurface over the impostor's colour and normal maps and the atlas described in
/// sylva:impostor:* attributes); LOD0 is selected. Materials under <root>/Materials, written by
/// the forest stage's writer (usdmesh.h). Layout: docs/usd.md, "LOD chains".
/// \throw InvalidInput (no level, names not matching the levels), Cancelled.
std::string formatLodChainStage(const mesh::BudgetLodChain& chain, const UsdLodChainNames& names,
                                Progress& progress = noProgress());

} // namespace sylva::exporter::usd
