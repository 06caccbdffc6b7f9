// The performance gate's cases for the engine and the document (issue #41, ctest label `perf`;
// the harness, how a figure is made and compared: perfharness.h): `perf_gate <case> [options]`.
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include <QString>
#include <unistd.h>

#include "document/project.h"
#include "document/projectexport.h"
#include "document/scenebuild.h"
#include "document/speciesfile.h"
#include "engine/export/treeexport.h"
#include "engine/forest/forestbuild.h"
#include "engine/graph/graph.h"
#include "engine/growth/envelope.h"
#include "engine/growth/spacecolonization.h"
#include "engine/lsystem/derivation.h"
#include "engine/lsystem/grammar.h"
#include "engine/mesh/mesh.h"
#include "engine/nodes/meshnodes.h"
#include "engine/skeleton/skeleton.h"
#include "engine/util/memorypolicy.h"
#include "perfharness.h"

using namespace sylva;
using perf::Case;

namespace {

QString source(const char* relative) {
    return QString::fromStdString((std::filesystem::path(SYLVA_SOURCE_DIR) / relative).string());
}

Case speciesCase(const char* preset, std::uint64_t seed, bool perInternode) {
    auto g = std::make_shared<graph::SpeciesGraph>();
    Case c;
    c.prepare = [g, preset] {
        *g = doc::loadSpecies(source((std::string("presets/") + preset).c_str()));
    };
    c.run = [g, seed, perInternode]() -> std::size_t {
        graph::Evaluator e(*g); // fresh: no cached node results, as `sylva-cli tree` grows it
        const graph::NodeOutput& out = e.evaluate(seed);
        perf::sink(out.mesh->triangleCount());
        return perInternode && out.skeleton ? out.skeleton->size() : 0;
    };
    return c;
}

Case forestCase(const char* project) {
    auto scene = std::make_shared<forest::ForestScene>();
    Case c;
    c.reps = 5;
    c.prepare = [scene, project] {
        *scene = doc::makeForestScene(doc::loadProject(source(project)));
    };
    c.run = [scene]() -> std::size_t {
        const std::filesystem::path out =
            std::filesystem::temp_directory_path() /
            ("sylva-perf-gate-" + std::to_string(::getpid()) + ".obj");
        {
            // As `sylva-cli forest f.obj` writes it: compact OBJ, the camera LOD, instancing.
            exporter::TreeExporter exporter(out, exporter::ObjChoices{false, true});
            forest::ForestOptions options;
            options.meshInstances = !exporter.writesInstances();
            options.onVariants = [&](const std::vector<forest::ForestVariant>& variants) {
                std::vector<exporter::ExportVariant> v;
                for (const forest::ForestVariant& variant : variants)
                    v.push_back({variant.name, variant.mesh, variant.species, variant.index});
                exporter.addVariants(v);
            };
            forest::buildForest(*scene, options, [&](const std::vector<forest::ForestTree>& batch) {
                std::vector<exporter::ExportTree> trees;
                for (const forest::ForestTree& t : batch)
                    trees.push_back({t.name, t.mesh, t.instance.position, t.instance.rotation,
                                     t.instance.scale * t.instance.growth, t.variant, t.instance.id,
                                     t.instance.species});
                exporter.add(trees);
            });
            exporter.commit();
        }
        std::error_code ec;
        std::filesystem::remove(out, ec);
        std::filesystem::remove(std::filesystem::path(out).replace_extension(".mtl"), ec);
        std::filesystem::remove_all(out.parent_path() / "textures", ec);
        return 0;
    };
    return c;
}

// As `sylva-cli forest <project> -o <dir>/forest.usda` writes it (doc::exportProject, the CLI's
// and the editor's one front door): the variants grown, the trees placed, adapted and meshed,
// a PointInstancer per species and the unique trees' meshes written.
Case usdCase(const char* project) {
    auto loaded = std::make_shared<doc::Project>();
    Case c;
    c.reps = 3;
    c.warm = false;
    c.prepare = [loaded, project] { *loaded = doc::loadProject(source(project)); };
    c.run = [loaded]() -> std::size_t {
        const std::filesystem::path dir = std::filesystem::temp_directory_path() /
                                          ("sylva-perf-gate-usd-" + std::to_string(::getpid()));
        doc::ExportRequest request;
        request.path = dir / "forest.usda";
        const doc::ExportReport report = doc::exportProject(*loaded, request);
        perf::sink(report.stats.trees + report.written);
        std::error_code ec;
        std::filesystem::remove_all(dir, ec);
        return 0;
    };
    return c;
}

std::map<std::string, Case> cases() {
    std::map<std::string, Case> all;
    Case oak = speciesCase("english-oak.json", 2, false);
    oak.what = "English oak (presets/english-oak.json, seed 2) grown and meshed, warm, 1 thread";
    oak.unit = "tree";
    oak.reps = 15;
    all["oak"] = oak;

    Case so = speciesCase("so-broadleaf.json", 1, true);
    so.what = "self-organizing broadleaf (presets/so-broadleaf.json) grown and meshed, per "
              "internode, 1 thread";
    so.unit = "internode";
    so.reps = 9;
    all["so-broadleaf"] = so;

    Case sc;
    auto points = std::make_shared<std::vector<glm::vec3>>();
    sc.what = "space colonization of 10,000 attraction points in a 4.5 m sphere (the "
              "reference's round crown), 1 thread";
    sc.unit = "tree";
    sc.reps = 15;
    sc.prepare = [points] { *points = growth::Envelope::sphere({0, 6, 0}, 4.5f).sample(10000, 7); };
    sc.run = [points]() -> std::size_t {
        growth::ColonizationParams p;
        p.trunkHeight = 2.0f;
        const growth::ColonizationResult r = growth::colonize(*points, p, nullptr);
        perf::sink(r.skeleton.size());
        return 0;
    };
    all["spacecol"] = sc;

    Case ls;
    ls.what = "L-system expansion: F -> F[+F]F[-F]F 8 generations (fast path) and a parametric "
              "grammar with conditions 11 generations (general path)";
    ls.unit = "expansion";
    ls.reps = 15;
    auto grammars = std::make_shared<std::vector<lsys::Grammar>>();
    ls.prepare = [grammars] {
        grammars->push_back(lsys::parseGrammar("axiom: F\nF -> F[+F]F[-F]F\n"));
        grammars->push_back(
            lsys::parseGrammar("define: r = 0.9\naxiom: A(1, 0.2)\n"
                               "A(l, w) : l > 0.01 -> !(w)F(l)[&(30)A(l*r, w*0.7)]"
                               "/(137.5)[&(30)A(l*r, w*0.7)]/(137.5)A(l*r, w*0.7)\n"));
    };
    ls.run = [grammars]() -> std::size_t {
        lsys::DeriveOptions o;
        o.generations = 8;
        perf::sink(lsys::derive((*grammars)[0], o).size());
        o.generations = 11;
        perf::sink(lsys::derive((*grammars)[1], o).size());
        return 0;
    };
    all["lsystem"] = ls;

    Case f1000 = forestCase("resources/demo/bench-1000.sylva");
    f1000.what = "1,000-tree forest (resources/demo/bench-1000.sylva) to a compact OBJ with "
                 "the camera LOD, 1 thread";
    f1000.unit = "forest";
    all["forest-1000"] = f1000;

    Case library = forestCase("resources/demo/library.sylva");
    library.what = "library.sylva (12 hand-placed trees) to a compact OBJ, 1 thread";
    library.unit = "forest";
    all["library"] = library;

    Case usd = usdCase("resources/demo/bench-10000.sylva");
    usd.what = "10,000-tree library forest (resources/demo/bench-10000.sylva) to USD (.usda), as "
               "sylva-cli forest writes it, 1 thread";
    usd.unit = "forest";
    all["usd-10000"] = usd;
    return all;
}

} // namespace

int main(int argc, char** argv) {
    keepFreedMemory();
    graph::registerBuiltinNodeTypes();
    return perf::runGate(argc, argv, cases());
}
