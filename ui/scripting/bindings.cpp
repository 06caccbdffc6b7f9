// The `sylva` Python module as the editor embeds it: the running window's document, edited
// through the same document functions (and so the same undoable commands) as the mouse. The
// names are a public contract: docs/scripting.md.
#include <cmath>
#include <cstring>
#include <functional>
#include <optional>

#include <pybind11/embed.h>
#include <pybind11/stl.h>

#include <QApplication>
#include <QElapsedTimer>
#include <QEventLoop>
#include <QLayout>
#include <QStatusBar>
#include <QTimer>

#include "document/autosave.h"
#include "document/document.h"
#include "document/errormessage.h"
#include "engine/lsystem/grammar.h"
#include "engine/mesh/mesh.h"
#include "engine/util/error.h"
#include "python/bindings/convert.h"
#include "python/bindings/engine.h"
#include "python/bindings/project.h"
#include "ui/document/messagespanel.h"
#include "ui/generation/documentgenerator.h"
#include "ui/generation/speciespreview.h"
#include "ui/generation/treebranches.h"
#include "ui/mainwindow.h"
#include "ui/nodes/nodegraphscene.h"
#include "ui/scripting/pythonhost.h"
#include "ui/speciesworkbench.h"
#include "ui/viewport/toolcontroller.h"
#include "ui/viewport/tools/branchtool.h"
#include "ui/viewport/viewport.h"

namespace py = pybind11;

namespace sylva::ui {

namespace {

MainWindow& window() {
    MainWindow* w = PythonHost::window();
    if (!w) throw std::runtime_error("the sylva module needs the editor's window");
    return *w;
}

doc::Document& document() {
    return window().document();
}

// Python <-> parameter values, vectors and project parts: the same conversions as
// `import sylva`.
using python::fromValue;
using python::fromVec3;
using python::toValue;
using python::toVec3;

// The project's parts as `import sylva` gives and takes them (python/bindings/project.h).
using python::Tree;

Tree treeOf(doc::TreeId id) {
    return python::treeOf(id, document().tree(id));
}

/// Lays the window out as it will be shown. A script runs as soon as the window is visible,
/// before the event loop has applied the layout requests of its docks: the viewport was still
/// 557 px wide (later 393), and a point drawn at x=537 was reported at x=619, where an outside
/// tool's click missed it. Layouts post more requests while they are applied (docks,
/// splitters), hence the few passes.
void layOut(MainWindow& w) {
    if (!w.isVisible()) w.show();
    w.ensurePolished();
    for (int pass = 0; pass < 3; ++pass) {
        QCoreApplication::sendPostedEvents(nullptr, QEvent::LayoutRequest);
        if (QLayout* l = w.layout()) l->activate();
    }
    QCoreApplication::sendPostedEvents(nullptr, QEvent::LayoutRequest);
}

/// Keeps the window live (its events, timers, the workers' results) until \p done answers true
/// or \p seconds pass, and returns done(); every scripted wait goes through here. It sleeps
/// until an event comes, woken at least every 20 ms to ask \p done and to let a signal in:
/// Ctrl-C or SIGTERM raise KeyboardInterrupt in the script at the wait (PythonHost::runScript),
/// so a script that seems to hang says where it waits. Events are run at least once.
bool pumpUntil(double seconds, const std::function<bool()>& done) {
    QElapsedTimer clock;
    clock.start();
    const qint64 limit = qint64(seconds * 1000.0);
    QTimer tick;
    tick.setTimerType(Qt::PreciseTimer);
    tick.start(20);
    while (!done()) {
        const bool more = clock.elapsed() < limit;
        QCoreApplication::processEvents(more ? QEventLoop::WaitForMoreEvents
                                             : QEventLoop::AllEvents);
        if (PyErr_CheckSignals() != 0) throw py::error_already_set();
        if (!more) break;
    }
    return done();
}

py::dict generate() {
    MainWindow& w = window();
    if (!pumpUntil(600.0, [&w] { return !w.isGenerating(); }))
        throw std::runtime_error("the generation did not finish in time");
    const GenerationResult& r = w.generator().result();
    if (!w.lastError().isEmpty() && !r.ok()) throw InvalidInput(w.lastError().toStdString());
    // The newest generation failed: result() is the last good build, which is not this
    // document's (after a failed open or edit): never hand its numbers out as the document's.
    if (!w.generator().failure().isEmpty())
        throw InvalidInput(w.generator().failure().toStdString());
    py::dict stats;
    auto stat = [&r](const char* key) {
        auto it = r.stats.find(key);
        return it == r.stats.end() ? 0.0 : it->second;
    };
    stats["trees"] = r.trees.size();
    stats["triangles"] = r.triangleCount();
    stats["vertices"] = r.vertexCount();
    stats["co2_kg"] = stat("co2_kg");
    stats["regrown"] = static_cast<std::size_t>(stat("regrown"));
    stats["colliding_trees"] = static_cast<std::size_t>(stat("colliding_trees"));
    stats["instanced"] = static_cast<std::size_t>(stat("instanced"));
    stats["unique"] = static_cast<std::size_t>(stat("unique"));
    stats["variants"] = static_cast<std::size_t>(stat("variants"));
    stats["orphaned_edits"] = static_cast<std::size_t>(stat("orphaned_edits"));
    stats["ms"] = r.elapsedMs;
    stats["edit_to_result_ms"] = w.generator().editToResultMs();
    stats["timings_ms"] = r.timingsMs; // wall time per forest stage (species, place, trees...)
    return stats;
}

/// The shown tree \p id as grown (after the generation of the last edit), with its transform.
const DrawnTree& grownTree(doc::TreeId id) {
    (void)document().tree(id); // InvalidInput for an unknown tree
    generate();
    for (const DrawnTree& t : window().generator().result().trees)
        if (t.docId == id && t.grown) return t;
    throw InvalidInput("tree " + std::to_string(id) + " has not been grown");
}

struct DocumentApi {};
struct WindowApi {};

} // namespace

} // namespace sylva::ui

