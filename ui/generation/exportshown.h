#pragma once

#include <cstddef>

#include <QString>
#include <glm/vec3.hpp>

#include "document/document.h"
#include "engine/util/progress.h"
#include "ui/generation/treegenerator.h"

namespace sylva::ui {

/// What File ▸ Export takes from a project: only the selected trees, and the level of detail
/// chosen for the viewport's camera instead of the project's (the forest is built again for
/// it, as `sylva-cli forest` would with that camera). A species preview ignores both.
struct ExportOptions {
    bool selectionOnly = false;
    bool viewportCamera = false;
    /// A project with a wind (Project::wind) is written with it, as `sylva-cli forest --wind`
    /// with the project's direction, strength, gustiness and frequency: a rig and the looping
    /// clip per tree, the _WIND* data, Pivot Painter 2 textures and the .wind.csv table
    /// (.glb, .gltf, .fbx; an OBJ gets its table). Off, or a project without a wind, a .usda
    /// or a species preview: written without.
    bool projectWind = true;
};

/// What the editor shows, as exportShown() needs it.
struct ShownScene {
    const GenerationResult& result;          ///< the last successful generation drawn
    const doc::Document* document = nullptr; ///< its project and selection; null: a preview
    glm::vec3 eye{0.0f}, target{0.0f};       ///< the viewport's camera
};

/// What exportShown() wrote.
struct ExportCount {
    std::size_t trees = 0; ///< trees written
    std::size_t files = 0; ///< files written (the main file, its materials, textures)
    bool wind = false;     ///< written with the project's wind
};

/// Exports \p shown to \p path by its extension: a species preview's tree exactly as `sylva-cli
/// tree` writes it; the document's project through doc::exportProject, the export `sylva-cli
/// forest` and Python's `export_forest` make (the forest built as they build it, the project's
/// wind by default), with \p options translated into the request: only the selected trees, the
/// viewport camera's level of detail, no wind. Runs on the calling thread (the editor calls it
/// on a worker; \p progress reports and cancels). \throw InvalidInput when the selection holds
/// no hand-placed tree to export \throw IoError when the writing fails (the file is then left as
/// it was) \throw Cancelled
ExportCount exportShown(const QString& path, const ShownScene& shown,
                        const ExportOptions& options = {}, Progress& progress = noProgress());

} // namespace sylva::ui
