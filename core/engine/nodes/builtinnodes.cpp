// Registers the engine's node types. Each node folder file provides a register function; this
// file is the one place that knows them all, so adding a node type is one line here.
#include "engine/nodes/builtinnodes.h"

#include <mutex>

#include "engine/nodes/adaptnode.h"
#include "engine/nodes/lsystemnode.h"
#include "engine/nodes/meshnodes.h"
#include "engine/nodes/selforganizingnode.h"
#include "engine/nodes/spacecolonizationnode.h"

namespace sylva::graph {

void registerBuiltinNodeTypes() {
    static std::once_flag once;
    std::call_once(once, [] {
        NodeRegistry& registry = NodeRegistry::instance();
        nodes::registerLsystemNode(registry);
        mesh::registerMeshNodes(registry);
        env::registerAdaptNode(registry);
        growth::registerSelfOrganizingNode(registry);
        growth::registerSpaceColonizationNode(registry);
    });
}

} // namespace sylva::graph

namespace sylva::nodes {

graph::SpeciesGraph grammarSpecies(const std::string& grammarFile) {
    graph::SpeciesGraph g;
    graph::NodeDesc grow{"grow", "lsystem", Value::Object{{"grammar_file", grammarFile}}, {}};
    graph::NodeDesc mesh{"mesh", "tube_mesh", Value::Object{}, {"grow"}};
    g.nodes = {grow, mesh};
    g.output = "mesh";
    return g;
}

} // namespace sylva::nodes
