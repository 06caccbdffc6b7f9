#pragma once

#include <cstddef>

#include <QString>
#include <glm/vec3.hpp>

#include "document/document.h"
#include "ui/generation/treegenerator.h"

namespace sylva::ui {

/// What File ▸ Export takes from a project: only the selected trees, and the level of detail
/// chosen for the viewport's camera instead of the project's (the forest is built again for
/// it, as `sylva-cli forest` would with that camera). A species preview ignores both.
struct ExportOptions {
    bool selectionOnly = false;
    bool viewportCamera = false;
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
};

/// Exports \p shown to \p path by its extension, exactly as `sylva-cli tree` (a species) or
/// `sylva-cli forest` (the document's project) writes it; with \p options, only the selected
/// trees and at the viewport camera's level of detail. Runs on the calling thread (a rebuild
/// for the camera takes as long as a generation).
/// \throw InvalidInput when the selection holds no hand-placed tree to export
/// \throw IoError when the rebuild or the writing fails (the file is then left as it was)
ExportCount exportShown(const QString& path, const ShownScene& shown,
                        const ExportOptions& options = {});

} // namespace sylva::ui
