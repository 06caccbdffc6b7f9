#pragma once

#include "document/project.h"
#include "engine/forest/forestbuild.h"
#include "engine/nodes/adaptnode.h"

#include <vector>

namespace sylva::doc {

/// Turns a project into what the engine builds a forest from: loads every species (file or
/// inline graph), every obstacle mesh (with its transform) into one Embree scene, and the
/// terrain of a terrain domain as the ground. Paths resolve against the project's folder.
/// \throw InvalidInput / IoError naming the file that is missing, unreadable or empty.
forest::ForestScene makeForestScene(const Project& project);

/// The project's obstacle meshes as one scene's specs (files resolved, transforms): what
/// makeForestScene loads, and what opening checks through the same scene cache, so that a
/// project's meshes are read once, not once to check and again to grow.
std::vector<env::ObstacleSpec> obstacleSpecsOf(const Project& project);

/// The terrain mesh of the terrain domain \p d.
env::ObstacleSpec terrainSpecOf(const Project& project, const PlacementDomain& d);

} // namespace sylva::doc
