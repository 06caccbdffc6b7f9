#include "document/document.h"

#include <algorithm>
#include <cmath>

#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QSaveFile>

#include "document/commands/scenecommands.h"
#include "document/commands/speciescommands.h"
#include "document/commands/treecommands.h"
#include "document/filerefs.h"
#include "document/speciesfile.h"
#include "engine/graph/graph.h"
#include "engine/util/error.h"
#include "engine/util/random.h"

namespace sylva::doc {

using graph::Value;

namespace {

std::pair<std::string, std::string> splitParamPath(const std::string& path) {
    const auto dot = path.find('.');
    if (dot == std::string::npos || dot == 0 || dot + 1 == path.size())
        throw InvalidInput("a parameter is named \"node.param\", got \"" + path + "\"");
    return {path.substr(0, dot), path.substr(dot + 1)};
}

Value* findNode(Value& graph, const std::string& id) {
    Value::Object& g = graph.objectRef();
    auto nodes = g.find("nodes");
    if (nodes == g.end() || !nodes->second.isArray()) return nullptr;
    for (Value& n : nodes->second.arrayRef())
        if (n.isObject() && n.string("id", "") == id) return &n;
    return nullptr;
}

const Value* findNode(const Value& graph, const std::string& id) {
    const Value* nodes = graph.find("nodes");
    if (!nodes || !nodes->isArray()) return nullptr;
    for (const Value& n : nodes->toArray())
        if (n.isObject() && n.string("id", "") == id) return &n;
    return nullptr;
}

} // namespace

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
    mTreeIds.clear();
    mNextTreeId = 1;
    for (std::size_t i = 0; i < mProject.instances.size(); ++i)
        mTreeIds.push_back(mNextTreeId++);
    mSelection.clear();
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

int Document::treeIndex(TreeId id) const {
    const auto it = std::find(mTreeIds.begin(), mTreeIds.end(), id);
    return it == mTreeIds.end() ? -1 : static_cast<int>(it - mTreeIds.begin());
}

const ProjectInstance& Document::tree(TreeId id) const {
    const int i = treeIndex(id);
    if (i < 0) throw InvalidInput("there is no tree with id " + std::to_string(id));
    return mProject.instances[static_cast<std::size_t>(i)];
}

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
}

TreeId Document::addTree(const ProjectInstance& t) {
    validateTree(t);
    const TreeId id = takeNextTreeId();
    mUndo.push(new cmd::AddTree(*this, static_cast<int>(mTreeIds.size()), id, t));
    return id;
}

void Document::setTree(TreeId id, const ProjectInstance& t, bool commit) {
    (void)tree(id);
    validateTree(t);
    mUndo.push(cmd::changeTree(*this, id, t, commit));
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
        copy.seed = mixSeed(copy.seed, mNextTreeId) % 1000000007ull;
        const TreeId newId = takeNextTreeId();
        mUndo.push(new cmd::AddTree(*this, static_cast<int>(mTreeIds.size()), newId, copy));
        created << newId;
    }
    mUndo.endMacro();
    return created;
}

void Document::rawInsertTree(int index, TreeId id, const ProjectInstance& t) {
    mProject.instances.insert(mProject.instances.begin() + index, t);
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

void Document::rawSetTree(TreeId id, const ProjectInstance& t) {
    mProject.instances[static_cast<std::size_t>(treeIndex(id))] = t;
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
    const QString file = mProject.resolve(s.file);
    const graph::SpeciesGraph g = loadSpecies(file);
    const Value root = Value::parseJson(serializeSpecies(g).toStdString(), file.toStdString());
    ProjectSpecies out;
    out.name = s.name;
    out.graph = *root.find("graph");
    out.traits = *root.find("traits");
    rebaseGraphFiles(*out.graph, QString::fromStdString(g.baseDir.string()), mProject.baseDir);
    return out;
}

Value Document::speciesGraph(const std::string& name) const {
    const int i = speciesIndex(name);
    if (i < 0) throw InvalidInput("unknown species '" + name + "'");
    return *inlined(mProject.species[static_cast<std::size_t>(i)]).graph;
}

Value Document::param(const std::string& species, const std::string& path) const {
    const auto [node, key] = splitParamPath(path);
    Value g = speciesGraph(species);
    const Value* n = findNode(g, node);
    if (!n) throw InvalidInput("species '" + species + "' has no node '" + node + "'");
    const Value* params = n->find("params");
    const Value* v = params ? params->find(key) : nullptr;
    return v ? *v : Value();
}

graph::SpeciesGraph Document::toEngine(const ProjectSpecies& s) const {
    Value::Object root{{"format", "sylva-species"},
                       {"format_version", kSpeciesFormatVersion},
                       {"name", s.name},
                       {"graph", *s.graph}};
    if (s.traits) root["traits"] = *s.traits;
    return speciesFromValue(Value(std::move(root)), QString::fromStdString(s.name),
                            mProject.baseDir);
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
                               : QCoreApplication::translate("Commands", "Change %1")
                                     .arg(QString::fromStdString(path)),
              commit, [&](Value& g) {
                  Value* n = findNode(g, node);
                  if (!n)
                      throw InvalidInput("species '" + species + "' has no node '" + node + "'");
                  Value::Object& params = n->objectRef()["params"].objectRef();
                  if (value.isNull())
                      params.erase(key);
                  else
                      params[key] = value;
                  if (key == "grammar" && !value.isNull()) params.erase("grammar_file");
              });
}