using namespace sylva;
using namespace sylva::ui;

namespace sylva::ui {
// Referenced by PythonHost so that the linker keeps this file (and the module's registration)
// when the editor links the static library.
void linkSylvaModule() {}
} // namespace sylva::ui

PYBIND11_EMBEDDED_MODULE(sylva, m) {
    // The engine and its project types (load_species, grow, Project, Tree, load_project,
    // build_forest, ...), the same as `import sylva` from python3 (docs/python.md); only the
    // editor's document (with undo) and window below, over the same types and conversions.
    sylva::python::bindEngine(m);
    m.doc() = "Sylva's editor: its document (trees, species, obstacles, undo) and window.";
    // Errors become ValueError / OSError / ... with the window's messages through the
    // translator bindEngine registered (python/bindings/convert.cpp, over doc::describeError).

    py::class_<DocumentApi>(m, "Document", "The open project; every edit is one undo step.")
        .def(
            "open",
            [](DocumentApi&, const std::string& path) {
                for (const std::string& w : document().open(QString::fromStdString(path)))
                    py::print("sylva: warning:", w);
            },
            py::arg("path"))
        .def(
            "save",
            [](DocumentApi&, std::optional<std::string> path) {
                // As File > Save: the window stamps its own write, so the file watcher does not
                // take it for a change on disk (and reload over later edits).
                if (!path && document().path().isEmpty())
                    throw IoError("the document has no file yet: save it under a name");
                if (!window().saveAs(path ? QString::fromStdString(*path) : document().path()))
                    throw IoError(window().lastError().toStdString());
            },
            py::arg("path") = py::none())
        .def("new", [](DocumentApi&) { document().newProject(); })
        .def_property_readonly("path", [](DocumentApi&) { return document().path().toStdString(); })
        .def_property_readonly("modified", [](DocumentApi&) { return document().isModified(); })
        .def(
            "project", [](DocumentApi&) { return python::projectFrom(document().project()); },
            "A copy of the open project as a sylva.Project (build_forest, export_forest, ... as "
            "in python3); edits to it do not reach the document.")
        .def("trees",
             [](DocumentApi&) {
                 std::vector<Tree> out;
                 for (doc::TreeId id : document().treeIds())
                     out.push_back(treeOf(id));
                 return out;
             })
        .def(
            "tree", [](DocumentApi&, doc::TreeId id) { return treeOf(id); }, py::arg("id"))
        .def(
            "add_tree",
            [](DocumentApi&, const std::string& species, py::object position, double rotation,
               double scale, std::optional<std::uint64_t> seed, double growth,
               const py::object& season) {
                doc::ProjectInstance t =
                    python::newTree(document().project(), document().treeIds().size(), species,
                                    position, rotation, scale, seed, growth);
                t.season = python::seasonFrom(season);
                return document().addTree(t);
            },
            py::arg("species"), py::arg("position"), py::arg("rotation") = 0.0,
            py::arg("scale") = 1.0, py::arg("seed") = py::none(), py::arg("growth") = 1.0,
            py::arg("season") = py::none(),
            "A hand-placed tree (as sylva.Project.add_tree); returns its id.")
        .def(
            "set_tree",
            [](DocumentApi&, doc::TreeId id, py::object position, std::optional<double> rotation,
               std::optional<double> scale, std::optional<std::uint64_t> seed,
               std::optional<std::string> species, std::optional<double> growth,
               const py::object& season) {
                doc::ProjectInstance t = document().tree(id);
                // "" (or "project") clears the tree's own season; None leaves it.
                if (!season.is_none()) {
                    const std::string name = season.cast<std::string>();
                    t.season = name.empty() || name == "project" ? std::string()
                                                                 : python::seasonFrom(season);
                }
                if (!position.is_none()) t.position = toVec3(position, "position");
                if (rotation) t.rotation = *rotation;
                if (scale) t.scale = *scale;
                if (seed) t.seed = *seed;
                if (species) t.species = *species;
                if (growth) t.growth = *growth;
                document().setTree(id, t);
            },
            py::arg("id"), py::arg("position") = py::none(), py::arg("rotation") = py::none(),
            py::arg("scale") = py::none(), py::arg("seed") = py::none(),
            py::arg("species") = py::none(), py::arg("growth") = py::none(),
            py::arg("season") = py::none())
        .def(
            "remove_tree", [](DocumentApi&, doc::TreeId id) { document().removeTrees({id}); },
            py::arg("id"))
        .def(
            "branches",
            [](DocumentApi&, doc::TreeId id) {
                const DrawnTree& drawn = grownTree(id);
                const doc::ProjectInstance& t = document().tree(id);
                return python::branchesList(editedBranchesOf(drawn, t.branchEdits), drawn.transform,
                                            static_cast<float>(t.scale * t.growth));
            },
            py::arg("tree_id"),
            "The branches of a hand-placed tree as grown, its edits applied (pruned ones left "
            "out), before adaptation to obstacles: dicts of id, parent (None for the trunk), "
            "order, base and tip (world x, y, z), length and radius (m). Waits for the "
            "generation. docs/branch-edits.md")
        .def(
            "edit_branch",
            [](DocumentApi&, doc::TreeId id, const std::string& branch, const py::object& prune,
               const py::object& bend, const py::object& length, const py::object& radius,
               const py::object& lock) {
                const std::vector<skel::BranchEdit> edits = document().branchEdits(id);
                const skel::BranchEdit edit =
                    python::branchEditFrom(edits, branch, prune, bend, length, radius, lock);
                // The branch must be the grown tree's (an orphaned edit may still be changed
                // or cleared).
                bool known = false;
                for (const skel::BranchEdit& e : edits)
                    known = known || e.branch == branch;
                if (!known)
                    for (const skel::Branch& b : skel::branchesOf(*grownTree(id).grown))
                        known = known || b.id == branch;
                if (!known)
                    throw InvalidInput("tree " + std::to_string(id) + " has no branch " + branch);
                // The shown tree: the edit's anchor, and a lock's geometry (which needs it).
                const DrawnTree* drawn = nullptr;
                try {
                    drawn = &grownTree(id);
                } catch (const InvalidInput&) {
                    if (edit.lock && edit.locked.empty()) throw;
                }
                applyBranchEdit(document(), drawn, id, edit);
            },
            py::arg("tree_id"), py::arg("branch_id"), py::arg("prune") = py::none(),
            py::arg("bend") = py::none(), py::arg("length") = py::none(),
            py::arg("radius") = py::none(), py::arg("lock") = py::none(),
            "Edits one branch of a hand-placed tree by its id (one undo step): None leaves a "
            "setting; prune=False, bend=(), length=1.0, radius=1.0, lock=False clear it. "
            "ValueError for an unknown tree or branch or a value out of range (length and "
            "radius in [0.05, 20], bend a non-zero world direction).")
        .def(
            "branch_edits",
            [](DocumentApi&, doc::TreeId id) {
                return python::branchEditsList(document().branchEdits(id));
            },
            py::arg("tree_id"), "A hand-placed tree's branch edits as dicts.")
        .def(
            "clear_branch_edits",
            [](DocumentApi&, doc::TreeId id) { document().clearBranchEdits(id); },
            py::arg("tree_id"), "Removes every branch edit of a tree (one undo step).")
        .def(
            "duplicate_trees",
            [](DocumentApi&, const std::vector<doc::TreeId>& ids) {
                const QList<doc::TreeId> out =
                    document().duplicateTrees(QList<doc::TreeId>(ids.begin(), ids.end()));
                return std::vector<doc::TreeId>(out.begin(), out.end());
            },
            py::arg("ids"))
        .def("species", [](DocumentApi&) { return python::speciesNames(document().project()); })
        .def(
            "add_species",
            [](DocumentApi&, const std::string& name, const std::string& file) {
                document().addSpecies(name, QString::fromStdString(file));
            },
            py::arg("name"), py::arg("file"))
        .def("rename_species", [](DocumentApi&, const std::string& from,
                                  const std::string& to) { document().renameSpecies(from, to); })
        .def("remove_species",
             [](DocumentApi&, const std::string& name) { document().removeSpecies(name); })
        .def(
            "set_variants",
            [](DocumentApi&, const std::string& species, int k) {
                document().setSpeciesVariants(species, k);
            },
            py::arg("species"), py::arg("k"))
        .def(
            "get_param",
            [](DocumentApi&, const std::string& species, const std::string& path) {
                return fromValue(document().param(species, path));
            },
            py::arg("species"), py::arg("path"))
        .def(
            "set_param",
            [](DocumentApi&, const std::string& species, const std::string& path,
               py::object value) { document().setParam(species, path, toValue(value)); },
            py::arg("species"), py::arg("path"), py::arg("value"))
        .def(
            "grammar",
            [](DocumentApi&, const std::string& species, const std::string& node) {
                return document().grammar(species, node);
            },
            py::arg("species"), py::arg("node"))
        .def(
            "set_grammar",
            [](DocumentApi&, const std::string& species, const std::string& node,
               const std::string& text) {
                // The edit is kept even with errors (as in the editor); the diagnostics say what
                // is wrong, as (line, column, message) tuples.
                document().setGrammar(species, node, text);
                py::list out;
                for (const Diagnostic& d : lsys::checkGrammar(text, node).diagnostics)
                    out.append(py::make_tuple(d.line, d.column, d.message));
                return out;
            },
            py::arg("species"), py::arg("node"), py::arg("text"),
            "Sets an lsystem node's grammar; returns its diagnostics [(line, column, message)].")
        .def(
            "graph",
            [](DocumentApi&, const std::string& species) {
                return fromValue(document().speciesGraph(species));
            },
            py::arg("species"),
            "The species graph: {'nodes': [{'id', 'type', 'params', 'inputs', ...}], 'output'}.")
        .def(
            "add_node",
            [](DocumentApi&, const std::string& species, const std::string& type, py::object params,
               const std::string& id, std::optional<std::pair<float, float>> at) {
                return document().addNode(
                    species, type,
                    params.is_none() ? sylva::Value(sylva::Value::Object{}) : toValue(params), id,
                    at ? glm::vec2(at->first, at->second) : glm::vec2(0.0f));
            },
            py::arg("species"), py::arg("type"), py::arg("params") = py::none(), py::arg("id") = "",
            py::arg("position") = py::none(), "Adds a node; returns its id.")
        .def(
            "remove_node",
            [](DocumentApi&, const std::string& species, const std::string& id) {
                document().removeNode(species, id);
            },
            py::arg("species"), py::arg("id"))
        .def(
            "connect",
            [](DocumentApi&, const std::string& species, const std::string& from,
               const std::string& to) { document().connectNodes(species, from, to); },
            py::arg("species"), py::arg("source"), py::arg("target"),
            "Feeds source's result into target (replacing a single input); ValueError says why "
            "a connection is refused.")
        .def(
            "disconnect",
            [](DocumentApi&, const std::string& species, const std::string& from,
               const std::string& to) { document().disconnectNodes(species, from, to); },
            py::arg("species"), py::arg("source"), py::arg("target"))
        .def(
            "set_output",
            [](DocumentApi&, const std::string& species, const std::string& id) {
                document().setOutputNode(species, id);
            },
            py::arg("species"), py::arg("id"))
        .def(
            "move_node",
            [](DocumentApi&, const std::string& species, const std::string& id, float x, float y) {
                document().moveNode(species, id, glm::vec2(x, y));
            },
            py::arg("species"), py::arg("id"), py::arg("x"), py::arg("y"))
        .def(
            "preview_ms",
            [](DocumentApi&) -> py::object {
                // The species editor's last edit → new preview mesh on screen. A measured time is
                // never exactly 0; 0 means no preview ran (the species editor was never open),
                // which must not read as "instant".
                SpeciesPreview* p = window().workbench()->preview();
                if (p->failed()) return py::none();
                if (p->editToScreenMs() > 0.0) return py::float_(p->editToScreenMs());
                if (p->editToResultMs() > 0.0) return py::float_(p->editToResultMs());
                return py::none();
            },
            "Milliseconds from the last edit to the species preview's new mesh on screen; None "
            "when no preview ran.")
        .def(
            "preview_stats",
            [](DocumentApi&) {
                SpeciesPreview* p = window().workbench()->preview();
                py::dict d;
                d["edit_to_result_ms"] = p->editToResultMs();
                d["edit_to_screen_ms"] = p->editToScreenMs();
                d["evaluate_ms"] = p->result().evaluateMs;
                py::dict runs;
                for (const auto& [id, run] : p->result().runs)
                    runs[py::str(id)] = py::make_tuple(run.ran, run.ms, run.evaluations);
                d["nodes"] = runs;
                const PreviewResult& r = p->result();
                d["species"] = r.species.toStdString();
                d["error"] = r.error.isEmpty() ? py::object(py::none())
                                               : py::object(py::str(r.error.toStdString()));
                d["error_node"] = r.errorNode.toStdString();
                d["triangles"] = r.mesh ? r.mesh->triangleCount() : 0;
                d["vertices"] = r.mesh ? r.mesh->vertexCount() : 0;
                // What the preview pane draws: the result's own mesh, not another tree.
                const auto& shown = window().workbench()->previewViewport()->shownMesh();
                d["shown_is_result"] = shown != nullptr && shown == r.mesh;
                std::uint64_t hash = 1469598103934665603ull; // FNV-1a over the positions
                if (shown)
                    for (const glm::vec3& v : shown->positions)
                        for (float c : {v.x, v.y, v.z}) {
                            std::uint32_t bits;
                            std::memcpy(&bits, &c, sizeof bits);
                            hash = (hash ^ bits) * 1099511628211ull;
                        }
                d["shown_hash"] = hash;
                // The stages after the result: the upload of the new mesh and its frame
                // (upload included), on the GUI thread.
                const Viewport* view = window().workbench()->previewViewport();
                d["upload_ms"] = view->lastUploadMs();
                d["frame_ms"] = view->lastPaintMs();
                d["present_ms"] = view->lastPresentMs();
                // What is left of edit → screen: from the result to its frame's start (the GUI
                // thread busy with other work, the window's update request).
                const double screen = p->editToScreenMs();
                d["wait_ms"] = screen > 0.0
                                   ? std::max(0.0, screen - p->editToResultMs() -
                                                       view->lastPaintMs() - view->lastPresentMs())
                                   : 0.0;
                return d;
            },
            "The last preview: edit → result and → screen, the evaluation alone, per node (ran, "
            "ms, evaluations), its species, error (None when it succeeded) and failing node, its "
            "triangles and vertices, whether the pane shows that very mesh (shown_is_result) and "
            "a hash of the positions it shows (shown_hash), and the GUI thread's stages: the "
            "mesh's "
            "upload (upload_ms), the frame that drew it (frame_ms, upload included), the window "
            "system's present after it (present_ms) and the wait from the result to that frame "
            "(wait_ms).")
        .def("obstacles",
             [](DocumentApi&) { return python::obstaclesList(document().project().obstacles); })
        .def(
            "add_obstacle",
            [](DocumentApi&, const std::string& file, py::object translate, py::object rotate,
               py::object scale) {
                doc::ProjectObstacle o;
                o.file = file;
                python::applyTransform(o, translate, rotate, scale);
                document().addObstacle(o);
                return document().project().obstacles.size() - 1;
            },
            py::arg("file"), py::arg("translate") = py::none(), py::arg("rotate") = py::none(),
            py::arg("scale") = py::none())
        .def(
            "set_obstacle",
            [](DocumentApi&, int index, py::object translate, py::object rotate, py::object scale) {
                const auto& all = document().project().obstacles;
                if (index < 0 || index >= int(all.size()))
                    throw InvalidInput("there is no obstacle " + std::to_string(index));
                doc::ProjectObstacle o = all[std::size_t(index)];
                python::applyTransform(o, translate, rotate, scale);
                document().setObstacle(index, o);
            },
            py::arg("index"), py::arg("translate") = py::none(), py::arg("rotate") = py::none(),
            py::arg("scale") = py::none())
        .def("remove_obstacle", [](DocumentApi&, int index) { document().removeObstacle(index); })
        .def("domains",
             [](DocumentApi&) { return python::domainsList(document().project().domains); })
        .def(
            "set_domain",
            [](DocumentApi&, int index, std::optional<std::map<std::string, int>> counts,
               py::object min, py::object max) {
                const auto& all = document().project().domains;
                if (index < 0 || index >= int(all.size()))
                    throw InvalidInput("there is no domain " + std::to_string(index));
                doc::PlacementDomain d = all[std::size_t(index)];
                if (counts) d.counts = *counts;
                if (!min.is_none()) d.min = python::toXZ(min, "min");
                if (!max.is_none()) d.max = python::toXZ(max, "max");
                document().setDomain(index, d);
            },
            py::arg("index"), py::arg("counts") = py::none(), py::arg("min") = py::none(),
            py::arg("max") = py::none())
        .def_property(
            "seed", [](DocumentApi&) { return document().project().seed; },
            [](DocumentApi&, std::uint64_t seed) { document().setSeed(seed); })
        .def_property(
            "season", [](DocumentApi&) { return python::seasonTo(document().project().season); },
            [](DocumentApi&, const py::object& season) {
                document().setSeason(python::seasonFrom(season));
            },
            "The project's season ('spring', 'summer', 'autumn', 'winter'; None: each species' "
            "own); setting it is one undo step.")
        .def(
            "set_camera",
            [](DocumentApi&, py::object position, py::object target) {
                document().setCamera(toVec3(position, "position"), toVec3(target, "target"));
            },
            py::arg("position"), py::arg("target"))
        .def("camera",
             [](DocumentApi&) {
                 return py::make_tuple(fromVec3(document().project().cameraPosition),
                                       fromVec3(document().project().cameraTarget));
             })
        .def(
            "set_light",
            [](DocumentApi&, py::object direction) {
                document().setLight(toVec3(direction, "direction"));
            },
            py::arg("direction"))
        .def(
            "set_wind",
            [](DocumentApi&, py::object direction, py::object strength, py::object gustiness,
               py::object frequency) {
                // Settings not given keep the project's (or, when it has none, the default's).
                wind::WindSettings w = document().project().wind.value_or(wind::WindSettings{});
                if (!direction.is_none()) w.direction = toVec3(direction, "direction");
                if (!strength.is_none()) w.strength = strength.cast<float>();
                if (!gustiness.is_none()) w.gustiness = gustiness.cast<float>();
                if (!frequency.is_none()) w.frequency = frequency.cast<float>();
                document().setWind(w);
            },
            py::arg("direction") = py::none(), py::arg("strength") = py::none(),
            py::arg("gustiness") = py::none(), py::arg("frequency") = py::none(),
            "Sets the project's wind (one undo step); settings not given are kept.")
        .def(
            "clear_wind", [](DocumentApi&) { document().setWind(std::nullopt); },
            "Unsets the project's wind (the engine's default; nothing saved); one undo step.")
        .def(
            "wind", [](DocumentApi&) { return python::windTo(document().project().wind); },
            "The project's wind as a dict (direction, strength, gustiness, frequency), or None.")
        .def("undo", [](DocumentApi&) { document().undoStack()->undo(); })
        .def("redo", [](DocumentApi&) { document().undoStack()->redo(); })
        .def("undo_count", [](DocumentApi&) { return document().undoStack()->index(); })
        .def("undo_texts",
             [](DocumentApi&) {
                 std::vector<std::string> out;
                 const QUndoStack* s = document().undoStack();
                 for (int i = 0; i < s->index(); ++i)
                     out.push_back(s->text(i).toStdString());
                 return out;
             })
        .def("selection",
             [](DocumentApi&) {
                 const QList<doc::TreeId> ids = document().selectedTrees();
                 return std::vector<doc::TreeId>(ids.begin(), ids.end());
             })
        .def(
            "selected_branch",
            [](DocumentApi&) -> py::object {
                const auto& b = document().selectedBranch();
                if (!b) return py::none();
                return py::make_tuple(b->tree, b->branch);
            },
            "The branch the Branch tool selected: (tree_id, branch_id), or None.")
        .def(
            "select_branch",
            [](DocumentApi&, doc::TreeId id, const std::string& branch) {
                bool known = false;
                for (const skel::Branch& b : skel::branchesOf(*grownTree(id).grown))
                    known = known || b.id == branch;
                if (!known)
                    throw InvalidInput("tree " + std::to_string(id) + " has no branch " + branch);
                document().setSelectedBranch(doc::Document::BranchRef{id, branch});
            },
            py::arg("tree_id"), py::arg("branch_id"),
            "Selects a branch as a click of the Branch tool does.")
        .def(
            "select",
            [](DocumentApi&, const std::vector<doc::TreeId>& ids) {
                document().selectTrees(QList<doc::TreeId>(ids.begin(), ids.end()));
            },
            py::arg("ids"))
        .def(
            "serialized", [](DocumentApi&) { return document().serialized().toStdString(); },
            "The project as it would be saved (canonical JSON).")
        .def(
            "generate", [](DocumentApi&) { return generate(); },
            "Waits for the current generation; returns its statistics.")
        .def(
            "export",
            [](DocumentApi&, const std::string& path, bool selectionOnly, bool viewportCamera) {
                generate();
                if (!window().exportTo(QString::fromStdString(path),
                                       {selectionOnly, viewportCamera}))
                    throw IoError(window().lastError().toStdString());
            },
            py::arg("path"), py::arg("selection_only") = false, py::arg("viewport_camera") = false);

    py::class_<WindowApi>(m, "Window", "The editor's window.")
        .def(
            "screenshot",
            [](WindowApi&, const std::string& path, bool viewportOnly) {
                // What the last edit made, not the forest before it: wait for its generation
                // (and the Statistics and Outliner it updates) before grabbing.
                MainWindow& w = window();
                pumpUntil(600.0, [&w] { return !w.isGenerating(); });
                QApplication::processEvents();
                const bool ok = viewportOnly
                                    ? window().saveScreenshot(QString::fromStdString(path))
                                    : window().saveWindowScreenshot(QString::fromStdString(path));
                if (!ok) throw IoError(window().lastError().toStdString());
            },
            py::arg("path"), py::arg("viewport_only") = false,
            "Saves the window (or only the 3D view) as a PNG, after the generation of the last "
            "edit has finished, so the picture shows the document as it is now.")
        .def("resize", [](WindowApi&, int w, int h) { window().resize(w, h); })
        .def(
            "edit_species",
            [](WindowApi&, const std::string& species) {
                if (!species.empty() && document().speciesIndex(species) < 0)
                    throw InvalidInput("unknown species '" + species + "'");
                window().editSpecies(QString::fromStdString(species));
            },
            py::arg("species") = "",
            "Shows the species editor (graph, grammar, preview, node parameters) on a species.")
        .def(
            "select_node",
            [](WindowApi&, const std::string& id) {
                window().workbench()->graphScene()->selectNode(QString::fromStdString(id));
            },
            py::arg("id"), "Selects a node in the species editor (its parameters and grammar).")
        .def(
            "wait_for_preview",
            [](WindowApi&, double timeout) {
                SpeciesPreview* p = window().workbench()->preview();
                pumpUntil(timeout, [p] { return !p->isBusy(); });
                for (int k = 0; k < 5; ++k)
                    QApplication::processEvents(QEventLoop::AllEvents, 20);
                return !p->isBusy() && !p->failed();
            },
            py::arg("timeout") = 60.0,
            "Waits until the species preview is up to date; False when it timed out or the "
            "preview failed (the error is on the preview pane and in Messages).")
        .def(
            "set_tool",
            [](WindowApi&, const std::string& name) {
                ToolController::Tool tool;
                if (!ToolController::fromName(QString::fromStdString(name), tool))
                    throw InvalidInput("unknown tool '" + name +
                                       "' (select, move, place, brush, erase, branch)");
                window().tools().setTool(tool);
            },
            py::arg("name"), "select, move, place, brush, erase or branch, as the toolbar.")
        .def("tool",
             [](WindowApi&) { return ToolController::name(window().tools().tool()).toStdString(); })
        .def(
            "set_place_species",
            [](WindowApi&, const std::string& species) {
                if (document().speciesIndex(species) < 0)
                    throw InvalidInput("unknown species '" + species + "'");
                window().tools().setPlaceSpecies(species);
            },
            py::arg("species"))
        .def(
            "set_brush",
            [](WindowApi&, std::optional<float> radius, std::optional<float> density,
               std::optional<std::map<std::string, double>> mix) {
                ToolController::Brush brush = window().tools().brush();
                if (radius) brush.radius = *radius;
                if (density) brush.density = *density;
                if (mix) brush.mix.assign(mix->begin(), mix->end());
                window().tools().setBrush(brush);
            },
            py::arg("radius") = py::none(), py::arg("density") = py::none(),
            py::arg("mix") = py::none(), "Brush radius (m), density (trees per 100 m2), mix.")
        .def(
            "project",
            [](WindowApi&, float x, float y, float z) -> py::object {
                layOut(window());
                Viewport* v = window().viewport();
                const auto p = v->project({x, y, z});
                if (!p) return py::none();
                const QPoint global = v->mapToGlobal(p->toPoint());
                return py::make_tuple(global.x(), global.y());
            },
            py::arg("x"), py::arg("y"), py::arg("z"),
            "Where a world point is drawn, in global screen pixels (what xdotool takes), or None; "
            "for the window as it is shown (its layout is applied first).")
        .def(
            "branch_at",
            [](WindowApi&, int x, int y) -> py::object {
                layOut(window());
                Viewport* v = window().viewport();
                const auto hit =
                    window().tools().branchTool().branchAt(v->mapFromGlobal(QPoint(x, y)));
                if (!hit) return py::none();
                return py::make_tuple(hit->tree, hit->branch);
            },
            py::arg("x"), py::arg("y"),
            "The branch the Branch tool would select at global screen pixel (x, y) (what "
            "win.project gives): (tree_id, branch_id), or None.")
        .def(
            "look_from",
            [](WindowApi&, py::object eye, py::object target) {
                window().viewport()->setViewFrom(toVec3(eye, "eye"), toVec3(target, "target"));
                window().viewport()->frameScene();
                window().viewport()->camera().lookFrom(toVec3(eye, "eye"),
                                                       toVec3(target, "target"));
                window().viewport()->update();
            },
            py::arg("eye"), py::arg("target"),
            "Points the viewport's camera (a view, not the project camera: doc.set_camera).")
        .def(
            "measure_frames",
            [](WindowApi&, int frames, double orbit) {
                if (frames < 1 || frames > 100000)
                    throw InvalidInput("measure_frames takes 1 to 100000 frames");
                if (!std::isfinite(orbit) || std::abs(orbit) > 90.0)
                    throw InvalidInput("measure_frames' orbit is -90 to 90 degrees a frame");
                const MainWindow::FrameStats f = window().measureFrames(frames, float(orbit));
                py::dict d;
                d["fps"] = f.fps;
                d["ms_per_frame"] = f.msPerFrame;
                d["cpu_ms_per_frame"] = f.cpuMsPerFrame;
                d["gui_cpu_ms_per_frame"] = f.guiCpuMsPerFrame;
                d["trees_drawn"] = f.treesDrawn;
                d["triangles"] = f.triangles;
                d["triangles_drawn"] = f.trianglesDrawn;
                d["trees_per_level"] = f.treesPerLevel;
                d["triangles_per_level"] = f.trianglesPerLevel;
                d["motion_trees"] = f.motionTrees;
                return d;
            },
            py::arg("frames") = 60, py::arg("orbit") = 4.0,
            "Orbits the view by orbit degrees per frame (0: a still camera, each frame drawn "
            "again) and measures frames per second and CPU time.")
        .def(
            "wait_view_lod",
            [](WindowApi&, double seconds) {
                QElapsedTimer clock;
                clock.start();
                Viewport* v = window().viewport();
                v->update();
                QCoreApplication::processEvents();
                pumpUntil(seconds - 1e-3 * double(clock.elapsed()),
                          [v] { return v->lodPending() == 0; });
                QCoreApplication::processEvents();
                return v->lodPending() == 0;
            },
            py::arg("timeout") = 120.0,
            "Waits (the window stays live) until the viewport's coarser levels of detail are "
            "made; False when some are still being made after timeout seconds.")
        .def(
            "set_view_lod",
            [](WindowApi&, bool on) {
                window().viewport()->lod().setEnabled(on);
                window().viewport()->update();
            },
            py::arg("on"), "Turns the viewport's distance level of detail on or off.")
        .def(
            "set_view_wind", [](WindowApi&, bool on) { window().setViewWind(on); }, py::arg("on"),
            "View > Wind: the viewport and the species preview sway their trees in the "
            "project's wind (doc.set_wind).")
        .def(
            "view_wind", [](WindowApi&) { return window().viewWind(); },
            "Whether View > Wind is on.")
        .def(
            "set_wind_time",
            [](WindowApi&, std::optional<double> seconds) {
                if (seconds && !std::isfinite(*seconds))
                    throw py::value_error("wind time must be a finite number of seconds");
                window().setWindTime(seconds);
            },
            py::arg("seconds"),
            "Freezes the views' wind clock at this many seconds (the same time draws the same "
            "frame: scripts, tests, pictures); None lets it run with the wall clock again.")
        .def(
            "wind_time", [](WindowApi&) { return window().viewport()->windTime(); },
            "The viewport's wind clock, in seconds.")
        .def(
            "set_back_face_culling",
            [](WindowApi&, bool on) {
                window().viewport()->setBackFaceCulling(on);
                if (Viewport* preview = window().workbench()->previewViewport())
                    preview->setBackFaceCulling(on);
            },
            py::arg("on"),
            "Culls the back faces of the bark tubes in the viewport and the species preview (on "
            "by default; off only to compare: the picture is the same).")
        .def(
            "regenerate_all", [](WindowApi&) { window().generator().regenerateAll(); },
            "Drops every cached tree and regrows the whole document (File > Reload).")
        .def(
            "last_update_ms", [](WindowApi&) { return window().lastEditToScreenMs(); },
            "Milliseconds from the last edit to its new meshes on screen.")
        .def(
            "autosave",
            [](WindowApi&) {
                const bool saved = window().autosave().saveNow();
                return saved ? window().autosave().recoveryFile().toStdString() : std::string();
            },
            "Writes the autosave copy now; its path, or '' when there was nothing unsaved.")
        .def(
            "generating", [](WindowApi&) { return window().isGenerating(); },
            "Whether a generation (or a species regrowth) is running or about to start.")
        .def(
            "view_camera",
            [](WindowApi&) {
                const OrbitCamera& c = window().viewport()->camera();
                return py::make_tuple(fromVec3(c.eye()), fromVec3(c.target()));
            },
            "The 3D view's camera as it is now: (eye, target), world metres.")
        .def(
            "status",
            [](WindowApi&) {
                return py::make_tuple(window().statusBar()->currentMessage().toStdString(),
                                      window().generationError().toStdString());
            },
            "The status bar: (its transient line, the failed generation it keeps showing or '').")
        .def("messages", [](WindowApi&) {
            std::vector<std::string> out;
            for (int i = 0; i < window().messages()->count(); ++i)
                out.push_back(window().messages()->message(i).toStdString());
            return out;
        });

    m.def(
        "document", [] { return DocumentApi{}; }, "The open document.");
    m.def(
        "window", [] { return WindowApi{}; }, "The editor's window.");
    m.def(
        "wait",
        [](double seconds) {
            if (seconds < 0 || seconds > 86400)
                throw InvalidInput("wait() takes 0 to 86400 seconds");
            pumpUntil(seconds, [] { return false; });
        },
        py::arg("seconds"), "Keeps the window (and autosave) running for a while.");
    m.def(
        "quit",
        [](int code) {
            PyErr_SetObject(PyExc_SystemExit, py::int_(code).ptr());
            throw py::error_already_set();
        },
        py::arg("code") = 0, "Leaves the editor with this exit status.");
    m.attr("__version__") = QApplication::applicationVersion().toStdString();
}
