#pragma once

#include "engine/graph/graph.h"

namespace sylva::nodes {

/// Registers `lsystem`: grammar (inline text) or grammar_file → derivation → turtle skeleton.
/// Parameters and their ranges: the type's ParamSpecs (`sylva-cli nodes lsystem`).
void registerLsystemNode(graph::NodeRegistry& registry);

} // namespace sylva::nodes
