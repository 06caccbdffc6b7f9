#pragma once

#include <cstdint>
#include <filesystem>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "document/project.h"
#include "engine/export/usd/usdstagewriter.h"
#include "engine/export/windexport.h"
#include "engine/forest/forestbuild.h"
#include "engine/mesh/season.h"
#include "engine/util/progress.h"

namespace sylva::doc {

/// Wind settings a front door gives over the project's wind (`--wind-strength 1.2`, Python's
/// `strength=1.2`): each one set overrides that setting; the rest are the project's (or the
/// engine's defaults when the project has no wind).
struct WindOverride {
    std::optional<glm::vec3> direction;
    std::optional<float> strength, gustiness, frequency;
    std::optional<float> clipLength; ///< seconds of the looping clip
    std::optional<float> clipFps;
    std::optional<int> bones;
};

/// One export of a project's forest, as every front door asks for it (`sylva-cli forest`,
/// Python's `Project.export_forest`): the CLI's flags and Python's keywords only translate into
/// this.
struct ExportRequest {
    std::filesystem::path path; ///< the file; its extension picks the format
    int tile = 0;               ///< 0-based tile of tileCount (placement::parseTileSpec)
    int tileCount = 1;
    std::optional<glm::vec3> camera;    ///< the LOD reference instead of the project's camera
    std::optional<mesh::Season> season; ///< the whole forest in one season
    bool lod = true, adapt = true, neighbours = true, instancing = true;
    bool adaptVariants = true; ///< false: `--grow-unique`
    bool naivePlacement = false;
    /// Writes the wind rig and clip (.glb, .gltf, .fbx) or the `.wind.csv` table beside an OBJ,
    /// in the project's wind with \ref windOverride over it. Unset: the project's choice: on
    /// when it has a wind and the format carries one (not .usda). true for a .usda is refused.
    std::optional<bool> wind;
    WindOverride windOverride;
    bool fullPrecision = false, fsync = false, instanceTables = false, assimpGltf = false;
    /// Only these trees (stable ids: the editor's selection) are written; the forest is still
    /// built whole, so they adapt to their neighbours as in the full export. Unset: every tree.
    std::optional<std::set<std::uint64_t>> trees;
};

/// What an export wrote and its one statistics value.
struct ExportReport {
    std::vector<std::filesystem::path> files;
    forest::ForestStats stats;
    std::size_t written = 0; ///< trees written (fewer than stats.trees with a tree filter)
    bool wind = false;       ///< written with a wind model
    std::size_t obstacleTriangles = 0;
    std::vector<std::string> species; ///< names, by index (shortfalls name them)
    int tile = 1, tiles = 1;          ///< 1-based, as written
    std::optional<exporter::usd::UsdLayerStats> usd;
    double loadMs = 0.0, writeMs = 0.0, totalMs = 0.0;
};

/// The wind an export writes: the project's wind (or the engine's defaults) with \p override
/// over it, validated (InvalidInput naming the range).
exporter::WindExportOptions exportWind(const std::optional<wind::WindSettings>& projectWind,
                                       const WindOverride& override);

/// What identifies a run for `sylva-cli compose` (written into every `.usda` tile as
/// `sylvaScene`): the project as saved (canonical JSON) and the request's settings that change
/// trees (camera, LOD, adaptation, neighbours, season), FNV-1a 64 as hex. The same project
/// gives the same key from every front door.
std::string sceneKey(const Project& project, const ExportRequest& request);

/// Builds \p project's forest and writes it as \p request says, batch by batch (nothing at the
/// path before it is complete; Cancelled through \p progress leaves no file).
/// \throw InvalidInput, IoError, LimitExceeded, Cancelled.
ExportReport exportProject(const Project& project, const ExportRequest& request,
                           Progress& progress = noProgress());

/// The same from a scene already made (Python's projects carry obstacles as arrays):
/// \p project gives the wind and the scene key.
ExportReport exportForest(forest::ForestScene scene, const Project& project,
                          const ExportRequest& request, Progress& progress = noProgress());

/// The report as one JSON object: what `sylva-cli forest --stats` prints and Python's
/// `export_forest` returns (parsed): trees, trees_in_scene, tile, tiles, threads, vertices,
/// triangles, obstacle_triangles, colliding_trees, pruned_nodes, instanced, unique,
/// adapted_variants, instanced_by_check, variants, shortfall, usd (a .usda), metrics,
/// timings_ms, cpu_ms.
std::string exportStatsJson(const ExportReport& report, int threads);

} // namespace sylva::doc
