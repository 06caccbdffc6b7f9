#pragma once

#include <QString>

#include "engine/util/progress.h"
#include "ui/treegenerator.h"

namespace sylva::ui {

/// Whether \p path names a project (`.sylva`, or a JSON file that is a project or the reference
/// implementation's scene description) rather than a species or grammar.
bool isProjectFile(const QString& path);

/// Loads the project at \p path and builds its forest exactly as `sylva-cli forest` does (the
/// same placement, adaptation to the obstacles and neighbours, and level of detail from the
/// project's camera), then merges every tree, placed in the world, and the obstacle and terrain
/// meshes into one mesh for the viewport: submeshes "bark", "leaf", then "obstacle" and
/// "ground". No skeleton (a forest has many). Stats: "trees", "obstacle_triangles",
/// "colliding_trees", "pruned_nodes" and the scene's "co2_kg". Loader warnings
/// (a newer file, upgrades) go to GenerationResult::warning. Never throws, like generateTree.
GenerationResult generateScene(const QString& path, Progress& progress = noProgress());

/// generateScene for a project, generateTree otherwise.
GenerationResult generate(const QString& path, Progress& progress = noProgress());

} // namespace sylva::ui