void Document::applyPreset(const std::string& species, const QString& file) {
    const int i = speciesIndex(species);
    if (i < 0) throw InvalidInput("unknown species '" + species + "'");
    const graph::SpeciesGraph g = loadSpecies(file);
    const Value root = Value::parseJson(serializeSpecies(g).toStdString(), file.toStdString());
    const ProjectSpecies& old = mProject.species[static_cast<std::size_t>(i)];
    ProjectSpecies applied;
    applied.name = old.name;
    applied.graph = *root.find("graph");
    applied.traits = *root.find("traits");
    rebaseGraphFiles(*applied.graph, QString::fromStdString(g.baseDir.string()), mProject.baseDir);
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
    Value graphValue = *s.graph;
    // Self-contained: a grammar file's text goes into the file; other files are rebased.
    for (Value& n : graphValue.objectRef()["nodes"].arrayRef()) {
        Value& params = n.objectRef()["params"];
        if (const Value* file = params.find("grammar_file"); file && file->isString()) {
            const std::string text = grammar(species, n.string("id", ""));
            params.objectRef().erase("grammar_file");
            params.objectRef()["grammar"] = Value(text);
        }
        n.objectRef().erase("editor_position");
    }
    rebaseGraphFiles(graphValue, mProject.baseDir, QFileInfo(path).absolutePath());
    Value::Object root{{"format", "sylva-species"},
                       {"format_version", kSpeciesFormatVersion},
                       {"name", s.name},
                       {"graph", graphValue}};
    if (s.traits) root["traits"] = *s.traits;
    QSaveFile out(path);
    if (!out.open(QIODevice::WriteOnly))
        throw IoError("cannot write " + path.toStdString() + ": " +
                      out.errorString().toStdString());
    out.write(QByteArray::fromStdString(Value(std::move(root)).toPrettyJson() + "\n"));
    if (!out.commit())
        throw IoError("cannot write " + path.toStdString() + ": " +
                      out.errorString().toStdString());
}

void Document::editGraph(const std::string& species, const QString& node, const QString& label,
                         bool commit, const std::function<void(Value&)>& edit) {
    const int i = speciesIndex(species);
    if (i < 0) throw InvalidInput("unknown species '" + species + "'");
    const ProjectSpecies& old = mProject.species[static_cast<std::size_t>(i)];
    ProjectSpecies edited = inlined(old);
    edit(*edited.graph);
    validateSpecies(edited); // unknown parameter, a graph the engine refuses: nothing changes
    // An unchanged value that commits still goes on: it closes a drag or a burst of typing (it
    // merges into the open step, or is dropped as obsolete).
    if (edited == old && !commit) return;
    mUndo.push(cmd::changeSpecies(*this, i, old, edited, node, commit, label));
}

namespace {

Value::Array& nodesOf(Value& graph) {
    return graph.objectRef()["nodes"].arrayRef();
}

std::vector<std::string> inputsOf(const Value& node) {
    std::vector<std::string> out;
    if (const Value* in = node.find("inputs"); in && in->isArray())
        for (const Value& v : in->toArray())
            out.push_back(v.toString("an input id"));
    return out;
}

void setInputs(Value& node, const std::vector<std::string>& inputs) {
    Value::Array a;
    for (const std::string& s : inputs)
        a.emplace_back(s);
    if (a.empty())
        node.objectRef().erase("inputs");
    else
        node.objectRef()["inputs"] = Value(std::move(a));
}

Value& nodeOrThrow(Value& graph, const std::string& species, const std::string& id) {
    Value* n = findNode(graph, id);
    if (!n) throw InvalidInput("species '" + species + "' has no node '" + id + "'");
    return *n;
}

} // namespace

std::string Document::addNode(const std::string& species, const std::string& type,
                              const Value& params, const std::string& id, glm::vec2 position) {
    graph::registerBuiltinNodeTypes();
    if (!graph::NodeRegistry::instance().find(type)) {
        std::string known;
        for (const std::string& n : graph::NodeRegistry::instance().names())
            known += (known.empty() ? "" : ", ") + n;
        throw InvalidInput("unknown node type '" + type + "' (known: " + known + ")");
    }
    const Value current = speciesGraph(species);
    std::string newId = id;
    if (newId.empty()) {
        newId = type;
        for (int k = 2; findNode(current, newId); ++k)
            newId = type + std::to_string(k);
    } else if (findNode(current, newId)) {
        throw InvalidInput("species '" + species + "' already has a node '" + newId + "'");
    }
    editGraph(
        species, QString::fromStdString(newId),
        QCoreApplication::translate("Commands", "Add node %1").arg(QString::fromStdString(newId)),
        true, [&](Value& g) {
            Value::Object node{
                {"id", newId},
                {"type", type},
                {"params", params.isNull() ? Value(Value::Object{}) : params},
                {"editor_position", Value(Value::Array{double(position.x), double(position.y)})}};
            nodesOf(g).emplace_back(std::move(node));
        });
    return newId;
}

