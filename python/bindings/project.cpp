#include "project.h"

#include <QDir>

#include <algorithm>

#include "document/scenebuild.h"
#include "engine/environment/obstaclescene.h"
#include "engine/mesh/season.h"
#include "engine/placement/placement.h"
#include "engine/util/error.h"
#include "engine/util/random.h"

namespace sylva::python {

forest::ForestScene Project::makeScene() const {
    forest::ForestScene s = doc::makeForestScene(project);
    if (!arrayObstacles.empty()) {
        std::vector<env::ObstacleMesh> all;
        if (s.obstacles) all = s.obstacles->meshes();
        all.insert(all.end(), arrayObstacles.begin(), arrayObstacles.end());
        s.obstacles = std::make_shared<const env::ObstacleScene>(std::move(all));
    }
    if (ground) {
        if (s.ground)
            throw InvalidInput("the project has a terrain domain already; it cannot have a "
                               "ground from arrays as well");
        s.ground =
            std::make_shared<const env::ObstacleScene>(std::vector<env::ObstacleMesh>{*ground});
        placement::Domain d;
        d.min = {ground->lo.x, ground->lo.z};
        d.max = {ground->hi.x, ground->hi.z};
        for (const auto& [name, count] : groundCounts)
            d.counts.emplace_back(name, static_cast<std::size_t>(count));
        s.domains.push_back(std::move(d));
    }
    return s;
}

Project projectFrom(const doc::Project& project) {
    Project p;
    p.project = project;
    if (p.project.baseDir.isEmpty()) p.project.baseDir = QDir::currentPath();
    return p;
}

Tree treeOf(std::uint64_t id, const doc::ProjectInstance& t) {
    return {id, t.species, t.position, t.rotation, t.scale, t.growth, t.seed, t.season};
}

std::string seasonFrom(const py::object& season) {
    if (season.is_none()) return {};
    return std::string(mesh::seasonName(mesh::parseSeason(season.cast<std::string>())));
}

py::object seasonTo(const std::string& season) {
    return season.empty() ? py::object(py::none()) : py::object(py::str(season));
}

py::object windTo(const std::optional<wind::WindSettings>& w) {
    if (!w) return py::none();
    py::dict d;
    d["direction"] = fromVec3(w->direction);
    d["strength"] = w->strength;
    d["gustiness"] = w->gustiness;
    d["frequency"] = w->frequency;
    return d;
}

doc::ProjectInstance newTree(const doc::Project& project, std::size_t treesBefore,
                             const std::string& species, const py::handle& position,
                             double rotation, double scale, std::optional<std::uint64_t> seed,
                             double growth) {
    doc::ProjectInstance t;
    t.species = species;
    t.position = toVec3(position, "position");
    t.rotation = rotation;
    t.scale = scale;
    t.growth = growth;
    t.seed = seed ? *seed : project.newTreeSeed(treesBefore);
    return t;
}

std::vector<std::string> speciesNames(const doc::Project& project) {
    std::vector<std::string> names;
    for (const doc::ProjectSpecies& s : project.species)
        names.push_back(s.name);
    return names;
}

py::list obstaclesList(const std::vector<doc::ProjectObstacle>& obstacles) {
    py::list out;
    for (const doc::ProjectObstacle& o : obstacles) {
        py::dict d;
        d["file"] = o.file;
        d["translate"] = fromVec3(o.translate);
        d["rotate"] = fromVec3(o.rotate);
        d["scale"] = fromVec3(o.scale);
        out.append(d);
    }
    return out;
}

void applyTransform(doc::ProjectObstacle& o, const py::handle& translate, const py::handle& rotate,
                    const py::handle& scale) {
    if (!translate.is_none()) o.translate = toVec3(translate, "translate");
    if (!rotate.is_none()) o.rotate = toVec3(rotate, "rotate");
    if (!scale.is_none()) o.scale = toVec3(scale, "scale");
}

env::MeshTransform transformFrom(const py::handle& translate, const py::handle& rotate,
                                 const py::handle& scale) {
    doc::ProjectObstacle o;
    applyTransform(o, translate, rotate, scale);
    env::MeshTransform t;
    t.translate = o.translate;
    t.rotateDeg = o.rotate;
    t.scale = o.scale;
    return t;
}

py::list branchEditsList(const std::vector<skel::BranchEdit>& edits) {
    py::list out;
    for (const skel::BranchEdit& e : edits) {
        py::dict d;
        d["branch"] = e.branch;
        if (e.prune) d["prune"] = true;
        if (e.bend) d["bend"] = fromVec3(*e.bend);
        if (e.length != 1.0f) d["length"] = e.length;
        if (e.radius != 1.0f) d["radius"] = e.radius;
        if (e.lock) d["lock"] = true;
        if (e.lock && !e.locked.empty()) d["locked_nodes"] = e.locked.size();
        out.append(d);
    }
    return out;
}

skel::BranchEdit branchEditFrom(const std::vector<skel::BranchEdit>& edits,
                                const std::string& branch, const py::object& prune,
                                const py::object& bend, const py::object& length,
                                const py::object& radius, const py::object& lock) {
    skel::BranchEdit e;
    e.branch = branch;
    for (const skel::BranchEdit& old : edits)
        if (old.branch == branch) e = old;
    const bool unlocking = !lock.is_none() && !lock.cast<bool>();
    if (e.lock && !e.locked.empty() && !unlocking &&
        !(prune.is_none() && bend.is_none() && length.is_none() && radius.is_none()))
        throw InvalidInput("branch " + branch +
                           " is locked: unlock it (lock=False) before changing it");
    if (!prune.is_none()) e.prune = prune.cast<bool>();
    if (!lock.is_none()) {
        e.lock = lock.cast<bool>();
        if (!e.lock) { // unlocked: the kept geometry goes too
            e.lockedBase = glm::vec3(0.0f);
            e.locked.clear();
            e.lockedLeaves.clear();
        }
    }
    if (!length.is_none()) e.length = length.cast<float>();
    if (!radius.is_none()) e.radius = radius.cast<float>();
    if (!bend.is_none()) {
        if (py::isinstance<py::bool_>(bend)) {
            if (bend.cast<bool>()) throw InvalidInput("bend needs three numbers (x, y, z)");
            e.bend.reset();
        } else if (py::len(bend) == 0) {
            e.bend.reset();
        } else {
            e.bend = toVec3(bend, "bend");
        }
    }
    doc::checkBranchEdit(e, "branch edit");
    return e;
}

std::vector<skel::BranchEdit> withBranchEdit(std::vector<skel::BranchEdit> edits,
                                             const skel::BranchEdit& edit) {
    doc::checkBranchEdit(edit, "branch edit");
    auto same = std::find_if(edits.begin(), edits.end(),
                             [&](const skel::BranchEdit& e) { return e.branch == edit.branch; });
    if (doc::isEmptyEdit(edit)) {
        if (same != edits.end()) edits.erase(same);
    } else if (same != edits.end()) {
        *same = edit;
    } else {
        edits.push_back(edit);
    }
    return edits;
}

py::list branchesList(const std::vector<skel::Branch>& branches, const glm::mat4& transform,
                      float scale) {
    py::list out;
    for (const skel::Branch& b : branches) {
        py::dict d;
        d["id"] = b.id;
        d["parent"] = b.parent.empty() ? py::object(py::none()) : py::object(py::str(b.parent));
        d["order"] = b.order;
        d["base"] = fromVec3(glm::vec3(transform * glm::vec4(b.base, 1.0f)));
        d["tip"] = fromVec3(glm::vec3(transform * glm::vec4(b.tip, 1.0f)));
        d["length"] = b.length * scale;
        d["radius"] = b.baseRadius * scale;
        out.append(d);
    }
    return out;
}

py::list domainsList(const std::vector<doc::PlacementDomain>& domains) {
    py::list out;
    for (const doc::PlacementDomain& d : domains) {
        py::dict o;
        o["id"] = d.id;
        o["shape"] = d.shape;
        o["min"] = py::make_tuple(d.min.x, d.min.y);
        o["max"] = py::make_tuple(d.max.x, d.max.y);
        o["counts"] = d.counts;
        out.append(o);
    }
    return out;
}

glm::vec2 toXZ(const py::handle& o, const char* what) {
    const auto v = o.cast<std::vector<float>>();
    if (v.size() != 2) throw InvalidInput(std::string(what) + " needs two numbers (x, z)");
    return {v[0], v[1]};
}

void bindTree(py::module_& m) {
    py::class_<Tree>(m, "Tree",
                     "A hand-placed tree of a project or of the editor's document (a snapshot "
                     "of its values).")
        .def_readonly("id", &Tree::id,
                      "the tree's stable id (saved in the project, kept by every edit, named by "
                      "every export)")
        .def_readonly("species", &Tree::species)
        .def_property_readonly("position", [](const Tree& t) { return fromVec3(t.position); })
        .def_readonly("rotation", &Tree::rotation, "degrees about +Y")
        .def_readonly("scale", &Tree::scale)
        .def_readonly("growth", &Tree::growth)
        .def_readonly("seed", &Tree::seed)
        .def_property_readonly(
            "season", [](const Tree& t) { return seasonTo(t.season); },
            "the tree's own season ('spring', 'summer', 'autumn', 'winter'), or None: the "
            "project's")
        .def("__repr__", [](const Tree& t) {
            return "<Tree " + std::to_string(t.id) + " " + t.species + " at (" +
                   std::to_string(t.position.x) + ", " + std::to_string(t.position.y) + ", " +
                   std::to_string(t.position.z) + ")>";
        });
}

} // namespace sylva::python
