#include "document/linkedfiles.h"

#include "document/scenebuild.h"
#include "document/speciesfile.h"
#include "engine/graph/fileparams.h"
#include "engine/graph/graph.h"
#include "engine/lsystem/grammar.h"
#include "engine/util/error.h"

#include <filesystem>
#include <fstream>
#include <sstream>

namespace sylva::doc {

namespace {

std::string readLinkedText(const std::filesystem::path& path, const std::string& species) {
    std::ifstream in(path, std::ios::binary);
    if (!in)
        throw IoError("species '" + species + "': cannot read the linked file " + path.string());
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
}

void checkSpeciesGraph(const graph::SpeciesGraph& g, const std::string& species) {
    graph::registerBuiltinNodeTypes();
    graph::Evaluator(g).validate();
    for (const graph::NodeDesc& node : g.nodes) {
        const Value& p = node.params;
        if (!p.isObject()) continue;
        if (const Value* text = p.find("grammar"); text && text->isString()) {
            lsys::parseGrammar(text->toString("grammar"),
                               g.sourceFile.empty() ? species : g.sourceFile);
        } else if (const Value* file = p.find("grammar_file"); file && file->isString()) {
            const std::filesystem::path path = g.baseDir / file->toString("grammar_file");
            lsys::parseGrammar(readLinkedText(path, species), path.string());
        }
        Value params = p; // forEachFileIn walks a mutable value
        graph::forEachFileIn(params, [&](const Value& v) {
            if (v.toString("file").empty()) return;
            const std::filesystem::path path = g.baseDir / v.toString("file");
            std::ifstream in(path, std::ios::binary);
            if (!in)
                throw IoError("species '" + species + "', node '" + node.id +
                              "': cannot read the linked file " + path.string());
        });
    }
}

} // namespace

void checkLinkedFiles(const Project& project) {
    for (const ProjectSpecies& ps : project.species) {
        const graph::SpeciesGraph g =
            ps.graph ? speciesFromGraph(ps.name, *ps.graph, ps.traits, project.baseDir)
                     : loadSpecies(project.resolve(ps.file));
        checkSpeciesGraph(g, ps.name);
    }
    // Loaded as the growth loads them, into the scene cache it reads: read once, not twice.
    if (const auto obstacles = obstacleSpecsOf(project); !obstacles.empty())
        env::loadObstacleScene(obstacles);
    for (const PlacementDomain& d : project.domains)
        if (d.shape == "terrain") env::loadObstacleScene({terrainSpecOf(project, d)});
}

} // namespace sylva::doc
