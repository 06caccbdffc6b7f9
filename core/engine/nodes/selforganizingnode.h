#pragma once

#include "engine/graph/graph.h"
#include "engine/growth/selforganizing.h"

namespace sylva::growth {

/// Reads the self-organizing parameters from a node's parameter object (snake_case keys, the
/// defaults of SelfOrganizingParams for absent ones) and validates them.
/// \throw InvalidInput for a wrong type, an unknown enum string or a value out of range.
SelfOrganizingParams selfOrganizingParamsFrom(const sylva::Value& params);

/// The parameter names the `self_organizing` node understands (also valid in a stand's tree).
const std::vector<std::string>& selfOrganizingParamNames();

/// Registers the `self_organizing` node type: no inputs; output skeleton, stats `internodes`,
/// `cycles`, `shed`, `nodes`, `leaves`, timing `grow`. Uses NodeContext::seed when the caller
/// overrides the seed, else the `seed` parameter.
void registerSelfOrganizingNode(graph::NodeRegistry& registry);

} // namespace sylva::growth
