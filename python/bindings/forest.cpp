// sylva.Project, sylva.Forest, sylva.ForestTree: a forest built as `sylva-cli forest` builds
// it, with obstacles and a ground that may also come from arrays (a DCC tool's own meshes).
#include <algorithm>
#include <filesystem>
#include <map>
#include <optional>

#include <omp.h>
#include <pybind11/stl.h>

#include <QDir>
#include <QFileInfo>

#include "convert.h"
#include "project.h"
#include "types.h"

#include "document/filerefs.h"
#include "document/project.h"
#include "document/projectexport.h"
#include "document/projectsettings.h"
#include "document/scenebuild.h"
#include "document/speciesfile.h"
#include "engine/environment/obstaclemesh.h"
#include "engine/environment/obstaclescene.h"
#include "engine/export/treeexport.h"
#include "engine/export/windexport.h"
#include "engine/forest/forestbuild.h"
#include "engine/graph/graph.h"
#include "engine/placement/placement.h"
#include "engine/util/error.h"
#include "engine/wind/windmodel.h"

namespace sylva::python {

graph::SpeciesGraph speciesGraphFrom(const py::object& source); // species.cpp

namespace {

using Clock = std::chrono::steady_clock;
double msSince(Clock::time_point t) {
    return std::chrono::duration<double, std::milli>(Clock::now() - t).count();
}

struct ForestTreeRef {
    std::shared_ptr<const std::vector<forest::ForestTree>> all;
    std::size_t index = 0;
    std::string species;
    const forest::ForestTree& tree() const { return (*all)[index]; }
};

/// sylva.ForestVariant: one of a species' K variants that instanced trees share.
struct VariantRef {
    std::shared_ptr<const std::vector<forest::ForestVariant>> all;
    std::size_t index = 0;
    std::string species;
    const forest::ForestVariant& variant() const { return (*all)[index]; }
};

struct Forest {
    std::shared_ptr<const std::vector<forest::ForestTree>> trees;
    /// The variants the trees' ForestTree::variant indexes (written once by glTF).
    std::shared_ptr<const std::vector<forest::ForestVariant>> variants;
    std::vector<std::string> speciesNames;
    py::dict stats;
    /// Built with wind data (build_forest(wind=True)): node ids in the meshes, skeletons kept.
    bool windData = false;
    /// The project's wind when it was built (the defaults of export(wind=True)).
    std::optional<wind::WindSettings> projectWind;
};

struct BuildOptions {
    forest::ForestOptions options;
    std::optional<glm::vec3> camera;
};

BuildOptions buildOptions(const py::object& camera, bool lod, bool adapt, bool neighbours,
                          bool instancing, const py::object& tile, std::optional<int> threads) {
    BuildOptions b;
    b.options.instancing = instancing;
    b.options.useLod = lod;
    b.options.adapt = adapt;
    b.options.neighbours = neighbours;
    if (!camera.is_none()) b.camera = toVec3(camera, "camera");
    if (!tile.is_none()) {
        if (py::isinstance<py::str>(tile)) {
            std::tie(b.options.tile, b.options.tileCount) =
                placement::parseTileSpec(tile.cast<std::string>());
        } else {
            const auto t = tile.cast<std::pair<int, int>>();
            std::tie(b.options.tile, b.options.tileCount) =
                placement::parseTileSpec(std::to_string(t.first) + "/" + std::to_string(t.second));
        }
    }
    if (threads) {
        if (*threads < 1 || *threads > 1024)
            throw InvalidInput("threads must be between 1 and 1024, got " +
                               std::to_string(*threads));
        omp_set_num_threads(*threads);
    }
    return b;
}

py::dict statsDict(const forest::ForestStats& stats, const forest::ForestScene& s,
                   const forest::ForestOptions& o) {
    py::dict d;
    d["trees"] = stats.trees;
    d["trees_in_scene"] = stats.treesInScene;
    d["tile"] = o.tile + 1;
    d["tiles"] = o.tileCount;
    d["vertices"] = stats.vertices;
    d["triangles"] = stats.triangles;
    d["obstacle_triangles"] = s.obstacles ? s.obstacles->triangleCount() : 0;
    d["colliding_trees"] = stats.collidingTrees;
    d["pruned_nodes"] = stats.prunedNodes;
    d["instanced"] = stats.instanced;
    d["unique"] = stats.unique;
    d["variants"] = stats.variants;
    std::size_t missing = 0;
    py::list shortfalls;
    for (const placement::Shortfall& sf : stats.shortfalls) {
        missing += sf.requested - sf.placed;
        py::dict x;
        x["domain"] = sf.domain;
        x["species"] = s.species[sf.species].name;
        x["requested"] = sf.requested;
        x["placed"] = sf.placed;
        shortfalls.append(x);
    }
    d["shortfall"] = missing;
    d["shortfalls"] = shortfalls;
    d["branch_edits"] = stats.branchEdits;
    d["orphaned_edits"] = stats.orphanedEdits;
    d["warnings"] = stats.warnings;
    const forest::SceneMetrics& m = stats.metrics;
    py::dict metrics;
    metrics["trees"] = m.trees;
    metrics["mean_height_m"] = m.meanHeightM;
    metrics["mean_dbh_m"] = m.meanDbhM;
    metrics["mean_crown_width_m"] = m.meanCrownWidthM;
    metrics["wood_volume_m3"] = m.woodVolumeM3;
    metrics["dry_biomass_kg"] = m.dryBiomassKg;
    metrics["carbon_kg"] = m.carbonKg;
    metrics["co2_kg"] = m.co2Kg;
    metrics["chave_agb_kg"] = m.chaveAgbKg;
    d["metrics"] = metrics;
    d["co2_kg"] = m.co2Kg;
    d["timings_ms"] = stats.wallMs;
    d["cpu_ms"] = stats.cpuMs;
    return d;
}

void warnShortfalls(const forest::ForestStats& stats, const std::vector<std::string>& species) {
    for (const placement::Shortfall& sf : stats.shortfalls)
        PyErr_WarnEx(PyExc_UserWarning,
                     ("domain " + std::to_string(sf.domain + 1) + ": placed " +
                      std::to_string(sf.placed) + " of " + std::to_string(sf.requested) + " '" +
                      species[sf.species] + "' (no room left)")
                         .c_str(),
                     1);
}

void warnShortfalls(const forest::ForestStats& stats, const forest::ForestScene& s) {
    std::vector<std::string> species;
    for (const forest::SceneSpecies& sp : s.species)
        species.push_back(sp.name);
    warnShortfalls(stats, species);
}

/// Python's wind keywords (None: the project's setting) as the settings over a project's wind.
doc::WindOverride windOverrideFrom(const py::object& direction, const py::object& strength,
                                   const py::object& gustiness, const py::object& frequency,
                                   const py::object& bones, const py::object& clipLength,
                                   const py::object& fps) {
    auto number = [](const py::object& o) {
        return o.is_none() ? std::optional<float>() : std::optional<float>(o.cast<float>());
    };
    doc::WindOverride w;
    if (!direction.is_none()) w.direction = toVec3(direction, "direction");
    w.strength = number(strength);
    w.gustiness = number(gustiness);
    w.frequency = number(frequency);
    w.clipLength = number(clipLength);
    w.clipFps = number(fps);
    if (!bones.is_none()) w.bones = bones.cast<int>();
    return w;
}

exporter::ExportTree exportTree(const forest::ForestTree& t) {
    return {t.name,
            t.mesh,
            t.instance.position,
            t.instance.rotation,
            t.instance.scale * t.instance.growth,
            t.variant,
            t.instance.id,
            t.instance.species,
            t.meshCameraDistance};
}

std::vector<exporter::ExportVariant> exportVariants(const std::vector<forest::ForestVariant>& v) {
    std::vector<exporter::ExportVariant> out;
    for (const forest::ForestVariant& variant : v)
        out.push_back({variant.name, variant.mesh, variant.species, variant.index});
    return out;
}

std::vector<std::string> writeForest(const std::vector<forest::ForestTree>& trees,
                                     const std::vector<exporter::ExportVariant>& variants,
                                     const std::vector<std::string>& species,
                                     const std::string& path, bool fullPrecision, bool fsync,
                                     bool instanceTables) {
    exporter::ForestWriterOptions options;
    options.species = species;
    options.fsync = fsync;
    options.compact = !fullPrecision;
    exporter::TreeExporter exporter(path, options);
    exporter.setInstanceTables(instanceTables);
    exporter.addVariants(variants);
    std::vector<exporter::ExportTree> batch;
    batch.reserve(trees.size());
    for (const forest::ForestTree& t : trees)
        batch.push_back(exportTree(t));
    exporter.add(batch);
    std::vector<std::string> written;
    for (const auto& f : exporter.commit())
        written.push_back(f.string());
    return written;
}

void addSpecies(Project& p, const std::string& name, const py::object& source) {
    if (name.empty()) throw InvalidInput("a species needs a name");
    if (p.project.findSpecies(name))
        throw InvalidInput("the project has a species '" + name + "' already");
    doc::ProjectSpecies ps;
    ps.name = name;
    if (!py::isinstance<py::dict>(source) &&
        (py::isinstance<py::str>(source) || py::hasattr(source, "__fspath__"))) {
        const QString file = QFileInfo(QString::fromStdString(toPath(source))).absoluteFilePath();
        doc::loadSpecies(file); // fail now, with the file's message, rather than at build time
        ps.file = file.toStdString();
    } else {
        // A Species or a dict: inline, file parameters rewritten for the project's folder.
        const graph::SpeciesGraph g = speciesGraphFrom(source);
        sylva::Value root = sylva::Value::parseJson(doc::serializeSpecies(g).toStdString());
        sylva::Value inlineGraph = *root.find("graph");
        doc::rebaseGraphFiles(inlineGraph, QString::fromStdString(g.baseDir.string()),
                              p.project.baseDir);
        ps.graph = std::move(inlineGraph);
        if (const sylva::Value* traits = root.find("traits")) ps.traits = *traits;
    }
    p.project.species.push_back(std::move(ps));
}

std::map<std::string, int> countsFrom(const py::object& counts, const Project& p) {
    std::map<std::string, int> out;
    if (counts.is_none()) return out;
    for (const auto& [k, v] : counts.cast<py::dict>()) {
        const std::string name = py::str(k).cast<std::string>();
        const int n = v.cast<int>();
        if (!p.project.findSpecies(name))
            throw InvalidInput("the project has no species '" + name + "'");
        if (n < 0)
            throw InvalidInput("a tree count must not be negative, got " + std::to_string(n));
        out[name] = n;
    }
    return out;
}

env::ObstacleMesh meshFromArrays(const std::string& name, const py::object& vertices,
                                 const py::object& triangles, const env::MeshTransform& t) {
    const std::vector<glm::vec3> v = toVec3Array(vertices, (name + ": vertices").c_str());
    const std::vector<glm::uvec3> f = toTriangleArray(triangles, (name + ": triangles").c_str());
    return env::makeObstacleMesh(name, v, f, t.matrix());
}

} // namespace

/// Locks \p edit as the editor does (skel::lockBranch): the project's forest is built without
/// meshes, keeping the tree's skeleton as grown, and the branch's subtree as it is shown — the
/// tree's other edits and this edit's own applied — is kept in the edit, in the tree's frame
/// (bends are world directions). \throw InvalidInput for a branch the grown tree lacks or a
/// trunk.
static void lockAsGrown(const Project& p, const doc::ProjectInstance& tree,
                        skel::BranchEdit& edit) {
    forest::ForestScene scene = p.makeScene();
    forest::ForestOptions options;
    options.buildMeshes = false;
    options.keepGrown = true;
    std::shared_ptr<const skel::Skeleton> grown;
    glm::mat4 transform(1.0f);
    forest::buildForest(scene, options, [&](const std::vector<forest::ForestTree>& batch) {
        for (const forest::ForestTree& t : batch)
            if (t.instance.handPlaced && t.instance.id == tree.id) {
                grown = t.grown;
                transform = t.instance.transform();
            }
    });
    if (!grown) throw InvalidInput("tree " + std::to_string(tree.id) + " was not grown");
    const glm::mat3 toLocal = glm::inverse(glm::mat3(transform));
    std::vector<skel::BranchEdit> others = tree.branchEdits;
    for (skel::BranchEdit& e : others)
        if (e.bend) e.bend = toLocal * *e.bend;
    skel::BranchEdit kept = edit;
    if (kept.bend) kept.bend = toLocal * *kept.bend;
    skel::lockBranch(*grown, others, kept);
    edit.lock = true;
    edit.lockedBase = kept.lockedBase;
    edit.locked = std::move(kept.locked);
    edit.lockedLeaves = std::move(kept.lockedLeaves);
}

void bindForest(py::module_& m) {
    py::class_<ForestTreeRef>(m, "ForestTree",
                              "One tree of a built forest: its mesh in its own frame and the "
                              "transform that places it.")
        .def_property_readonly("id", [](const ForestTreeRef& t) { return t.tree().instance.id; })
        .def_property_readonly("name", [](const ForestTreeRef& t) { return t.tree().name; })
        .def_readonly("species", &ForestTreeRef::species)
        .def_property_readonly(
            "position", [](const ForestTreeRef& t) { return fromVec3(t.tree().instance.position); })
        .def_property_readonly(
            "rotation", [](const ForestTreeRef& t) { return t.tree().instance.rotation; },
            "radians about +Y")
        .def_property_readonly(
            "scale",
            [](const ForestTreeRef& t) {
                return t.tree().instance.scale * t.tree().instance.growth;
            },
            "uniform scale of the mesh (size variation × growth stage)")
        .def_property_readonly("growth",
                               [](const ForestTreeRef& t) { return t.tree().instance.growth; })
        .def_property_readonly("seed",
                               [](const ForestTreeRef& t) { return t.tree().instance.seed; })
        .def_property_readonly("hand_placed",
                               [](const ForestTreeRef& t) { return t.tree().instance.handPlaced; })
        .def_property_readonly(
            "instanced", [](const ForestTreeRef& t) { return t.tree().variant >= 0; },
            "whether the tree is an instance of one of its species' variants (it touches no "
            "obstacle and no neighbour's crown); False: grown and adapted for its place")
        .def_property_readonly(
            "variant",
            [](const ForestTreeRef& t) -> py::object {
                if (t.tree().variant < 0) return py::none();
                return py::int_(t.tree().variant);
            },
            "index into Forest.variants for an instanced tree, None for a unique one")
        .def_property_readonly(
            "adapted_from",
            [](const ForestTreeRef& t) -> py::object {
                if (t.tree().adaptedFrom < 0) return py::none();
                return py::int_(t.tree().adaptedFrom);
            },
            "a unique tree adapted from a variant's skeleton: its index into Forest.variants; "
            "None for an instanced tree and one grown from its own seed")
        .def_property_readonly(
            "transform",
            [](const ForestTreeRef& t) {
                const glm::mat4 mat = t.tree().instance.transform();
                float rows[16];
                for (int r = 0; r < 4; ++r)
                    for (int c = 0; c < 4; ++c)
                        rows[4 * r + c] = mat[c][r];
                return makeArray(rows, 4, 4);
            },
            "4×4 local-to-world matrix (row-major: world = M @ (x, y, z, 1))")
        .def_property_readonly(
            "mesh", [](const ForestTreeRef& t) { return MeshRef{t.tree().mesh}; },
            "the tree's mesh in its own frame (an instanced tree's is its variant's, meshed at "
            "the tree's camera distance when built with lod=True, else the variant's own)")
        .def(
            "world_positions",
            [](const ForestTreeRef& t) {
                const glm::mat4 mat = t.tree().instance.transform();
                const auto& p = t.tree().mesh->positions;
                std::vector<glm::vec3> out(p.size());
                for (std::size_t i = 0; i < p.size(); ++i)
                    out[i] = glm::vec3(mat * glm::vec4(p[i], 1.0f));
                return makeArray(&out.data()->x, out.size(), 3);
            },
            "the mesh's vertices placed in the world, shape (N, 3)")
        .def_property_readonly("metrics",
                               [](const ForestTreeRef& t) { return metricsDict(t.tree().metrics); })
        .def_property_readonly(
            "colliding", [](const ForestTreeRef& t) { return t.tree().adapt.collidingBefore > 0; },
            "whether the grown tree met an obstacle or a neighbour before adaptation")
        .def_property_readonly("pruned_nodes",
                               [](const ForestTreeRef& t) { return t.tree().adapt.hiddenNodes; })
        .def("__repr__", [](const ForestTreeRef& t) {
            const glm::vec3 p = t.tree().instance.position;
            return "<sylva.ForestTree " + t.tree().name + " at (" + std::to_string(p.x) + ", " +
                   std::to_string(p.y) + ", " + std::to_string(p.z) + ")>";
        });

    py::class_<VariantRef>(m, "ForestVariant",
                           "One of a species' K variants: grown once at full growth, never "
                           "adapted; instanced trees show it with their own transform.")
        .def_property_readonly(
            "index", [](const VariantRef& v) { return v.index; },
            "its place in Forest.variants (ForestTree.variant)")
        .def_property_readonly(
            "name", [](const VariantRef& v) { return v.variant().name; }, "\"<species>_v<k>\"")
        .def_readonly("species", &VariantRef::species)
        .def_property_readonly(
            "species_variant", [](const VariantRef& v) { return v.variant().index; },
            "k, 0..K-1 within its species")
        .def_property_readonly("seed", [](const VariantRef& v) { return v.variant().seed; })
        .def_property_readonly(
            "mesh", [](const VariantRef& v) { return MeshRef{v.variant().mesh}; },
            "full detail, in the variant's own frame (scale 1)")
        .def_property_readonly("metrics",
                               [](const VariantRef& v) { return metricsDict(v.variant().metrics); })
        .def("__repr__",
             [](const VariantRef& v) { return "<sylva.ForestVariant " + v.variant().name + ">"; });

    py::class_<Forest>(m, "Forest", "The trees of a built forest, in instance order.")
        .def("__len__", [](const Forest& f) { return f.trees->size(); })
        .def("__getitem__",
             [](const Forest& f, py::ssize_t i) {
                 const auto n = static_cast<py::ssize_t>(f.trees->size());
                 if (i < 0) i += n;
                 if (i < 0 || i >= n) throw py::index_error("tree index out of range");
                 const auto k = static_cast<std::size_t>(i);
                 return ForestTreeRef{f.trees, k, f.speciesNames[(*f.trees)[k].instance.species]};
             })
        .def_property_readonly(
            "trees",
            [](const Forest& f) {
                std::vector<ForestTreeRef> out;
                for (std::size_t k = 0; k < f.trees->size(); ++k)
                    out.push_back({f.trees, k, f.speciesNames[(*f.trees)[k].instance.species]});
                return out;
            })
        .def_property_readonly(
            "variants",
            [](const Forest& f) {
                std::vector<VariantRef> out;
                for (std::size_t k = 0; k < f.variants->size(); ++k)
                    out.push_back({f.variants, k, f.speciesNames[(*f.variants)[k].species]});
                return out;
            },
            "the variants instanced trees share (ForestTree.variant indexes this list)")
        .def(
            "tree_by_id",
            [](const Forest& f, std::uint64_t id) {
                for (std::size_t k = 0; k < f.trees->size(); ++k)
                    if ((*f.trees)[k].instance.id == id)
                        return ForestTreeRef{f.trees, k,
                                             f.speciesNames[(*f.trees)[k].instance.species]};
                throw py::key_error("the forest has no tree " + std::to_string(id));
            },
            py::arg("id"), "the tree with this stable id (KeyError when there is none)")
        .def_readonly("stats", &Forest::stats,
                      "as `sylva-cli forest --stats`: trees, instanced, unique, variants, "
                      "vertices, triangles, colliding_trees, pruned_nodes, shortfall, metrics "
                      "(co2_kg, ...), timings_ms, cpu_ms")
        .def(
            "export",
            [](const Forest& f, const py::object& path, bool fullPrecision, bool fsync,
               bool instanceTables, bool wind, const py::object& direction,
               const py::object& strength, const py::object& gustiness, const py::object& frequency,
               const py::object& bones, const py::object& clipLength, const py::object& fps) {
                const std::string p = toPath(path);
                if (!wind) {
                    if (!direction.is_none() || !strength.is_none() || !gustiness.is_none() ||
                        !frequency.is_none() || !bones.is_none() || !clipLength.is_none() ||
                        !fps.is_none())
                        throw InvalidInput("wind settings need wind=True");
                    py::gil_scoped_release release;
                    return writeForest(*f.trees, exportVariants(*f.variants), f.speciesNames, p,
                                       fullPrecision, fsync, instanceTables);
                }
                if (!f.windData)
                    throw InvalidInput("export(wind=True) needs a forest built with wind data: "
                                       "build_forest(wind=True)");
                // The project's wind (when it has one) under the keyword arguments.
                const exporter::WindExportOptions options = doc::exportWind(
                    f.projectWind, windOverrideFrom(direction, strength, gustiness, frequency,
                                                    bones, clipLength, fps));
                py::gil_scoped_release release;
                std::vector<std::string> written;
                // As `sylva-cli forest --wind`: .glb/.gltf/.fbx through the wind exporter (one
                // rig per unique mesh: instances of a variant share its arrays and clip); an OBJ
                // as without wind plus its .wind.csv table.
                if (exporter::formatFor(p).wind == exporter::WindSupport::Table)
                    written = writeForest(*f.trees, exportVariants(*f.variants), f.speciesNames, p,
                                          fullPrecision, fsync, instanceTables);
                exporter::WindExporter windExporter(p, options);
                std::vector<exporter::WindExportTree> trees;
                trees.reserve(f.trees->size());
                for (const forest::ForestTree& t : *f.trees)
                    trees.push_back({t.name, t.mesh, t.skeleton, t.instance.position,
                                     t.instance.rotation, t.instance.scale * t.instance.growth});
                windExporter.add(trees);
                for (const auto& file : windExporter.commit())
                    written.push_back(file.string());
                return written;
            },
            py::arg("path"), py::arg("full_precision") = false, py::arg("fsync") = false,
            py::arg("instance_tables") = false, py::arg("wind") = false,
            py::arg("direction") = py::none(), py::arg("strength") = py::none(),
            py::arg("gustiness") = py::none(), py::arg("frequency") = py::none(),
            py::arg("bones") = py::none(), py::arg("clip_length") = py::none(),
            py::arg("fps") = py::none(),
            "writes the forest as `sylva-cli forest -o path` does (same bytes); returns the "
            "paths written. wind=True (a forest from build_forest(wind=True)) writes it as "
            "`sylva-cli forest --wind`: per tree a rig (instances of a variant share its arrays "
            "and clip), the looping clip 'wind', the _WIND* data, Pivot Painter 2 textures and "
            "<stem>.wind.csv; the wind is the project's when it has one, then the keyword "
            "arguments' (as Tree.export)")
        .def("__repr__", [](const Forest& f) {
            return "<sylva.Forest " + std::to_string(f.trees->size()) + " trees>";
        });

    py::class_<Project>(m, "Project",
                        "A forest project: species, placement domains, hand-placed trees, "
                        "obstacles (files or arrays), camera and seed.")
        .def(py::init([](std::uint64_t seed, const py::object& baseDir) {
                 Project p;
                 p.project.seed = seed;
                 p.project.baseDir = QDir::currentPath();
                 if (!baseDir.is_none())
                     p.project.baseDir =
                         QFileInfo(QString::fromStdString(toPath(baseDir))).absoluteFilePath();
                 return p;
             }),
             py::arg("seed") = 0, py::arg("base_dir") = py::none(),
             "an empty project; relative paths resolve against base_dir (default: the working "
             "directory)")
        .def_property(
            "seed", [](const Project& p) { return p.project.seed; },
            [](Project& p, std::uint64_t s) { p.project.seed = s; })
        .def_property(
            "camera", [](const Project& p) { return fromVec3(p.project.cameraPosition); },
            [](Project& p, const py::object& v) { p.project.cameraPosition = toVec3(v, "camera"); },
            "camera position for the level of detail (metres)")
        .def_property(
            "wind", [](const Project& p) { return windTo(p.project.wind); },
            [](Project& p, const py::object& v) {
                if (v.is_none()) {
                    p.project.wind.reset();
                    return;
                }
                // Keys not given take the defaults; unknown keys are refused.
                wind::WindSettings w;
                for (const auto& [key, value] : v.cast<py::dict>()) {
                    const std::string k = key.cast<std::string>();
                    if (k == "direction")
                        w.direction = toVec3(value, "wind direction");
                    else if (k == "strength")
                        w.strength = value.cast<float>();
                    else if (k == "gustiness")
                        w.gustiness = value.cast<float>();
                    else if (k == "frequency")
                        w.frequency = value.cast<float>();
                    else
                        throw InvalidInput("unknown wind setting '" + k +
                                           "' (direction, strength, gustiness, frequency)");
                }
                wind::WindSettings check;
                check.direction = w.direction;
                check.strength = w.strength;
                check.gustiness = w.gustiness;
                check.frequency = w.frequency;
                wind::validate(check);
                p.project.wind = w;
            },
            "the project's wind (docs/wind.md) as a dict (direction, strength 0..2, gustiness "
            "0..1, frequency Hz 0.05..5), or None (unset: nothing saved); set a dict (missing "
            "keys take the defaults) or None")
        .def_property_readonly("base_dir",
                               [](const Project& p) { return p.project.baseDir.toStdString(); })
        .def_property_readonly("species", [](const Project& p) { return speciesNames(p.project); })
        .def_property_readonly("domains",
                               [](const Project& p) { return domainsList(p.project.domains); })
        .def_property_readonly(
            "tree_count", [](const Project& p) { return p.project.instances.size(); },
            "hand-placed trees")
        .def(
            "trees",
            [](const Project& p) {
                std::vector<Tree> out;
                for (const doc::ProjectInstance& t : p.project.instances)
                    out.push_back(treeOf(t.id, t));
                return out;
            },
            "the hand-placed trees (Tree), in file order")
        .def(
            "tree",
            [](const Project& p, std::uint64_t id) {
                for (const doc::ProjectInstance& t : p.project.instances)
                    if (t.id == id) return treeOf(id, t);
                throw InvalidInput("there is no tree " + std::to_string(id));
            },
            py::arg("id"), "the hand-placed tree with this id")
        .def_property_readonly(
            "variants",
            [](const Project& p) {
                std::map<std::string, int> out;
                for (const doc::ProjectSpecies& s : p.project.species)
                    out[s.name] = s.variants;
                return out;
            },
            "K per species: how many variants its instanced trees share")
        .def(
            "set_variants",
            [](Project& p, const std::string& species, int k) {
                for (doc::ProjectSpecies& s : p.project.species)
                    if (s.name == species) {
                        requireRange(("variants of '" + species + "'").c_str(), k,
                                     doc::settings::kVariants.min, doc::settings::kVariants.max);
                        s.variants = k;
                        return;
                    }
                throw InvalidInput("the project has no species '" + species + "'");
            },
            py::arg("species"), py::arg("k"),
            ("how many variants the species' instanced trees share (" +
             doc::settings::kVariants.rangeText() + ", default " +
             std::to_string(doc::kDefaultVariants) +
             "; 0: every tree of the species is grown for its place)")
                .c_str())
        .def_property_readonly(
            "obstacles", [](const Project& p) { return obstaclesList(p.project.obstacles); },
            "the obstacle files (dicts: file, translate, rotate, scale); arrays are not listed")
        .def("add_species", &addSpecies, py::arg("name"), py::arg("species"),
             "a species from a file path (kept as a reference), a Species or a dict (inline)")
        .def(
            "add_domain",
            [](Project& p, const py::dict& counts, const py::object& min, const py::object& max,
               const py::object& polygon) {
                doc::PlacementDomain d;
                d.counts = countsFrom(counts, p);
                if (!polygon.is_none()) {
                    d.shape = "polygon";
                    for (const auto& xz : polygon.cast<std::vector<std::vector<float>>>()) {
                        if (xz.size() != 2) throw InvalidInput("polygon corners are (x, z) pairs");
                        d.polygon.push_back({xz[0], xz[1]});
                    }
                    if (d.polygon.size() < 3)
                        throw InvalidInput("a polygon needs at least three corners");
                } else {
                    d.min = toXZ(min, "min");
                    d.max = toXZ(max, "max");
                    if (!(d.min.x < d.max.x && d.min.y < d.max.y))
                        throw InvalidInput("a domain's min must be below its max in x and z");
                }
                // A fresh id above every other: its trees' ids are new too.
                for (const doc::PlacementDomain& other : p.project.domains)
                    d.id = std::max(d.id, other.id);
                ++d.id;
                p.project.domains.push_back(std::move(d));
                return p.project.domains.size() - 1;
            },
            py::arg("counts"), py::arg("min") = py::make_tuple(-50.0, -50.0),
            py::arg("max") = py::make_tuple(50.0, 50.0), py::arg("polygon") = py::none(),
            "a rectangle (min, max as (x, z)) or polygon domain with counts {species: n}")
        .def(
            "set_ground",
            [](Project& p, const py::object& vertices, const py::object& triangles,
               const py::object& counts, const py::object& name) {
                const std::string label = name.is_none() ? "ground" : name.cast<std::string>();
                env::ObstacleMesh g = meshFromArrays(label, vertices, triangles, {});
                if (g.empty()) throw InvalidInput(label + ": the ground has no valid triangle");
                p.groundCounts = countsFrom(counts, p);
                p.ground = std::move(g);
            },
            py::arg("vertices"), py::arg("triangles"), py::arg("counts") = py::none(),
            py::arg("name") = py::none(),
            "a ground mesh from arrays (world space, Y up): trees stand where a ray down meets "
            "it, in every domain, and a domain over its footprint gets counts {species: n}")
        .def(
            "add_tree",
            [](Project& p, const std::string& species, const py::object& position, double rotation,
               double scale, std::optional<std::uint64_t> seed, double growth,
               const py::object& season) {
                if (!p.project.findSpecies(species))
                    throw InvalidInput("the project has no species '" + species + "'");
                doc::ProjectInstance t = newTree(p.project, p.project.instances.size(), species,
                                                 position, rotation, scale, seed, growth);
                t.season = seasonFrom(season);
                doc::assignIds(p.project); // every earlier tree has its id
                if (p.project.nextTreeId > doc::kMaxTreeId)
                    throw LimitExceeded("a project's tree ids are limited to " +
                                        std::to_string(doc::kMaxTreeId));
                t.id = p.project.nextTreeId++;
                p.project.instances.push_back(t);
                return t.id;
            },
            py::arg("species"), py::arg("position"), py::arg("rotation") = 0.0,
            py::arg("scale") = 1.0, py::arg("seed") = py::none(), py::arg("growth") = 1.0,
            py::arg("season") = py::none(),
            "a hand-placed tree (rotation in degrees about +Y; season: its own, None: the "
            "project's); returns its id")
        .def_property(
            "season", [](const Project& p) { return seasonTo(p.project.season); },
            [](Project& p, const py::object& season) { p.project.season = seasonFrom(season); },
            "the season of every tree without its own: 'spring', 'summer', 'autumn', 'winter', "
            "or None (each species' own, summer)")
        .def(
            "set_tree_season",
            [](Project& p, std::uint64_t id, const py::object& season) {
                for (doc::ProjectInstance& t : p.project.instances)
                    if (t.id == id) {
                        t.season = seasonFrom(season);
                        return;
                    }
                throw InvalidInput("there is no tree " + std::to_string(id));
            },
            py::arg("id"), py::arg("season"),
            "a hand-placed tree's own season, by its id (None: the project's)")
        .def(
            "edit_branch",
            [](Project& p, std::uint64_t id, const std::string& branch, const py::object& prune,
               const py::object& bend, const py::object& length, const py::object& radius,
               const py::object& lock) {
                for (doc::ProjectInstance& t : p.project.instances)
                    if (t.id == id) {
                        skel::BranchEdit edit = branchEditFrom(t.branchEdits, branch, prune, bend,
                                                               length, radius, lock);
                        if (edit.lock && edit.locked.empty())
                            lockAsGrown(p, t, edit); // the geometry, not only the flag
                        t.branchEdits = withBranchEdit(t.branchEdits, edit);
                        return;
                    }
                throw InvalidInput("there is no tree " + std::to_string(id));
            },
            py::arg("id"), py::arg("branch"), py::arg("prune") = py::none(),
            py::arg("bend") = py::none(), py::arg("length") = py::none(),
            py::arg("radius") = py::none(), py::arg("lock") = py::none(),
            "a hand edit of one branch of a hand-placed tree, by the branch's stable id "
            "(docs/branch-edits.md): None leaves a setting; prune=False, bend=(), length=1.0, "
            "radius=1.0, lock=False clear it; an edit of a branch the tree lacks is kept and "
            "reported when the forest is built")
        .def(
            "branch_edits",
            [](const Project& p, std::uint64_t id) {
                for (const doc::ProjectInstance& t : p.project.instances)
                    if (t.id == id) return branchEditsList(t.branchEdits);
                throw InvalidInput("there is no tree " + std::to_string(id));
            },
            py::arg("id"), "a hand-placed tree's branch edits as dicts")
        .def(
            "add_obstacle",
            [](Project& p, const py::object& file, const py::object& vertices,
               const py::object& triangles, const py::object& translate, const py::object& rotate,
               const py::object& scale, const py::object& name) {
                if (!file.is_none()) {
                    if (!vertices.is_none() || !triangles.is_none())
                        throw InvalidInput("an obstacle is a file or arrays, not both");
                    doc::ProjectObstacle o;
                    o.file = QFileInfo(QString::fromStdString(toPath(file)))
                                 .absoluteFilePath()
                                 .toStdString();
                    applyTransform(o, translate, rotate, scale);
                    p.project.obstacles.push_back(o);
                    return;
                }
                if (vertices.is_none() || triangles.is_none())
                    throw InvalidInput("an obstacle needs a file, or vertices and triangles");
                const std::string label =
                    name.is_none() ? "obstacle " + std::to_string(p.arrayObstacles.size() + 1)
                                   : name.cast<std::string>();
                p.arrayObstacles.push_back(meshFromArrays(label, vertices, triangles,
                                                          transformFrom(translate, rotate, scale)));
            },
            py::arg("file") = py::none(), py::arg("vertices") = py::none(),
            py::arg("triangles") = py::none(), py::arg("translate") = py::none(),
            py::arg("rotate") = py::none(), py::arg("scale") = py::none(),
            py::arg("name") = py::none(),
            "an obstacle mesh from a file (any format Assimp reads) or from arrays "
            "(vertices (N, 3), triangles (M, 3)); scaled, rotated (degrees about x, y, z) and "
            "translated")
        .def(
            "clear_obstacles",
            [](Project& p) {
                p.project.obstacles.clear();
                p.arrayObstacles.clear();
            },
            "removes every obstacle (files and arrays)")
        .def_property_readonly(
            "obstacle_count",
            [](const Project& p) { return p.project.obstacles.size() + p.arrayObstacles.size(); })
        .def(
            "save",
            [](const Project& p, const py::object& path) {
                if (!p.arrayObstacles.empty() || p.ground)
                    throw InvalidInput("obstacles and grounds given as arrays cannot be saved in "
                                       "a project file; write them to mesh files first");
                const QString file =
                    QFileInfo(QString::fromStdString(toPath(path))).absoluteFilePath();
                doc::saveProject(doc::rebaseProject(p.project, QFileInfo(file).absolutePath()),
                                 file);
            },
            py::arg("path"), "atomic save as a .sylva project (paths rebased)")
        .def(
            "build_forest",
            [](const Project& p, const py::object& progress, const py::object& camera, bool lod,
               bool adapt, bool neighbours, bool instancing, const py::object& tile,
               std::optional<int> threads, bool wind) {
                BuildOptions b =
                    buildOptions(camera, lod, adapt, neighbours, instancing, tile, threads);
                b.options.windData = wind;
                PyProgress prog(progress);
                auto trees = std::make_shared<std::vector<forest::ForestTree>>();
                auto variants = std::make_shared<std::vector<forest::ForestVariant>>();
                b.options.onVariants = [&variants](const std::vector<forest::ForestVariant>& v) {
                    *variants = v;
                };
                forest::ForestScene s;
                forest::ForestStats stats;
                withoutGil(prog, [&] {
                    const auto t0 = Clock::now();
                    s = p.makeScene();
                    if (b.camera) s.camera = *b.camera;
                    const double loadMs = msSince(t0);
                    stats = forest::buildForest(
                        s, b.options,
                        [&](const std::vector<forest::ForestTree>& batch) {
                            trees->insert(trees->end(), batch.begin(), batch.end());
                        },
                        prog);
                    stats.wallMs["load"] = loadMs;
                });
                warnShortfalls(stats, s);
                Forest f;
                f.trees = trees;
                f.variants = variants;
                for (const forest::SceneSpecies& sp : s.species)
                    f.speciesNames.push_back(sp.name);
                f.stats = statsDict(stats, s, b.options);
                f.windData = wind;
                f.projectWind = p.project.wind;
                return f;
            },
            py::arg("progress") = py::none(), py::arg("camera") = py::none(), py::arg("lod") = true,
            py::arg("adapt") = true, py::arg("neighbours") = true, py::arg("instancing") = true,
            py::arg("tile") = py::none(), py::arg("threads") = py::none(), py::arg("wind") = false,
            "builds the forest as `sylva-cli forest` does, the GIL released; progress(fraction, "
            "stage) is called on this thread; Ctrl-C raises KeyboardInterrupt. wind=True keeps "
            "what a wind export needs (`sylva-cli forest --wind`: node ids, full-detail variants)")
        .def(
            "export_forest",
            [](const Project& p, const py::object& path, const py::object& progress,
               const py::object& camera, bool lod, bool adapt, bool neighbours, bool instancing,
               const py::object& tile, std::optional<int> threads, bool fullPrecision, bool fsync,
               bool instanceTables, std::optional<bool> wind, const py::object& direction,
               const py::object& strength, const py::object& gustiness, const py::object& frequency,
               const py::object& bones, const py::object& clipLength, const py::object& fps) {
                // The keywords only translate into the request every front door makes
                // (document/projectexport): the same bytes and statistics as sylva-cli forest.
                const BuildOptions b =
                    buildOptions(camera, lod, adapt, neighbours, instancing, tile, threads);
                doc::ExportRequest request;
                request.path = toPath(path);
                request.tile = b.options.tile;
                request.tileCount = b.options.tileCount;
                request.camera = b.camera;
                request.lod = lod;
                request.adapt = adapt;
                request.neighbours = neighbours;
                request.instancing = instancing;
                request.fullPrecision = fullPrecision;
                request.fsync = fsync;
                request.instanceTables = instanceTables;
                request.wind = wind;
                if (wind == false && (!direction.is_none() || !strength.is_none() ||
                                      !gustiness.is_none() || !frequency.is_none() ||
                                      !bones.is_none() || !clipLength.is_none() || !fps.is_none()))
                    throw InvalidInput("wind settings need wind=True");
                request.windOverride = windOverrideFrom(direction, strength, gustiness, frequency,
                                                        bones, clipLength, fps);
                PyProgress prog(progress);
                doc::ExportReport report;
                withoutGil(prog, [&] {
                    const auto t0 = Clock::now();
                    forest::ForestScene s = p.makeScene();
                    const double sceneMs = msSince(t0);
                    report = doc::exportForest(std::move(s), p.project, request, prog);
                    report.loadMs += sceneMs;
                    report.totalMs = msSince(t0);
                });
                warnShortfalls(report.stats, report.species);
                return py::module_::import("json").attr("loads")(
                    doc::exportStatsJson(report, omp_get_max_threads()));
            },
            py::arg("path"), py::arg("progress") = py::none(), py::arg("camera") = py::none(),
            py::arg("lod") = true, py::arg("adapt") = true, py::arg("neighbours") = true,
            py::arg("instancing") = true, py::arg("tile") = py::none(),
            py::arg("threads") = py::none(), py::arg("full_precision") = false,
            py::arg("fsync") = false, py::arg("instance_tables") = false,
            py::arg("wind") = py::none(), py::arg("direction") = py::none(),
            py::arg("strength") = py::none(), py::arg("gustiness") = py::none(),
            py::arg("frequency") = py::none(), py::arg("bones") = py::none(),
            py::arg("clip_length") = py::none(), py::arg("fps") = py::none(),
            withFormats(
                "builds and writes the forest batch by batch without keeping it (`sylva-cli "
                "forest -o path`: {formats}, same bytes, .usda tiles included); the wind rig and "
                "clip ({wind-rig}) or the .wind.csv beside an OBJ are written in the project's "
                "wind when it has "
                "one (wind=None), or as wind=True/False says (--wind, --no-wind), the settings "
                "given over the project's; Ctrl-C leaves no file; returns the statistics of "
                "`sylva-cli forest --stats`"))
        .def("__repr__", [](const Project& p) {
            return "<sylva.Project " + std::to_string(p.project.species.size()) + " species, " +
                   std::to_string(p.project.domains.size() + (p.ground ? 1 : 0)) + " domains>";
        });

    m.def(
        "load_project",
        [](const py::object& path) {
            doc::LoadReport report;
            Project p;
            p.project = doc::loadProjectOrScene(QString::fromStdString(toPath(path)), &report);
            for (const std::string& w : report.warnings)
                PyErr_WarnEx(PyExc_UserWarning, w.c_str(), 1);
            return p;
        },
        py::arg("path"),
        "a .sylva project (or the reference implementation's scene description), as "
        "`sylva-cli forest` reads it");
}

} // namespace sylva::python
