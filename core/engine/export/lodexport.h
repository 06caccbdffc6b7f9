#pragma once

#include <cstddef>
#include <filesystem>
#include <string>
#include <vector>

#include "engine/mesh/lod.h"
#include "engine/skeleton/skeleton.h"
#include "engine/util/progress.h"

namespace sylva::exporter {

/// One written level of a LOD chain.
/// \p name with every character but letters, digits, '-' and '_' replaced by '_': the stem
/// the LOD writers give their files.
std::string fileSafeName(const std::string& name);

struct LodFileLevel {
    std::string name;          ///< "<species>_LOD<i>": OBJ object and glTF node name
    double distance = 0.0;     ///< metres from the camera where the level starts
    std::size_t triangles = 0; ///< bark + leaves
    std::size_t vertices = 0;
    std::filesystem::path objPath; ///< <dir>/<species>_LOD<i>.obj
};

/// What writeLodChain() wrote.
struct LodChainFiles {
    std::vector<LodFileLevel> levels; ///< LOD0 (nearest) first
    std::filesystem::path mtlPath;    ///< <dir>/<species>.mtl, shared by the OBJ files
    std::filesystem::path glbPath;    ///< <dir>/<species>_LODs.glb, one node per level
};

/// Where the files go and what else to write.
struct LodExportOptions {
    bool obj = true; ///< one OBJ (+ shared MTL) per level
    bool glb = true; ///< all levels as nodes of one .glb (one mesh per level, at the origin)
    /// Folder holding bark.png / leaf.png to copy into <dir>/textures; empty: copy nothing.
    std::filesystem::path textureSource;
};

/// Writes a species' LOD chain for game engines: `<species>_LOD0.obj … <species>_LODn.obj`
/// (one object each, named like the file, sharing `<species>.mtl`) and `<species>_LODs.glb`
/// whose nodes `<species>_LOD0 …` each hold one level, every file atomically. The chain is the
/// one mesh::buildLodChain() makes from \p settings.lod's bands (resolution, twig threshold,
/// leaf thinning with conserved area). \p species becomes part of file names: characters other
/// than letters, digits, '-' and '_' are replaced by '_'. Creates \p dir if needed.
/// \throw InvalidInput for invalid LOD bands or an empty species name; IoError; Cancelled.
LodChainFiles writeLodChain(const std::filesystem::path& dir, const std::string& species,
                            const skel::Skeleton& skeleton, const mesh::TreeMeshSettings& settings,
                            const LodExportOptions& options = {},
                            Progress& progress = noProgress());

/// The same for a chain built already (e.g. by the species graph).
LodChainFiles writeLodChain(const std::filesystem::path& dir, const std::string& species,
                            const std::vector<mesh::LodChainLevel>& chain,
                            const LodExportOptions& options = {});

} // namespace sylva::exporter
