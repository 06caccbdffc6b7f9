#pragma once

#include <filesystem>

#include <glm/glm.hpp>

#include "engine/graph/graph.h"

namespace sylva::growth {

/// Registers the `space_colonization` node type: 0 inputs (a trunk of trunk_height from root)
/// or 1 input whose skeleton is the initial skeleton. Parameters and ranges are listed in
/// docs/space-colonization.md. Output: the skeleton; stats segments, nodes, attractors,
/// attractors_killed, attractors_left, iterations, stop_reason (0 no points left, 1 nothing in
/// reach, 2 iteration cap), zero_average_fixes, oscillation_fixes; timings "attractors" (sampling)
/// and "grow" (colonization and pipe model), milliseconds.
void registerSpaceColonizationNode(graph::NodeRegistry& registry);

/// Builds the attraction-point envelope from the node's `envelope` object; mesh files resolve
/// through \p ctx. Exposed for tests and the editor's envelope preview.
class Envelope;
Envelope envelopeFromParams(const sylva::Value& envelope, const graph::NodeContext& ctx);

/// A mesh envelope from \p file, scaled by \p scale about the origin and then moved by \p offset:
/// read as obstacle meshes are (env::loadObstacleMesh: the file checks Debian's Assimp needs, OBJ
/// without its line and point elements, the triangle limit), since a species file from elsewhere
/// names it. \throw IoError or InvalidInput naming the file.
Envelope loadEnvelopeMesh(const std::filesystem::path& file, float scale = 1.0f,
                          const glm::vec3& offset = glm::vec3(0.0f));

} // namespace sylva::growth
