#include "document/speciestree.h"

#include "document/speciesfile.h"
#include "engine/graph/graph.h"
#include "engine/nodes/meshnodes.h"
#include "engine/util/error.h"

namespace sylva::doc {

SpeciesTree growSpeciesTree(const QString& path, std::optional<std::uint64_t> seed,
                            Progress& progress) {
    graph::registerBuiltinNodeTypes();
    const graph::SpeciesGraph species = loadSpecies(path);
    const graph::NodeDesc* out = graph::meshOutput(species);
    if (!out) throw InvalidInput("a LOD chain needs a species whose output is a tube_mesh node");
    graph::Evaluator evaluator(species);
    const graph::NodeOutput& grown = evaluator.evaluateNode(
        species.skeletonSource(), seed.has_value(), seed.value_or(0), progress);
    if (!grown.skeleton) throw InvalidInput("the species produces no skeleton");
    return {grown.skeleton, mesh::treeMeshSettingsFromParams(out->params, 0, species.baseDir)};
}

} // namespace sylva::doc
