#pragma once

#include <memory>
#include <vector>

#include <QString>

#include "document/document.h"
#include "document/filerefs.h"
#include "engine/forest/treecache.h"
#include "engine/util/progress.h"
#include "ui/generation/treegenerator.h"

namespace sylva::env {
class ObstacleScene;
}

namespace sylva::ui {

using doc::isProjectFile;

/// What successive generations of one document share: the trees of the last build (reused when
/// their inputs are unchanged) and the obstacle scenes they were adapted to. Used by one
/// generation at a time.
struct SceneCaches {
    forest::TreeCache trees;
    std::shared_ptr<const env::ObstacleScene> obstacles, ground; ///< kept alive for the keys
};

/// Builds \p project's forest exactly as `sylva-cli forest` does (the same placement,
/// adaptation to the obstacles and neighbours, and level of detail from the project's camera).
/// Each tree is kept on its own (`trees`, placed by its instance transform; hand-placed trees
/// carry their document id, ProjectInstance::id); the obstacle and terrain meshes are
/// merged into `mesh` (submeshes "obstacle" and "ground"). With \p caches, trees whose inputs
/// did not change since the last call are reused instead of regrown. Stats: "trees",
/// "obstacle_triangles", "colliding_trees", "pruned_nodes", "height" (tallest tree), the
/// scene's "co2_kg", "instanced", "unique" and "variants" (ForestStats); "regrown" counts the
/// trees actually grown (not taken from the cache): unique trees plus variants; an instanced
/// tree draws its variant's mesh or level and is not counted. Never throws.
/// (A wind export builds its own forest: doc::exportProject.)
GenerationResult generateProject(const doc::Project& project, const QString& path,
                                 SceneCaches* caches, Progress& progress = noProgress());

/// Loads the project at \p path and generates it (generateProject); loader warnings go to
/// GenerationResult::warning. A project with no trees and no obstacles is an error here.
GenerationResult generateScene(const QString& path, Progress& progress = noProgress());

/// generateScene for a project, generateTree otherwise.
GenerationResult generate(const QString& path, Progress& progress = noProgress());

} // namespace sylva::ui
