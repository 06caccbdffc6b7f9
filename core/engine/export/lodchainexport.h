#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "engine/export/formats.h"
#include "engine/export/materials.h"
#include "engine/mesh/lodchain.h"
#include "engine/util/progress.h"

namespace sylva::exporter {

/// What writeGameLodChain() writes besides the JSON description (always written).
struct GameLodOptions {
    bool obj = true;  ///< <species>_LOD<i>.obj + <species>.mtl
    bool gltf = true; ///< <species>_LODs.glb: MSFT_lod chain, impostor card and maps
    bool fbx = true;  ///< <species>_LODs.fbx: the mesh levels as <species>_LOD<i> nodes
    bool usd = true;  ///< <species>_lods.usda: a "lod" variant set, LOD0..n and "impostor"
    /// Sylva's shipped textures (bark.png, leaf.png) for materials without a file of their own;
    /// also copied into <dir>/textures for the OBJ and FBX files. Empty: none.
    std::filesystem::path shippedTextures;
    /// Whether the chain is written in \p format (the format table's rows with a lodChain).
    bool wants(Format format) const {
        switch (format) {
        case Format::Obj:
            return obj;
        case Format::Glb:
            return gltf;
        case Format::Fbx:
            return fbx;
        case Format::Usda:
            return usd;
        case Format::Gltf:
            break;
        }
        return false;
    }
};

/// One written level.
struct GameLodLevel {
    std::string name; ///< "<species>_LOD<i>" (node, object and file name)
    double budget = 1.0, distance = 0.0, screenSize = 1.0;
    bool budgetMet = true;
    double silhouetteIoU = 1.0;     ///< against LOD0 at its switch distance (mesh::silhouetteIoU)
    double leafClusterPixels = 0.0; ///< the leaf clusters it was made with (0 for LOD0)
    std::size_t triangles = 0, vertices = 0;
    std::filesystem::path obj;
};

struct GameLodFiles {
    std::vector<GameLodLevel> levels;
    std::vector<mesh::DroppedLevel> dropped; ///< budgets left out (mesh::BudgetLodChain::dropped)
    std::filesystem::path glb, fbx, usd, mtl, json;
    std::filesystem::path impostorColor, impostorNormal, impostorDepth; ///< empty: no impostor
    bool impostor = false;
    double impostorDistance = 0.0, impostorScreenSize = 0.0;
    std::string description; ///< the JSON written to `json` (what `sylva-cli lods --json` prints)
};

/// What one format's LOD chain writer is given (FormatRow::lodChain: obj/objlodchain,
/// gltf/gltflodchain, fbx/fbxlodchain, usd/usdlodchainwriter); it writes its files, fills its
/// fields of GameLodFiles and appends what it wrote to `written`.
struct LodChainWrite {
    const std::filesystem::path& dir;
    const std::string& species;      ///< as given (USD's sylva:species)
    const std::string& base;         ///< fileSafeName(species): the files' stem
    const std::string& impostorName; ///< base + "_impostor"
    const mesh::BudgetLodChain& chain;
    const std::vector<Material>& materials; ///< the mesh levels' materials
    const GameLodOptions& options;
    /// The impostor's maps as PNG (empty without an impostor), written beside the chain.
    const std::string& colorPng;
    const std::string& normalPng;
    const std::string& depthPng;
    Progress& progress;
};

/// Writes a species' game LOD chain into \p dir (created when missing), every file atomically:
/// `<species>_impostor_color.png`, `_normal.png`, `_depth.png` (the atlas maps, docs/lods.md),
/// `<species>_LODs.glb` (LOD0's node carries MSFT_lod with the coarser levels and the impostor
/// card, MSFT_screencoverage in its extras; the impostor's material is documented in
/// docs/lods.md), `<species>_LODs.fbx` (the mesh levels as sibling nodes `<species>_LOD<i>`:
/// Assimp writes no FbxLODGroup), `<species>_lods.usda` (the root prim's variant set "lod":
/// LOD0..n and "impostor", docs/usd.md), OBJ files, and `<species>_lods.json` describing all of it
/// for a game engine's importer. \p species becomes part of file names: characters other than
/// letters, digits, '-' and '_' become '_'.
/// \throw InvalidInput (empty species name or chain), IoError, Cancelled.
GameLodFiles writeGameLodChain(const std::filesystem::path& dir, const std::string& species,
                               const mesh::BudgetLodChain& chain,
                               const mesh::LodSettings& reference,
                               const GameLodOptions& options = {},
                               Progress& progress = noProgress());

/// The chain of one tree as `sylva-cli lods` makes and writes it: buildBudgetLodChain() of
/// \p skeleton with \p settings (the impostor baked with the species' textures, else the
/// shipped ones in options.shippedTextures), then writeGameLodChain(). Reports the stages
/// "levels", "impostor" and "writing". The one path of the CLI, Python and the editor.
/// \throw InvalidInput, IoError, Cancelled (nothing is left written).
GameLodFiles writeTreeLodChain(const std::filesystem::path& dir, const std::string& name,
                               const skel::Skeleton& skeleton,
                               const mesh::TreeMeshSettings& settings,
                               const mesh::LodChainSettings& chain,
                               const GameLodOptions& options = {},
                               Progress& progress = noProgress());

} // namespace sylva::exporter
