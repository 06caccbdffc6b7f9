#pragma once

#include <filesystem>
#include <memory>
#include <vector>

#include "engine/environment/adapt.h"
#include "engine/environment/obstaclemesh.h"
#include "engine/environment/obstaclescene.h"
#include "engine/graph/graph.h"

namespace sylva::env {

/// One obstacle file and where it stands (a project's `obstacles` entry, or an adapt node's).
struct ObstacleSpec {
    std::filesystem::path file; ///< absolute, or relative to the process's working directory
    MeshTransform transform;
};

/// Loads the meshes and builds one ObstacleScene. With \p useCache, scenes are shared between
/// callers as long as the files (path, size, modification time) and transforms are unchanged,
/// so that an editor re-evaluating an adapt node does not rebuild the BVH. Thread-safe.
/// \throw IoError, InvalidInput as loadObstacleMesh.
std::shared_ptr<const ObstacleScene> loadObstacleScene(const std::vector<ObstacleSpec>& specs,
                                                       bool useCache = true);

/// Reads an obstacle entry {"file": ..., "translate": [x,y,z], "rotate": [x,y,z] (degrees),
/// "scale": [x,y,z] or a number}; \p baseDir resolves a relative file.
/// \throw InvalidInput naming the key.
ObstacleSpec obstacleSpecFromValue(const sylva::Value& v, const std::filesystem::path& baseDir);

/// Reads AdaptParams from node parameters (max_bend, bend_multiplier, prune, redistribute,
/// recheck_all, return_to_vertical, light_direction); absent keys keep the defaults.
AdaptParams adaptParamsFromValue(const sylva::Value& params);

/// Registers the `adapt` node type: one input (a skeleton), parameters as
/// adaptParamsFromValue plus `obstacles` (array of obstacle entries, files relative to the
/// species file) and the tree's placement `position` [x,y,z] m, `rotation` (degrees about Y)
/// and `scale`. Output: the adapted skeleton; stats adapt_*; timing "adapt".
void registerAdaptNode(graph::NodeRegistry& registry);

} // namespace sylva::env
