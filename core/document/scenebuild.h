#pragma once

#include "document/project.h"
#include "engine/forest/forestbuild.h"

namespace sylva::doc {

/// Turns a project into what the engine builds a forest from: loads every species (file or
/// inline graph), every obstacle mesh (with its transform) into one Embree scene, and the
/// terrain of a terrain domain as the ground. Paths resolve against the project's folder.
/// \throw InvalidInput / IoError naming the file that is missing, unreadable or empty.
forest::ForestScene makeForestScene(const Project& project);

} // namespace sylva::doc
