// sylva.Species, sylva.GrownTree, sylva.Skeleton, sylva.Mesh: one species grown on its own,
// as `sylva-cli tree` grows it.
#include <filesystem>
#include <map>
#include <mutex>
#include <optional>

#include <pybind11/stl.h>

#include <QString>

#include "convert.h"
#include "project.h"
#include "types.h"

#include "document/speciesfile.h"
#include "engine/export/lodchainexport.h"
#include "engine/export/treeexport.h"
#include "engine/export/windexport.h"
#include "engine/graph/graph.h"
#include "engine/mesh/lodchain.h"
#include "engine/nodes/meshnodes.h"
#include "engine/util/error.h"

namespace sylva::python {

namespace {

/// A species with its evaluator (whose per-node cache makes a regrow after one parameter
/// change cheap). Python threads may share one: growth takes the lock with the GIL released.
struct Species {
    std::shared_ptr<graph::Evaluator> evaluator;
    std::shared_ptr<std::mutex> lock = std::make_shared<std::mutex>();

    const graph::SpeciesGraph& graph() const { return evaluator->graph(); }
};

Species makeSpecies(graph::SpeciesGraph g) {
    graph::registerBuiltinNodeTypes();
    Species s{std::make_shared<graph::Evaluator>(std::move(g))};
    s.evaluator->validate();
    return s;
}

/// "node.param" → (node, param), split at the first dot as `sylva-cli tree --set` does.
std::pair<std::string, std::string> splitParam(const std::string& path) {
    const auto dot = path.find('.');
    if (dot == std::string::npos || dot == 0 || dot + 1 == path.size())
        throw InvalidInput("a parameter is named node.param, got '" + path + "'");
    return {path.substr(0, dot), path.substr(dot + 1)};
}

struct GrownTree {
    std::string species;
    std::optional<std::uint64_t> seed;
    std::shared_ptr<const skel::Skeleton> skeleton;
    std::shared_ptr<const mesh::Mesh> mesh;
    std::map<std::string, double> stats, timingsMs;
    graph::SpeciesTraits traits;
    /// The graph it grew from (as it was then), so that a wind export of a tree grown without
    /// wind data can grow the same tree again with it (generation is deterministic).
    std::shared_ptr<const graph::SpeciesGraph> graph;
};

/// Sets wind_data (per-vertex node ids and wind channels, docs/wind.md) on every tube_mesh.
void enableWindData(graph::Evaluator& evaluator) {
    for (const graph::NodeDesc& node : evaluator.graph().nodes)
        if (graph::roleOf(node.type) == graph::NodeRole::Mesher)
            evaluator.setParam(node.id, "wind_data", sylva::Value(true));
}

/// The tree's mesh with wind data: its own when it has node ids, else the same tree grown again
/// from its graph with wind_data on.
std::shared_ptr<const mesh::Mesh> windMesh(const GrownTree& t, Progress& progress) {
    if (t.mesh && t.mesh->node.size() == t.mesh->positions.size() && !t.mesh->positions.empty())
        return t.mesh;
    if (!t.graph) throw InvalidInput("this tree has no species graph to grow its wind data from");
    graph::Evaluator e(*t.graph);
    enableWindData(e);
    const graph::NodeOutput& out = t.seed ? e.evaluate(*t.seed, progress) : e.evaluate(progress);
    if (!out.mesh) throw InvalidInput("the species produces no mesh");
    return out.mesh;
}

py::dict nodeDict(const graph::NodeDesc& n) {
    py::dict d;
    d["id"] = n.id;
    d["type"] = n.type;
    d["inputs"] = n.inputs;
    d["params"] = fromValue(n.params);
    return d;
}

py::object speciesDict(const graph::SpeciesGraph& g) {
    const QByteArray json = doc::serializeSpecies(g);
    return fromValue(sylva::Value::parseJson(json.toStdString()));
}

Species loadSpeciesFrom(const py::object& source, const py::object& baseDir) {
    if (py::isinstance<py::dict>(source)) {
        const std::string base =
            baseDir.is_none() ? std::filesystem::current_path().string() : toPath(baseDir);
        return makeSpecies(doc::speciesFromValue(toValue(source), QStringLiteral("<dict>"),
                                                 QString::fromStdString(base)));
    }
    if (py::isinstance<Species>(source)) return source.cast<Species>();
    return makeSpecies(doc::loadSpecies(QString::fromStdString(toPath(source))));
}

} // namespace

exporter::WindExportOptions windExportOptions(const py::object& direction,
                                              const py::object& strength,
                                              const py::object& gustiness,
                                              const py::object& frequency, const py::object& bones,
                                              const py::object& clipLength, const py::object& fps,
                                              exporter::WindExportOptions base) {
    exporter::WindExportOptions o = base;
    if (!direction.is_none()) o.wind.direction = toVec3(direction, "direction");
    if (!strength.is_none()) o.wind.strength = strength.cast<float>();
    if (!gustiness.is_none()) o.wind.gustiness = gustiness.cast<float>();
    if (!frequency.is_none()) o.wind.frequency = frequency.cast<float>();
    if (!clipLength.is_none()) o.wind.period = clipLength.cast<float>();
    if (!bones.is_none()) o.rig.maxBones = bones.cast<int>();
    if (!fps.is_none()) o.rig.fps = fps.cast<float>();
    wind::validate(o.wind);
    wind::validate(o.rig);
    return o;
}

/// Also used by forest.cpp: a species argument (path, dict or Species) as a graph.
graph::SpeciesGraph speciesGraphFrom(const py::object& source) {
    return loadSpeciesFrom(source, py::none()).graph();
}

py::dict metricsDict(const forest::TreeMetrics& m) {
    py::dict d;
    d["height_m"] = m.heightM;
    d["dbh_m"] = m.dbhM;
    d["crown_width_m"] = m.crownWidthM;
    d["wood_volume_m3"] = m.woodVolumeM3;
    d["dry_biomass_kg"] = m.dryBiomassKg;
    d["carbon_kg"] = m.carbonKg;
    d["co2_kg"] = m.co2Kg;
    d["chave_agb_kg"] = m.chaveAgbKg;
    return d;
}

void bindSpecies(py::module_& m) {
    py::class_<MeshRef>(m, "Mesh",
                        "A tree's triangle mesh in the tree's own frame (metres, Y up). Each "
                        "property returns a new numpy array.")
        .def_property_readonly("positions",
                               [](const MeshRef& r) {
                                   return makeArray(&r.mesh->positions.data()->x,
                                                    r.mesh->positions.size(), 3);
                               })
        .def_property_readonly("normals",
                               [](const MeshRef& r) {
                                   return makeArray(&r.mesh->normals.data()->x,
                                                    r.mesh->normals.size(), 3);
                               })
        .def_property_readonly("uvs",
                               [](const MeshRef& r) {
                                   return makeArray(&r.mesh->uvs.data()->x, r.mesh->uvs.size(), 2);
                               })
        .def_property_readonly(
            "colors",
            [](const MeshRef& r) {
                return makeArray(&r.mesh->colors.data()->x, r.mesh->colors.size(), 4);
            },
            "per-vertex RGBA multipliers of the material colour (uint8, linear, 255 = 1: the "
            "leaf cards' tint, white on bark); empty (0 x 4) when the species sets no "
            "leaf_*_variation)")
        .def_property_readonly("indices",
                               [](const MeshRef& r) {
                                   return makeArray(r.mesh->indices.data(),
                                                    r.mesh->indices.size() / 3, 3);
                               })
        .def_property_readonly(
            "materials",
            [](const MeshRef& r) {
                std::vector<std::string> names;
                for (const mesh::Submesh& s : r.mesh->submeshes)
                    if (std::find(names.begin(), names.end(), s.material) == names.end())
                        names.push_back(s.material);
                if (r.mesh->submeshes.empty() && !r.mesh->indices.empty()) names.push_back("bark");
                return names;
            },
            "material names in the order they first appear (\"bark\", \"leaf\")")
        .def(
            "indices_of",
            [](const MeshRef& r, const std::string& material) {
                const mesh::Mesh& me = *r.mesh;
                std::vector<std::uint32_t> out;
                if (me.submeshes.empty()) {
                    if (material == "bark") out = me.indices;
                } else {
                    for (const mesh::Submesh& s : me.submeshes)
                        if (s.material == material)
                            out.insert(out.end(), me.indices.begin() + s.firstIndex,
                                       me.indices.begin() + s.firstIndex + s.indexCount);
                }
                return makeArray(out.data(), out.size() / 3, 3);
            },
            py::arg("material"), "the triangles of one material, shape (T, 3)")
        .def_property_readonly(
            "submeshes",
            [](const MeshRef& r) {
                py::list l;
                for (const mesh::Submesh& s : r.mesh->submeshes)
                    l.append(py::make_tuple(s.material, s.firstIndex / 3, s.indexCount / 3));
                return l;
            },
            "(material, first triangle, triangle count) runs covering indices in order")
        .def_property_readonly("vertex_count",
                               [](const MeshRef& r) { return r.mesh->vertexCount(); })
        .def_property_readonly("triangle_count",
                               [](const MeshRef& r) { return r.mesh->triangleCount(); })
        .def("__repr__", [](const MeshRef& r) {
            return "<sylva.Mesh " + std::to_string(r.mesh->vertexCount()) + " vertices, " +
                   std::to_string(r.mesh->triangleCount()) + " triangles>";
        });

    py::class_<SkeletonRef>(m, "Skeleton",
                            "A tree's skeleton: nodes stored parents before children (parents[i] "
                            "< i, -1 for a root), metres, Y up.")
        .def("__len__", [](const SkeletonRef& r) { return r.skeleton->size(); })
        .def_property_readonly("positions",
                               [](const SkeletonRef& r) {
                                   return makeArray(&r.skeleton->position.data()->x,
                                                    r.skeleton->size(), 3);
                               })
        .def_property_readonly("parents",
                               [](const SkeletonRef& r) {
                                   return makeArray(r.skeleton->parent.data(),
                                                    r.skeleton->parent.size(), 0);
                               })
        .def_property_readonly("radii",
                               [](const SkeletonRef& r) {
                                   return makeArray(r.skeleton->radius.data(),
                                                    r.skeleton->radius.size(), 0);
                               })
        .def_property_readonly("orders",
                               [](const SkeletonRef& r) {
                                   return makeArray(r.skeleton->order.data(),
                                                    r.skeleton->order.size(), 0);
                               })
        .def_property_readonly(
            "flags",
            [](const SkeletonRef& r) {
                return makeArray(r.skeleton->flags.data(), r.skeleton->flags.size(), 0);
            },
            "bits: 1 hidden (pruned), 2 tip, 4 fork, 8 starved")
        .def_property_readonly(
            "leaf_positions",
            [](const SkeletonRef& r) {
                std::vector<float> p;
                for (const skel::Leaf& l : r.skeleton->leaves)
                    p.insert(p.end(), {l.position.x, l.position.y, l.position.z});
                return makeArray(p.data(), r.skeleton->leaves.size(), 3);
            })
        .def("__repr__", [](const SkeletonRef& r) {
            return "<sylva.Skeleton " + std::to_string(r.skeleton->size()) + " nodes>";
        });

    py::class_<GrownTree>(m, "GrownTree", "One tree grown from a species and a seed.")
        .def_readonly("species", &GrownTree::species)
        .def_readonly("seed", &GrownTree::seed)
        .def_property_readonly("skeleton",
                               [](const GrownTree& t) -> py::object {
                                   if (!t.skeleton) return py::none();
                                   return py::cast(SkeletonRef{t.skeleton});
                               })
        .def_property_readonly("mesh", [](const GrownTree& t) { return MeshRef{t.mesh}; })
        .def_readonly("stats", &GrownTree::stats,
                      "counts from the generators (symbols, segments, leaves, ...)")
        .def_readonly("timings_ms", &GrownTree::timingsMs)
        .def(
            "metrics",
            [](const GrownTree& t, double scale) {
                if (!t.skeleton) throw InvalidInput("this tree has no skeleton");
                return metricsDict(forest::measureTree(
                    *t.skeleton, {t.traits.woodDensity, t.traits.carbonFraction}, scale));
            },
            py::arg("scale") = 1.0,
            "height, DBH, crown width, wood volume, dry biomass, carbon and CO2 (kg)")
        .def(
            "export",
            [](const GrownTree& t, const py::object& path, bool compact, bool fsync, bool wind,
               const py::object& direction, const py::object& strength, const py::object& gustiness,
               const py::object& frequency, const py::object& bones, const py::object& clipLength,
               const py::object& fps) {
                const std::string p = toPath(path);
                const bool rig = exporter::formatFor(p).wind == exporter::WindSupport::Rig;
                std::optional<exporter::WindExportOptions> windOptions;
                if (wind)
                    windOptions = windExportOptions(direction, strength, gustiness, frequency,
                                                    bones, clipLength, fps);
                else if (!direction.is_none() || !strength.is_none() || !gustiness.is_none() ||
                         !frequency.is_none() || !bones.is_none() || !clipLength.is_none() ||
                         !fps.is_none())
                    throw InvalidInput("wind settings need wind=True");
                std::vector<std::string> written;
                {
                    py::gil_scoped_release release;
                    const std::string name = exporter::objectNameFor(t.species);
                    // As `sylva-cli tree --wind`: .glb/.gltf/.fbx through the wind exporter (rig,
                    // clip, _WIND* data); an OBJ as without wind plus its .wind.csv table.
                    if (!wind || !rig) {
                        exporter::ForestWriterOptions options;
                        options.species = {name};
                        options.fsync = fsync;
                        options.compact = compact;
                        exporter::TreeExporter exporter(p, options);
                        exporter.add({exporter::ExportTree{name, t.mesh}});
                        for (const auto& f : exporter.commit())
                            written.push_back(f.string());
                    }
                    if (wind) {
                        if (!t.skeleton) throw InvalidInput("a wind export needs the skeleton");
                        exporter::WindExporter windExporter(p, *windOptions);
                        windExporter.add({{name, windMesh(t, noProgress()), t.skeleton}});
                        for (const auto& f : windExporter.commit())
                            written.push_back(f.string());
                    }
                }
                return written;
            },
            py::arg("path"), py::arg("compact") = false, py::arg("fsync") = false,
            py::arg("wind") = false, py::arg("direction") = py::none(),
            py::arg("strength") = py::none(), py::arg("gustiness") = py::none(),
            py::arg("frequency") = py::none(), py::arg("bones") = py::none(),
            py::arg("clip_length") = py::none(), py::arg("fps") = py::none(),
            withFormats(
                "writes the tree as `sylva-cli tree` does (by extension: {formats}; an OBJ with "
                "its "
                ".mtl and textures); returns the paths written. wind=True writes it as "
                "`sylva-cli tree --wind`: a rig of at most `bones` bones (default 64), skin "
                "weights, "
                "a looping clip 'wind' of `clip_length` s (default 4) at `fps` (30), the _WIND* "
                "vertex data, Unreal's Pivot Painter 2 textures and <stem>.wind.csv; direction (x, "
                "y, "
                "z), strength (0..2), gustiness "
                "(0..1) and frequency (Hz, 0.05..5) are the wind's (docs/wind.md)"))
        .def("__repr__", [](const GrownTree& t) {
            return "<sylva.GrownTree " + t.species + ": " +
                   std::to_string(t.mesh ? t.mesh->vertexCount() : 0) + " vertices>";
        });

    py::class_<Species>(m, "Species",
                        "A species graph (nodes with parameters) ready to grow trees. Parameters "
                        "are checked when set: unknown nodes and parameters raise ValueError.")
        .def_property_readonly("name", [](const Species& s) { return s.graph().name; })
        .def_property_readonly("output", [](const Species& s) { return s.graph().output; })
        .def_property_readonly("source", [](const Species& s) { return s.graph().sourceFile; })
        .def_property_readonly("node_ids",
                               [](const Species& s) {
                                   std::vector<std::string> ids;
                                   for (const graph::NodeDesc& n : s.graph().nodes)
                                       ids.push_back(n.id);
                                   return ids;
                               })
        .def_property_readonly("nodes",
                               [](const Species& s) {
                                   py::list l;
                                   for (const graph::NodeDesc& n : s.graph().nodes)
                                       l.append(nodeDict(n));
                                   return l;
                               })
        .def_property_readonly("traits",
                               [](const Species& s) {
                                   py::dict d;
                                   d["wood_density"] = s.graph().traits.woodDensity;
                                   d["carbon_fraction"] = s.graph().traits.carbonFraction;
                                   d["crown_radius"] = s.graph().traits.crownRadius;
                                   return d;
                               })
        .def(
            "get_param",
            [](const Species& s, const std::string& path) {
                const auto [node, key] = splitParam(path);
                const graph::NodeDesc* n = s.graph().findNode(node);
                if (!n)
                    throw InvalidInput("no node '" + node + "' in species '" + s.graph().name +
                                       "'");
                const sylva::Value* v = n->params.isObject() ? n->params.find(key) : nullptr;
                return v ? fromValue(*v) : py::object(py::none());
            },
            py::arg("path"), "a parameter's value by \"node.param\" (None when unset)")
        .def(
            "set_param",
            [](Species& s, const std::string& path, const py::object& value) {
                const auto [node, key] = splitParam(path);
                std::lock_guard lock(*s.lock);
                s.evaluator->setParam(node, key, toValue(value));
            },
            py::arg("path"), py::arg("value"),
            "sets \"node.param\" (as `sylva-cli tree --set`); ValueError for an unknown node or "
            "parameter. Values out of range raise ValueError when the tree grows.")
        .def(
            "params",
            [](const Species& s, const std::string& node) {
                const graph::NodeDesc* n = s.graph().findNode(node);
                if (!n)
                    throw InvalidInput("no node '" + node + "' in species '" + s.graph().name +
                                       "'");
                return fromValue(n->params);
            },
            py::arg("node"))
        .def(
            "to_dict", [](const Species& s) { return speciesDict(s.graph()); },
            "the species file's JSON as a dict")
        .def("copy", [](const Species& s) { return makeSpecies(s.graph()); })
        .def(
            "grow",
            [](Species& s, std::optional<std::uint64_t> seed, const py::object& progress,
               const py::object& season, bool wind) {
                PyProgress p(progress);
                GrownTree t;
                t.species = s.graph().name;
                t.seed = seed;
                t.traits = s.graph().traits;
                const std::string seasonName = seasonFrom(season);
                withoutGil(p, [&] {
                    std::lock_guard lock(*s.lock);
                    // A season is the meshing node's parameter for this growth only (as
                    // `sylva-cli tree --season`); the species keeps its own afterwards.
                    std::optional<graph::SpeciesGraph> own;
                    if (!seasonName.empty()) {
                        const graph::NodeDesc* mesh = graph::meshOutput(s.graph());
                        if (!mesh)
                            throw InvalidInput(
                                "season needs a species whose output node is a tube_mesh");
                        own = s.evaluator->graph();
                        s.evaluator->setParam(mesh->id, "season", sylva::Value(seasonName));
                    }
                    struct Restore {
                        Species& species;
                        std::optional<graph::SpeciesGraph>& graph;
                        ~Restore() {
                            if (graph) species.evaluator->setGraph(std::move(*graph));
                        }
                    } restore{s, own};
                    t.graph = s.evaluator->sharedGraph(); // shared until the species changes
                    // wind=True grows with wind data for this tree only: the species' graph
                    // (and its cached results) comes back afterwards.
                    std::optional<graph::Evaluator> windy;
                    if (wind) {
                        windy.emplace(s.graph());
                        enableWindData(*windy);
                    }
                    graph::Evaluator& e = windy ? *windy : *s.evaluator;
                    const graph::NodeOutput& out = seed ? e.evaluate(*seed, p) : e.evaluate(p);
                    if (!out.mesh)
                        throw InvalidInput("the species' output node '" + s.graph().output +
                                           "' produces no mesh; end the graph with a tube_mesh "
                                           "node");
                    t.skeleton = out.skeleton;
                    t.mesh = out.mesh;
                    t.stats = out.stats;
                    t.timingsMs = out.timingsMs;
                });
                return t;
            },
            py::arg("seed") = py::none(), py::arg("progress") = py::none(),
            py::arg("season") = py::none(), py::arg("wind") = false,
            "grows one tree (as `sylva-cli tree [--seed S] [--season NAME] [--wind]`), the GIL "
            "released; without a seed the generators use their own (a grammar's `seed:`); season: "
            "'spring', 'summer', 'autumn' or 'winter' (None: the species' own); wind=True grows it "
            "with the per-vertex wind data (as `--wind`), so that export(wind=True) need not grow "
            "it again")
        .def(
            "write_lods",
            [](Species& s, const py::object& folderArg, std::optional<std::uint64_t> seed,
               const std::vector<double>& budgets, int impostorGrid, int impostorCell,
               const py::object& progress) {
                const std::string folder =
                    py::module_::import("os").attr("fspath")(folderArg).cast<std::string>();
                PyProgress p(progress);
                mesh::LodChainSettings chainSettings;
                chainSettings.budgets = budgets;
                chainSettings.impostorSettings.grid = impostorGrid;
                chainSettings.impostorSettings.cellPixels = impostorCell;
                mesh::validateLodChain(chainSettings);
                std::string description;
                withoutGil(p, [&] {
                    std::lock_guard lock(*s.lock);
                    const graph::SpeciesGraph& g = s.graph();
                    const graph::NodeDesc* out = graph::meshOutput(g);
                    if (!out)
                        throw InvalidInput("write_lods needs a species whose output is a "
                                           "tube_mesh node");
                    const graph::NodeOutput& grown = s.evaluator->evaluateNode(
                        g.skeletonSource(), seed.has_value(), seed.value_or(0), p);
                    if (!grown.skeleton) throw InvalidInput("the species produces no skeleton");
                    const mesh::TreeMeshSettings settings =
                        mesh::treeMeshSettingsFromParams(out->params, 0, g.baseDir);
                    exporter::GameLodOptions options;
                    if (const auto res = exporter::resourcesDir(); !res.empty())
                        options.shippedTextures = res / "textures";
                    std::string stem = std::filesystem::path(g.sourceFile).stem().string();
                    if (stem.empty()) stem = g.name;
                    description = exporter::writeTreeLodChain(folder, stem, *grown.skeleton,
                                                              settings, chainSettings, options, p)
                                      .description;
                });
                return py::module_::import("json").attr("loads")(description);
            },
            py::arg("folder"), py::arg("seed") = py::none(),
            py::arg("budgets") = std::vector<double>{1.0, 0.35, 0.12, 0.04},
            py::arg("impostor_grid") = 8, py::arg("impostor_cell") = 256,
            py::arg("progress") = py::none(),
            "writes the species' game LOD chain into folder as `sylva-cli lods` does (levels by "
            "triangle budget, the impostor's maps, glTF with MSFT_lod, FBX, USD, OBJ; "
            "docs/lods.md) "
            "and returns its description (the <species>_lods.json content)")
        .def("__repr__", [](const Species& s) {
            return "<sylva.Species '" + s.graph().name + "' " +
                   std::to_string(s.graph().nodes.size()) + " nodes>";
        });

    m.def("load_species", &loadSpeciesFrom, py::arg("source"), py::arg("base_dir") = py::none(),
          "a species from a file (species .json, or a bare grammar .lsys) or from a dict in the "
          "species file's form; relative file parameters of a dict resolve against base_dir "
          "(default: the working directory)");
    m.def(
        "grow",
        [](const py::object& species, std::optional<std::uint64_t> seed, const py::object& progress,
           const py::object& season) {
            Species s = loadSpeciesFrom(species, py::none());
            return s.evaluator ? py::cast(s).attr("grow")(seed, progress, season)
                               : py::object(py::none());
        },
        py::arg("species"), py::arg("seed") = py::none(), py::arg("progress") = py::none(),
        py::arg("season") = py::none(), "load_species(species).grow(seed, season=season)");
    m.def(
        "node_types",
        [] {
            graph::registerBuiltinNodeTypes();
            py::dict d;
            const graph::NodeRegistry& r = graph::NodeRegistry::instance();
            for (const std::string& name : r.names())
                d[py::str(name)] = r.find(name)->knownParams;
            return d;
        },
        "node type → the parameter names it accepts");
}

} // namespace sylva::python
