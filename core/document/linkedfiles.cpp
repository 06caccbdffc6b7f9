#include "document/linkedfiles.h"

#include "document/scenebuild.h"
#include "document/speciesfile.h"
#include "engine/graph/fileparams.h"
#include "engine/graph/graph.h"
#include "engine/lsystem/grammar.h"
#include "engine/lsystem/grammarcache.h"
#include "engine/util/error.h"

#include <filesystem>
#include <fstream>

namespace sylva::doc {

namespace {

void checkSpeciesGraph(const graph::SpeciesGraph& g, const std::string& species) {
    graph::registerBuiltinNodeTypes();
    graph::Evaluator(g).validate();
    for (const graph::NodeDesc& node : g.nodes) {
        const Value& p = node.params;
        if (!p.isObject()) continue;
        std::filesystem::path grammarFile; // read below: not opened again as a linked file
        if (const Value* text = p.find("grammar"); text && text->isString()) {
            lsys::parseGrammar(text->toString("grammar"),
                               g.sourceFile.empty() ? species : g.sourceFile);
        } else if (const Value* file = p.find("grammar_file"); file && file->isString()) {
            // Parsed through the cache the growth reads (lsys::parsedGrammarFile): a grammar
            // file is parsed once an open, not once to check and again to grow.
            grammarFile = g.baseDir / file->toString("grammar_file");
            try {
                lsys::parsedGrammarFile(grammarFile);
            } catch (const IoError&) {
                throw IoError("species '" + species + "': cannot read the linked file " +
                              grammarFile.string());
            }
        }
        Value params = p; // forEachFileIn walks a mutable value
        graph::forEachFileIn(params, [&](const Value& v) {
            if (v.toString("file").empty()) return;
            const std::filesystem::path path = g.baseDir / v.toString("file");
            if (path == grammarFile) return;
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