void Document::removeNode(const std::string& species, const std::string& id) {
    editGraph(
        species, QString::fromStdString(id),
        QCoreApplication::translate("Commands", "Delete node %1").arg(QString::fromStdString(id)),
        true, [&](Value& g) {
            nodeOrThrow(g, species, id);
            if (g.string("output", "") == id)
                throw InvalidInput("'" + id +
                                   "' is the species' output (the tree); make another node "
                                   "the output first");
            Value::Array& nodes = nodesOf(g);
            for (auto it = nodes.begin(); it != nodes.end();) {
                if (it->string("id", "") == id) {
                    it = nodes.erase(it);
                    continue;
                }
                std::vector<std::string> in = inputsOf(*it);
                std::erase(in, id);
                setInputs(*it, in);
                ++it;
            }
        });
}

void Document::connectNodes(const std::string& species, const std::string& from,
                            const std::string& to) {
    editGraph(species, QString::fromStdString(to),
              QCoreApplication::translate("Commands", "Connect %1 to %2")
                  .arg(QString::fromStdString(from), QString::fromStdString(to)),
              true, [&](Value& g) {
                  graph::registerBuiltinNodeTypes();
                  Value& target = nodeOrThrow(g, species, to);
                  nodeOrThrow(g, species, from);
                  std::vector<std::string> in = inputsOf(target);
                  if (std::find(in.begin(), in.end(), from) != in.end()) return; // already
                  const graph::NodeType* t =
                      graph::NodeRegistry::instance().find(target.string("type", ""));
                  // A node with one input has it replaced: drop the old edge before checking.
                  if (t && t->maxInputs == 1 && in.size() == 1) in.clear();
                  setInputs(target, in);
                  ProjectSpecies probe;
                  probe.name = species;
                  probe.graph = g;
                  const std::string why = graph::connectionError(toEngine(probe), from, to);
                  if (!why.empty()) throw InvalidInput(why);
                  in.push_back(from);
                  setInputs(target, in);
              });
}

void Document::disconnectNodes(const std::string& species, const std::string& from,
                               const std::string& to) {
    editGraph(species, QString::fromStdString(to),
              QCoreApplication::translate("Commands", "Disconnect %1 from %2")
                  .arg(QString::fromStdString(from), QString::fromStdString(to)),
              true, [&](Value& g) {
                  Value& target = nodeOrThrow(g, species, to);
                  std::vector<std::string> in = inputsOf(target);
                  if (std::find(in.begin(), in.end(), from) == in.end())
                      throw InvalidInput("'" + from + "' is not connected to '" + to + "'");
                  std::erase(in, from);
                  setInputs(target, in);
              });
}

void Document::setOutputNode(const std::string& species, const std::string& id) {
    editGraph(species, QString::fromStdString(id),
              QCoreApplication::translate("Commands", "Make %1 the output")
                  .arg(QString::fromStdString(id)),
              true, [&](Value& g) {
                  nodeOrThrow(g, species, id);
                  g.objectRef()["output"] = Value(id);
              });
}

void Document::moveNode(const std::string& species, const std::string& id, glm::vec2 position,
                        bool commit) {
    editGraph(
        species, QString::fromStdString(id) + QStringLiteral("#position"),
        QCoreApplication::translate("Commands", "Move node %1").arg(QString::fromStdString(id)),
        commit, [&](Value& g) {
            nodeOrThrow(g, species, id).objectRef()["editor_position"] =
                Value(Value::Array{double(position.x), double(position.y)});
        });
}

std::optional<glm::vec2> Document::nodePosition(const std::string& species,
                                                const std::string& id) const {
    Value g = speciesGraph(species);
    const Value* n = findNode(g, id);
    if (!n) throw InvalidInput("species '" + species + "' has no node '" + id + "'");
    const Value* p = n->find("editor_position");
    if (!p || !p->isArray() || p->toArray().size() != 2) return std::nullopt;
    return glm::vec2(static_cast<float>(p->toArray()[0].toNumber()),
                     static_cast<float>(p->toArray()[1].toNumber()));
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
    mUndo.push(cmd::addDomain(*this, static_cast<int>(mProject.domains.size()), d));
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
    mUndo.push(cmd::changeDomain(*this, index, d, commit));
}

Document::Settings Document::settings() const {
    return {mProject.seed, mProject.cameraPosition, mProject.cameraTarget, mProject.lightDirection};
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
    mProject.seed = s.seed;
    mProject.cameraPosition = s.cameraPosition;
    mProject.cameraTarget = s.cameraTarget;
    mProject.lightDirection = s.lightDirection;
    emitChange(DocumentChange::Settings);
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
    pruneSelection();
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
    if (mSelection.size() != before) Q_EMIT selectionChanged();
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
