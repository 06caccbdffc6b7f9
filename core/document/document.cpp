#include "document/document.h"

#include "document/linkedfiles.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <set>

#include <QDir>
#include <QFile>
#include <QFileInfo>

#include "document/commands/scenecommands.h"
#include "document/commands/speciescommands.h"
#include "document/commands/treecommands.h"
#include "document/filerefs.h"
#include "document/projectsettings.h"
#include "document/speciesfile.h"
#include "document/speciesgraphedit.h"
#include "engine/graph/graph.h"
#include "engine/mesh/season.h"
#include "engine/util/error.h"
#include "engine/util/random.h"
#include "engine/wind/windmodel.h"

namespace sylva::doc {

using sylva::Value;

Document::Document(QObject* parent) : QObject(parent) {
    connect(&mUndo, &QUndoStack::cleanChanged, this, &Document::titleChanged);
    newProject();
}

Document::~Document() = default;

QString Document::displayName() const {
    return mPath.isEmpty() ? tr("Untitled") : QFileInfo(mPath).fileName();
}

void Document::replace(Project project, const QString& path) {
    mUndo.clear();
    mProject = std::move(project);
    mPath = path;
    assignIds(mProject);
    mTreeIds.clear();
    for (const ProjectInstance& t : mProject.instances)
        mTreeIds.push_back(static_cast<TreeId>(t.id));
    mSelection.clear();
    mSelectedBranch.reset();
    mUndo.setClean();
    emitChange(DocumentChange::Reset);
    Q_EMIT selectionChanged();
    Q_EMIT titleChanged();
}

void Document::newProject() {
    Project p;
    p.baseDir = QDir::currentPath();
    replace(std::move(p), {});
}

std::vector<std::string> Document::open(const QString& path) {
    LoadReport report;
    Project p = loadProjectOrScene(path, &report); // throws: nothing changed yet
    // Every linked file (species, grammar, mesh) is read and checked before the open project
    // is replaced: a bad one leaves it exactly as it was (bytes, path, undo history).
    checkLinkedFiles(p);
    replace(std::move(p), QFileInfo(path).absoluteFilePath());
    std::vector<std::string> messages = report.warnings;
    messages.insert(messages.end(), report.upgrades.begin(), report.upgrades.end());
    return messages;
}

void Document::save(const QString& path) {
    const QString target = QFileInfo(path.isEmpty() ? mPath : path).absoluteFilePath();
    if (target.isEmpty() || (path.isEmpty() && mPath.isEmpty()))
        throw IoError("the document has no file yet: save it under a name");
    Project copy = rebaseProject(mProject, QFileInfo(target).absolutePath());
    saveProject(copy, target); // atomic; throws IoError and leaves the document as it was
    const bool moved = copy.baseDir != mProject.baseDir;
    mProject = std::move(copy);
    mPath = target;
    mUndo.setClean();
    if (moved) emitChange(DocumentChange::Reset);
    Q_EMIT titleChanged();
}

void Document::restore(Project project, const QString& path) {
    replace(std::move(project), path);
    mUndo.resetClean(); // the restored edits are not saved anywhere yet
    Q_EMIT titleChanged();
}

// --- trees ------------------------------------------------------------------------------

TreeId Document::nextTreeId() const {
    if (mProject.nextTreeId > kMaxTreeId)
        throw LimitExceeded("a project's tree ids are limited to " + std::to_string(kMaxTreeId));
    return static_cast<TreeId>(mProject.nextTreeId);
}

int Document::treeIndex(TreeId id) const {
    const auto it = std::find(mTreeIds.begin(), mTreeIds.end(), id);
    return it == mTreeIds.end() ? -1 : static_cast<int>(it - mTreeIds.begin());
}

const ProjectInstance& Document::tree(TreeId id) const {
    const int i = treeIndex(id);
    if (i < 0) throw InvalidInput("there is no tree with id " + std::to_string(id));
    return mProject.instances[static_cast<std::size_t>(i)];
}

namespace {

void checkBranchEdits(const std::vector<skel::BranchEdit>& edits) {
    std::set<std::string> seen;
    for (const skel::BranchEdit& e : edits) {
        checkBranchEdit(e, "branch edit");
        if (!seen.insert(e.branch).second)
            throw InvalidInput("branch " + e.branch + " is edited twice");
    }
}

} // namespace

void Document::validateTree(const ProjectInstance& t) const {
    if (speciesIndex(t.species) < 0) {
        std::string known;
        for (const ProjectSpecies& s : mProject.species)
            known += (known.empty() ? "" : ", ") + s.name;
        throw InvalidInput("unknown species '" + t.species + "' (the project has: " +
                           (known.empty() ? std::string("none") : known) + ")");
    }
    for (int k = 0; k < 3; ++k)
        requireRange("tree position (m)", t.position[k], -1e6, 1e6);
    requireRange("tree rotation (degrees)", t.rotation, -1e6, 1e6);
    requireRange("tree scale", t.scale, 0.01, 100);
    requireRange("tree growth", t.growth, 0.01, 1);
    if (!t.season.empty()) (void)mesh::parseSeason(t.season);
    checkBranchEdits(t.branchEdits);
}

TreeId Document::addTree(const ProjectInstance& t) {
    validateTree(t);
    const TreeId id = nextTreeId();
    mUndo.push(new cmd::AddTree(*this, static_cast<int>(mTreeIds.size()), id, t));
    return id;
}

void Document::setTree(TreeId id, const ProjectInstance& t, bool commit) {
    (void)tree(id);
    validateTree(t);
    ProjectInstance same = t; // a tree keeps its id whatever the caller's copy says
    same.id = id;
    mUndo.push(cmd::changeTree(*this, id, same, commit));
}

void Document::removeTrees(const QList<TreeId>& ids) {
    for (TreeId id : ids)
        (void)tree(id);
    if (ids.isEmpty()) return;
    mUndo.beginMacro(ids.size() == 1 ? QCoreApplication::translate("Commands", "Remove tree")
                                     : QCoreApplication::translate("Commands", "Remove trees"));
    for (TreeId id : ids)
        mUndo.push(new cmd::RemoveTree(*this, id));
    mUndo.endMacro();
}

QList<TreeId> Document::duplicateTrees(const QList<TreeId>& ids, glm::vec3 offset) {
    for (TreeId id : ids)
        (void)tree(id);
    QList<TreeId> created;
    if (ids.isEmpty()) return created;
    mUndo.beginMacro(ids.size() == 1 ? QCoreApplication::translate("Commands", "Duplicate tree")
                                     : QCoreApplication::translate("Commands", "Duplicate trees"));
    for (TreeId id : ids) {
        ProjectInstance copy = tree(id);
        copy.position += offset;
        // A fresh seed that depends only on the document's state, so scripts are repeatable.
        copy.seed = treeSeed(mixSeed(copy.seed, mProject.nextTreeId));
        const TreeId newId = nextTreeId();
        mUndo.push(new cmd::AddTree(*this, static_cast<int>(mTreeIds.size()), newId, copy));
        created << newId;
    }
    mUndo.endMacro();
    return created;
}

void Document::rawInsertTree(int index, TreeId id, const ProjectInstance& t) {
    mProject.instances.insert(mProject.instances.begin() + index, t);
    mProject.instances[static_cast<std::size_t>(index)].id = id;
    mProject.nextTreeId = std::max<std::uint64_t>(mProject.nextTreeId, std::uint64_t(id) + 1);
    mTreeIds.insert(mTreeIds.begin() + index, id);
    emitChange(DocumentChange::Trees, {id});
}

ProjectInstance Document::rawRemoveTree(TreeId id) {
    const int i = treeIndex(id);
    ProjectInstance t = mProject.instances[static_cast<std::size_t>(i)];
    mProject.instances.erase(mProject.instances.begin() + i);
    mTreeIds.erase(mTreeIds.begin() + i);
    pruneSelection();
    emitChange(DocumentChange::Trees, {id});
    return t;
}

const std::vector<skel::BranchEdit>& Document::branchEdits(TreeId id) const {
    return tree(id).branchEdits;
}

void Document::setBranchEdits(TreeId id, const std::vector<skel::BranchEdit>& edits) {
    (void)tree(id);
    checkBranchEdits(edits);
    mUndo.push(cmd::changeBranchEdits(*this, id, edits));
}

void Document::editBranch(TreeId id, const skel::BranchEdit& edit) {
    checkBranchEdit(edit, "branch edit");
    std::vector<skel::BranchEdit> edits = tree(id).branchEdits;
    auto same = std::find_if(edits.begin(), edits.end(),
                             [&](const skel::BranchEdit& e) { return e.branch == edit.branch; });
    if (isEmptyEdit(edit)) {
        if (same != edits.end()) edits.erase(same);
    } else if (same != edits.end()) {
        *same = edit;
    } else {
        edits.push_back(edit);
    }
    setBranchEdits(id, edits);
}

void Document::clearBranchEdits(TreeId id) {
    setBranchEdits(id, {});
}

void Document::rawSetBranchEdits(TreeId id, const std::vector<skel::BranchEdit>& edits) {
    mProject.instances[static_cast<std::size_t>(treeIndex(id))].branchEdits = edits;
    emitChange(DocumentChange::Trees, {id});
}

void Document::rawSetTree(TreeId id, const ProjectInstance& t) {
    mProject.instances[static_cast<std::size_t>(treeIndex(id))] = t;
    mProject.instances[static_cast<std::size_t>(treeIndex(id))].id = id;
    emitChange(DocumentChange::Trees, {id});
}

// --- species ----------------------------------------------------------------------------

int Document::speciesIndex(const std::string& name) const {
    for (std::size_t i = 0; i < mProject.species.size(); ++i)
        if (mProject.species[i].name == name) return static_cast<int>(i);
    return -1;
}

void Document::addSpecies(const std::string& name, const QString& file) {
    if (name.empty()) throw InvalidInput("a species needs a name");
    if (speciesIndex(name) >= 0)
        throw InvalidInput("the project already has a species '" + name + "'");
    ProjectSpecies s;
    s.name = name;
    const QString absolute = QFileInfo(file).absoluteFilePath();
    (void)loadSpecies(absolute); // throws InvalidInput / IoError: nothing added
    s.file = relativeTo(mProject.baseDir, absolute);
    mUndo.push(new cmd::ListEdit<ProjectSpecies>(
        *this, false, static_cast<int>(mProject.species.size()), s,
        [](Document& d, int i, const ProjectSpecies& v) { d.rawInsertSpecies(i, v); },
        [](Document& d, int i) { d.rawRemoveSpecies(i); },
        QCoreApplication::translate("Commands", "Add species")));
}

void Document::renameSpecies(const std::string& from, const std::string& to) {
    const int i = speciesIndex(from);
    if (i < 0) throw InvalidInput("unknown species '" + from + "'");
    if (to.empty()) throw InvalidInput("a species needs a name");
    if (to == from) return;
    if (speciesIndex(to) >= 0) throw InvalidInput("the project already has a species '" + to + "'");
    mUndo.beginMacro(QCoreApplication::translate("Commands", "Rename species"));
    ProjectSpecies renamed = mProject.species[static_cast<std::size_t>(i)];
    renamed.name = to;
    mUndo.push(cmd::changeSpecies(*this, i, mProject.species[static_cast<std::size_t>(i)], renamed,
                                  {}, true,
                                  QCoreApplication::translate("Commands", "Rename species")));
    for (std::size_t k = 0; k < mProject.instances.size(); ++k) {
        if (mProject.instances[k].species != from) continue;
        ProjectInstance t = mProject.instances[k];
        t.species = to;
        mUndo.push(cmd::changeTree(*this, mTreeIds[k], t, true));
    }
    for (std::size_t k = 0; k < mProject.domains.size(); ++k) {
        auto it = mProject.domains[k].counts.find(from);
        if (it == mProject.domains[k].counts.end()) continue;
        PlacementDomain d = mProject.domains[k];
        d.counts.erase(from);
        d.counts[to] = it->second;
        mUndo.push(cmd::changeDomain(*this, static_cast<int>(k), d, true));
    }
    mUndo.endMacro();
}

void Document::setSpeciesVariants(const std::string& species, int variants) {
    const int i = speciesIndex(species);
    if (i < 0) throw InvalidInput("unknown species '" + species + "'");
    const SettingSpec& spec = settings::kVariants;
    if (variants < spec.min || variants > spec.max)
        throw InvalidInput("variants of species '" + species + "' must be " +
                           std::to_string(int(spec.min)) + " to " + std::to_string(int(spec.max)) +
                           ", not " + std::to_string(variants));
    const ProjectSpecies& old = mProject.species[static_cast<std::size_t>(i)];
    if (old.variants == variants) return;
    ProjectSpecies changed = old;
    changed.variants = variants;
    mUndo.push(cmd::changeSpecies(*this, i, old, changed, {}, true,
                                  QCoreApplication::translate("Commands", "Change variants")));
}

void Document::removeSpecies(const std::string& name) {
    const int i = speciesIndex(name);
    if (i < 0) throw InvalidInput("unknown species '" + name + "'");
    for (const ProjectInstance& t : mProject.instances)
        if (t.species == name)
            throw InvalidInput("species '" + name + "' is used by trees: remove them first");
    for (const PlacementDomain& d : mProject.domains)
        if (d.counts.count(name))
            throw InvalidInput("species '" + name + "' is used by a domain: remove it there first");
    mUndo.push(new cmd::ListEdit<ProjectSpecies>(
        *this, true, i, mProject.species[static_cast<std::size_t>(i)],
        [](Document& d, int k, const ProjectSpecies& v) { d.rawInsertSpecies(k, v); },
        [](Document& d, int k) { d.rawRemoveSpecies(k); },
        QCoreApplication::translate("Commands", "Remove species")));
}

ProjectSpecies Document::inlined(const ProjectSpecies& s) const {
    if (s.graph) return s;
    ProjectSpecies out = inlineSpeciesFile(s.name, mProject.resolve(s.file), mProject.baseDir);
    out.variants = s.variants; // the project's setting, not the file's
    return out;
}

Value Document::speciesGraph(const std::string& name) const {
    const int i = speciesIndex(name);
    if (i < 0) throw InvalidInput("unknown species '" + name + "'");
    return *inlined(mProject.species[static_cast<std::size_t>(i)]).graph;
}

Value Document::param(const std::string& species, const std::string& path) const {
    const auto [node, key] = splitParamPath(path);
    return nodeParam(speciesGraph(species), species, node, key);
}

graph::SpeciesGraph Document::toEngine(const ProjectSpecies& s) const {
    return speciesFromGraph(s.name, *s.graph, s.traits, mProject.baseDir);
}

graph::SpeciesGraph Document::engineSpecies(const std::string& name) const {
    const int i = speciesIndex(name);
    if (i < 0) throw InvalidInput("unknown species '" + name + "'");
    return toEngine(inlined(mProject.species[static_cast<std::size_t>(i)]));
}

void Document::validateSpecies(const ProjectSpecies& s) const {
    graph::registerBuiltinNodeTypes();
    graph::Evaluator(toEngine(s)).validate();
}

void Document::setParam(const std::string& species, const std::string& path, const Value& value,
                        bool commit) {
    // Named copies, not structured bindings: clang 14 (the fuzz build) cannot capture bindings.
    const auto parts = splitParamPath(path);
    const std::string node = parts.first;
    const std::string key = parts.second;
    editGraph(species, QString::fromStdString(node),
              key == "grammar" ? QCoreApplication::translate("Commands", "Edit grammar")
                               // "Change leaf scale (mesh)": the parameter in words, then its node.
                               : QCoreApplication::translate("Commands", "Change %1 (%2)")
                                     .arg(QString::fromStdString(graph::paramWords(key)),
                                          QString::fromStdString(node)),
              commit, [&](Value& g) { setNodeParam(g, species, node, key, value); });
}

void Document::applyPreset(const std::string& species, const QString& file) {
    const int i = speciesIndex(species);
    if (i < 0) throw InvalidInput("unknown species '" + species + "'");
    const ProjectSpecies& old = mProject.species[static_cast<std::size_t>(i)];
    ProjectSpecies applied = inlineSpeciesFile(old.name, file, mProject.baseDir);
    applied.variants = old.variants; // a preset is the tree; K stays the project's
    validateSpecies(applied);
    if (applied == old) return;
    mUndo.push(cmd::changeSpecies(*this, i, old, applied, {}, true,
                                  QCoreApplication::translate("Commands", "Apply preset %1")
                                      .arg(QFileInfo(file).completeBaseName())));
}

void Document::saveSpeciesAs(const std::string& species, const QString& path) const {
    const int i = speciesIndex(species);
    if (i < 0) throw InvalidInput("unknown species '" + species + "'");
    const ProjectSpecies s = inlined(mProject.species[static_cast<std::size_t>(i)]);
    // Self-contained: a grammar file's text goes into the file; other files are rebased.
    Value graphValue =
        standaloneGraph(*s.graph, [&](const std::string& node) { return grammar(species, node); });
    rebaseGraphFiles(graphValue, mProject.baseDir, QFileInfo(path).absolutePath());
    writeSpeciesFile(path, speciesEnvelope(s.name, std::move(graphValue), s.traits));
}

void Document::editGraph(const std::string& species, const QString& node, const QString& label,
                         bool commit, const std::function<void(Value&)>& edit) {
    editSpecies(species, node, label, commit, [&](ProjectSpecies& s) { edit(*s.graph); });
}

void Document::editSpecies(const std::string& species, const QString& node, const QString& label,
                           bool commit, const std::function<void(ProjectSpecies&)>& edit) {
    const int i = speciesIndex(species);
    if (i < 0) throw InvalidInput("unknown species '" + species + "'");
    const ProjectSpecies& old = mProject.species[static_cast<std::size_t>(i)];
    ProjectSpecies edited = inlined(old);
    edit(edited);
    validateSpecies(edited); // unknown parameter, a graph the engine refuses: nothing changes
    // An unchanged value that commits still goes on: it closes a drag or a burst of typing (it
    // merges into the open step, or is dropped as obsolete).
    if (edited == old && !commit) return;
    mUndo.push(cmd::changeSpecies(*this, i, old, edited, node, commit, label));
}

std::string Document::addNode(const std::string& species, const std::string& type,
                              const Value& params, const std::string& id, glm::vec2 position) {
    requireNodeType(type);
    const Value current = speciesGraph(species);
    const std::string newId = id.empty() ? freshNodeId(current, type) : id;
    if (findGraphNode(current, newId))
        throw InvalidInput("species '" + species + "' already has a node '" + newId + "'");
    editGraph(
        species, QString::fromStdString(newId),
        QCoreApplication::translate("Commands", "Add node %1").arg(QString::fromStdString(newId)),
        true, [&](Value& g) { addGraphNode(g, species, newId, type, params, position); });
    return newId;
}

void Document::removeNode(const std::string& species, const std::string& id) {
    editGraph(
        species, QString::fromStdString(id),
        QCoreApplication::translate("Commands", "Delete node %1").arg(QString::fromStdString(id)),
        true, [&](Value& g) { removeGraphNode(g, species, id); });
}

void Document::connectNodes(const std::string& species, const std::string& from,
                            const std::string& to) {
    editGraph(species, QString::fromStdString(to),
              QCoreApplication::translate("Commands", "Connect %1 to %2")
                  .arg(QString::fromStdString(from), QString::fromStdString(to)),
              true, [&](Value& g) { connectGraphNodes(g, species, from, to, mProject.baseDir); });
}

void Document::disconnectNodes(const std::string& species, const std::string& from,
                               const std::string& to) {
    editGraph(species, QString::fromStdString(to),
              QCoreApplication::translate("Commands", "Disconnect %1 from %2")
                  .arg(QString::fromStdString(from), QString::fromStdString(to)),
              true, [&](Value& g) { disconnectGraphNodes(g, species, from, to); });
}

void Document::setOutputNode(const std::string& species, const std::string& id) {
    editGraph(species, QString::fromStdString(id),
              QCoreApplication::translate("Commands", "Make %1 the output")
                  .arg(QString::fromStdString(id)),
              true, [&](Value& g) { setGraphOutput(g, species, id); });
}

void Document::moveNode(const std::string& species, const std::string& id, glm::vec2 position,
                        bool commit) {
    editGraph(
        species, QString::fromStdString(id) + QStringLiteral("#position"),
        QCoreApplication::translate("Commands", "Move node %1").arg(QString::fromStdString(id)),
        commit, [&](Value& g) { setNodeEditorPosition(g, species, id, position); });
}

void Document::moveNodes(const std::string& species,
                         const std::vector<std::pair<std::string, glm::vec2>>& positions) {
    if (positions.size() == 1) return moveNode(species, positions[0].first, positions[0].second);
    if (positions.empty()) return;
    editGraph(species, {}, QCoreApplication::translate("Commands", "Move nodes"), true,
              [&](Value& g) {
                  for (const auto& [id, position] : positions)
                      setNodeEditorPosition(g, species, id, position);
              });
}

void Document::removeNodes(const std::string& species, const std::vector<std::string>& ids,
                           const std::vector<std::pair<std::string, std::string>>& edges) {
    if (ids.empty() && edges.empty()) return;
    const auto among = [&ids](const std::string& id) {
        return std::find(ids.begin(), ids.end(), id) != ids.end();
    };
    editSpecies(species, {},
                ids.empty() ? QCoreApplication::translate("Commands", "Delete connection")
                            : QCoreApplication::translate("Commands", "Delete nodes"),
                true, [&](ProjectSpecies& s) {
                    Value& g = *s.graph;
                    // Step by step, each step checked as if it were its own edit: a step the
                    // tree cannot do without refuses the whole deletion.
                    for (const auto& [from, to] : edges)
                        if (!among(from) && !among(to)) {
                            disconnectGraphNodes(g, species, from, to);
                            validateSpecies(s);
                        }
                    for (const std::string& id : ids) {
                        removeGraphNode(g, species, id);
                        validateSpecies(s);
                    }
                });
}

std::vector<std::string> Document::pasteNodes(const std::string& species, const Value::Array& nodes,
                                              glm::dvec2 at) {
    if (nodes.empty()) return {};
    // Keep the copied layout, moved so that its top-left corner is at \p at; nodes without a
    // position go down a diagonal from it.
    glm::dvec2 corner(1e9, 1e9);
    for (const Value& n : nodes)
        if (const std::optional<glm::dvec2> p = nodeEditorPosition(n))
            corner = glm::min(corner, *p);
    if (corner.x > 1e8) corner = glm::dvec2(0.0);
    std::vector<std::string> made;
    editSpecies(species, {}, QCoreApplication::translate("Commands", "Paste nodes"), true,
                [&](ProjectSpecies& s) {
                    Value& g = *s.graph;
                    made.clear();
                    std::map<std::string, std::string> ids;
                    int k = 0;
                    for (const Value& n : nodes) {
                        glm::dvec2 pos = at + glm::dvec2(30.0 * k, 30.0 * k);
                        if (const std::optional<glm::dvec2> p = nodeEditorPosition(n))
                            pos = at + *p - corner;
                        ++k;
                        const std::string type = n.string("type", "");
                        requireNodeType(type);
                        const std::string id = freshNodeId(g, type);
                        addGraphNode(g, species, id, type,
                                     n.find("params") ? *n.find("params") : Value(Value::Object{}),
                                     glm::vec2(pos));
                        validateSpecies(s);
                        ids[n.string("id", "")] = id;
                        made.push_back(id);
                    }
                    for (const Value& n : nodes)
                        for (const std::string& in : nodeInputs(n))
                            if (ids.count(in)) {
                                connectGraphNodes(g, species, ids[in], ids[n.string("id", "")],
                                                  mProject.baseDir);
                                validateSpecies(s);
                            }
                });
    return made;
}

std::optional<glm::vec2> Document::nodePosition(const std::string& species,
                                                const std::string& id) const {
    Value g = speciesGraph(species);
    const std::optional<glm::dvec2> p = nodeEditorPosition(graphNode(g, species, id));
    if (!p) return std::nullopt;
    return glm::vec2(*p);
}

void Document::setGrammar(const std::string& species, const std::string& node,
                          const std::string& text, bool commit) {
    setParam(species, node + ".grammar", Value(text), commit);
}

std::string Document::grammar(const std::string& species, const std::string& node) const {
    const Value g = param(species, node + ".grammar");
    if (g.isString()) return g.toString();
    const Value file = param(species, node + ".grammar_file");
    if (!file.isString())
        throw InvalidInput("node '" + node + "' of species '" + species + "' has no grammar");
    QFile f(mProject.resolve(file.toString()));
    if (!f.open(QIODevice::ReadOnly))
        throw IoError("cannot read " + f.fileName().toStdString() + ": " +
                      f.errorString().toStdString());
    return f.readAll().toStdString();
}

void Document::rawSetSpecies(int index, const ProjectSpecies& s, const QString& node) {
    mProject.species[static_cast<std::size_t>(index)] = s;
    emitChange(DocumentChange::Species, {}, QString::fromStdString(s.name), node);
}

void Document::rawInsertSpecies(int index, const ProjectSpecies& s) {
    mProject.species.insert(mProject.species.begin() + index, s);
    emitChange(DocumentChange::Species, {}, QString::fromStdString(s.name));
}

void Document::rawRemoveSpecies(int index) {
    const QString name =
        QString::fromStdString(mProject.species[static_cast<std::size_t>(index)].name);
    mProject.species.erase(mProject.species.begin() + index);
    pruneSelection();
    emitChange(DocumentChange::Species, {}, name);
}

// --- obstacles, domains, settings -------------------------------------------------------

void Document::addObstacle(const ProjectObstacle& o) {
    ProjectObstacle copy = o;
    const QString absolute = QFileInfo(mProject.resolve(o.file)).absoluteFilePath();
    if (!QFileInfo(absolute).isFile())
        throw IoError("cannot read obstacle mesh " + absolute.toStdString() + ": no such file");
    copy.file = relativeTo(mProject.baseDir, absolute);
    mUndo.push(cmd::addObstacle(*this, static_cast<int>(mProject.obstacles.size()), copy));
}

void Document::removeObstacle(int index) {
    if (index < 0 || index >= static_cast<int>(mProject.obstacles.size()))
        throw InvalidInput("there is no obstacle " + std::to_string(index));
    mUndo.push(cmd::removeObstacle(*this, index));
}

void Document::setObstacle(int index, const ProjectObstacle& o, bool commit) {
    if (index < 0 || index >= static_cast<int>(mProject.obstacles.size()))
        throw InvalidInput("there is no obstacle " + std::to_string(index));
    for (int k = 0; k < 3; ++k) {
        requireRange("obstacle scale", o.scale[k], 1e-4, 1e4);
        requireRange("obstacle translation (m)", o.translate[k], -1e6, 1e6);
    }
    mUndo.push(cmd::changeObstacle(*this, index, o, commit));
}

void Document::addDomain(const PlacementDomain& d) {
    PlacementDomain fresh = d;
    // A new domain gets an id above every other: its trees' ids are new too.
    fresh.id = 0;
    for (const PlacementDomain& other : mProject.domains)
        fresh.id = std::max(fresh.id, other.id);
    if (++fresh.id > kMaxDomainId)
        throw LimitExceeded("a project's domain ids are limited to " +
                            std::to_string(kMaxDomainId));
    mUndo.push(cmd::addDomain(*this, static_cast<int>(mProject.domains.size()), fresh));
}

void Document::removeDomain(int index) {
    if (index < 0 || index >= static_cast<int>(mProject.domains.size()))
        throw InvalidInput("there is no domain " + std::to_string(index));
    mUndo.push(cmd::removeDomain(*this, index));
}

void Document::setDomain(int index, const PlacementDomain& d, bool commit) {
    if (index < 0 || index >= static_cast<int>(mProject.domains.size()))
        throw InvalidInput("there is no domain " + std::to_string(index));
    for (const auto& [name, count] : d.counts) {
        if (speciesIndex(name) < 0) throw InvalidInput("unknown species '" + name + "'");
        requireRange("trees per species and domain", count, 0, 1000000);
    }
    if (d.shape == "rectangle" && (d.min.x > d.max.x || d.min.y > d.max.y))
        throw InvalidInput("a rectangle domain needs min <= max");
    PlacementDomain same = d; // a domain keeps its id (and its trees theirs)
    same.id = mProject.domains[static_cast<std::size_t>(index)].id;
    mUndo.push(cmd::changeDomain(*this, index, same, commit));
}

Document::Settings Document::settings() const {
    return {mProject.seed,           mProject.cameraPosition, mProject.cameraTarget,
            mProject.lightDirection, mProject.season,         mProject.wind};
}

void Document::setSeed(std::uint64_t seed) {
    Settings s = settings();
    s.seed = seed;
    mUndo.push(cmd::changeSettings(*this, s, true,
                                   QCoreApplication::translate("Commands", "Change project seed")));
}

void Document::setCamera(const glm::vec3& position, const glm::vec3& target, bool commit) {
    if (glm::length(position - target) < 1e-4f)
        throw InvalidInput("the camera's position and target must differ");
    Settings s = settings();
    s.cameraPosition = position;
    s.cameraTarget = target;
    mUndo.push(cmd::changeSettings(*this, s, commit,
                                   QCoreApplication::translate("Commands", "Move camera")));
}

void Document::setLight(const glm::vec3& direction, bool commit) {
    if (glm::length(direction) < 1e-6f) throw InvalidInput("the light direction must not be zero");
    Settings s = settings();
    s.lightDirection = direction;
    mUndo.push(cmd::changeSettings(*this, s, commit,
                                   QCoreApplication::translate("Commands", "Change light")));
}

namespace {
/// \p season in its canonical spelling ("fall" is autumn), empty kept empty.
std::string canonicalSeason(const std::string& season) {
    return season.empty() ? season : std::string(mesh::seasonName(mesh::parseSeason(season)));
}
} // namespace

void Document::setSeason(const std::string& season) {
    Settings s = settings();
    s.season = canonicalSeason(season);
    if (s == settings()) return;
    mUndo.push(cmd::changeSettings(*this, s, true,
                                   QCoreApplication::translate("Commands", "Change season")));
}

void Document::setTreeSeason(TreeId id, const std::string& season) {
    ProjectInstance t = tree(id);
    t.season = canonicalSeason(season);
    setTree(id, t);
}

void Document::setWind(const std::optional<wind::WindSettings>& wind) {
    std::optional<wind::WindSettings> w = wind;
    if (w) {
        sylva::wind::validate(*w); // InvalidInput naming the setting and its allowed range
        w->period = sylva::wind::WindSettings{}.period; // an export's setting, not the project's
    }
    Settings s = settings();
    s.wind = w;
    mUndo.push(cmd::changeSettings(*this, s, true,
                                   QCoreApplication::translate("Commands", "Change wind")));
}

void Document::rawInsertObstacle(int index, const ProjectObstacle& o) {
    mProject.obstacles.insert(mProject.obstacles.begin() + index, o);
    pruneSelection();
    emitChange(DocumentChange::Obstacles);
}

void Document::rawRemoveObstacle(int index) {
    mProject.obstacles.erase(mProject.obstacles.begin() + index);
    pruneSelection();
    emitChange(DocumentChange::Obstacles);
}

void Document::rawSetObstacle(int index, const ProjectObstacle& o) {
    mProject.obstacles[static_cast<std::size_t>(index)] = o;
    emitChange(DocumentChange::Obstacles);
}

void Document::rawInsertDomain(int index, const PlacementDomain& d) {
    mProject.domains.insert(mProject.domains.begin() + index, d);
    pruneSelection();
    emitChange(DocumentChange::Domains);
}

void Document::rawRemoveDomain(int index) {
    mProject.domains.erase(mProject.domains.begin() + index);
    pruneSelection();
    emitChange(DocumentChange::Domains);
}

void Document::rawSetDomain(int index, const PlacementDomain& d) {
    mProject.domains[static_cast<std::size_t>(index)] = d;
    emitChange(DocumentChange::Domains);
}

void Document::rawSetSettings(const Settings& s) {
    const Settings before = settings();
    mProject.seed = s.seed;
    mProject.cameraPosition = s.cameraPosition;
    mProject.cameraTarget = s.cameraTarget;
    mProject.lightDirection = s.lightDirection;
    mProject.season = s.season;
    mProject.wind = s.wind;
    DocumentChange change;
    change.what = DocumentChange::Settings;
    if (before.seed != s.seed) change.settings << QString::fromLatin1(settingChange::kSeed);
    if (before.cameraPosition != s.cameraPosition || before.cameraTarget != s.cameraTarget)
        change.settings << QString::fromLatin1(settingChange::kCamera);
    if (before.lightDirection != s.lightDirection)
        change.settings << QString::fromLatin1(settingChange::kLight);
    if (before.season != s.season) change.settings << QString::fromLatin1(settingChange::kSeason);
    if (before.wind != s.wind) change.settings << QString::fromLatin1(settingChange::kWind);
    Q_EMIT changed(change);
}

// --- selection --------------------------------------------------------------------------

QList<TreeId> Document::selectedTrees() const {
    QList<TreeId> out;
    for (const ItemRef& r : mSelection)
        if (r.kind == ItemRef::Kind::Tree) out << r.id;
    return out;
}

void Document::setSelection(const QList<ItemRef>& items) {
    if (items == mSelection) return;
    mSelection = items;
    // A selected branch stays only while its tree alone is selected.
    if (mSelectedBranch &&
        mSelection != QList<ItemRef>{{ItemRef::Kind::Tree, mSelectedBranch->tree}})
        mSelectedBranch.reset();
    pruneSelection();
    Q_EMIT selectionChanged();
}

void Document::setSelectedBranch(const std::optional<BranchRef>& branch) {
    if (branch == mSelectedBranch) return;
    if (branch) (void)tree(branch->tree); // InvalidInput for an unknown tree
    mSelectedBranch = branch;
    const QList<ItemRef> items =
        branch ? QList<ItemRef>{{ItemRef::Kind::Tree, branch->tree}} : mSelection;
    if (items != mSelection) {
        mSelection = items;
        pruneSelection();
    }
    Q_EMIT selectionChanged();
}

void Document::selectTrees(const QList<TreeId>& ids) {
    QList<ItemRef> items;
    for (TreeId id : ids) {
        if (treeIndex(id) < 0) throw InvalidInput("there is no tree with id " + std::to_string(id));
        items.push_back({ItemRef::Kind::Tree, id});
    }
    setSelection(items);
}

void Document::pruneSelection() {
    const auto before = mSelection.size();
    mSelection.removeIf([this](const ItemRef& r) {
        switch (r.kind) {
        case ItemRef::Kind::Tree:
            return treeIndex(r.id) < 0;
        case ItemRef::Kind::Species:
            return r.id >= mProject.species.size();
        case ItemRef::Kind::Obstacle:
            return r.id >= mProject.obstacles.size();
        case ItemRef::Kind::Domain:
            return r.id >= mProject.domains.size();
        default:
            return false;
        }
    });
    const bool branchGone = mSelectedBranch && treeIndex(mSelectedBranch->tree) < 0;
    if (branchGone) mSelectedBranch.reset();
    if (mSelection.size() != before || branchGone) Q_EMIT selectionChanged();
}

void Document::emitChange(unsigned what, QList<TreeId> trees, QString species, QString node) {
    DocumentChange change;
    change.what = what;
    change.trees = std::move(trees);
    change.species = std::move(species);
    change.node = std::move(node);
    Q_EMIT changed(change);
}

} // namespace sylva::doc
