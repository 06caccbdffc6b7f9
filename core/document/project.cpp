#include "document/project.h"

#include "document/jsonlocate.h"

#include "document/formatupgrade.h"
#include "document/projectsettings.h"
#include "engine/graph/vectorparam.h"
#include "engine/mesh/season.h"
#include "engine/util/atomicfile.h"
#include "engine/util/error.h"
#include "engine/util/random.h"
#include "engine/util/text.h"
#include "engine/wind/windmodel.h"

#include <QDir>
#include <QFile>
#include <QFileInfo>

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <functional>
#include <map>
#include <set>

namespace sylva::doc {

namespace {

using graph::vec3Of;
using sylva::Value;

const std::vector<std::string> kKnownKeys = {
    "format",    "format_version", "app_version", "seed",  "species",      "domains",
    "instances", "obstacles",      "camera",      "light", "next_tree_id", "season"};

/// An optional id: a whole number in [1, \p max], or 0 when the key is absent.
std::uint64_t idOf(const Value& v, const std::string& where, std::uint64_t max) {
    const Value* id = v.find("id");
    if (!id) return 0;
    const double x = id->toNumber(where + ".id");
    if (!(x >= 1 && x <= static_cast<double>(max) && x == std::floor(x)))
        throw InvalidInput(where + ".id must be a whole number in [1, " + std::to_string(max) +
                           "]");
    return static_cast<std::uint64_t>(x);
}

glm::vec2 vec2Of(const Value& v, const std::string& what) {
    const Value::Array& a = v.toArray(what);
    if (a.size() != 2) throw InvalidInput(what + " must be [x, z]");
    return {static_cast<float>(a[0].toNumber(what)), static_cast<float>(a[1].toNumber(what))};
}

Value arrayOf(const glm::vec3& v) {
    return Value(Value::Array{decimalOf(v.x), decimalOf(v.y), decimalOf(v.z)});
}
Value arrayOf(const glm::vec2& v) {
    return Value(Value::Array{decimalOf(v.x), decimalOf(v.y)});
}

glm::vec3 vec3Or(const Value& obj, const std::string& key, const glm::vec3& fallback,
                 const std::string& where) {
    const Value* v = obj.find(key);
    return v ? vec3Of(*v, where + "." + key) : fallback;
}

ProjectSpecies parseSpeciesRef(const Value& v, std::size_t i) {
    const std::string where = "species[" + std::to_string(i) + "]";
    ProjectSpecies s;
    s.name = v.string("name", "");
    if (s.name.empty()) throw InvalidInput(where + " needs a \"name\"");
    s.file = v.string("file", "");
    if (const Value* g = v.find("graph")) s.graph = *g;
    if (const Value* t = v.find("traits")) {
        if (!s.graph) throw InvalidInput(where + ": \"traits\" belong to an inline \"graph\"");
        s.traits = *t;
    }
    if (const Value* k = v.find("variants")) {
        const double x = k->toNumber(where + ".variants");
        const SettingSpec& spec = settings::kVariants;
        if (!(x >= spec.min && x <= spec.max && x == std::floor(x)))
            throw InvalidInput(where + ".variants must be a whole number in [" +
                               std::to_string(int(spec.min)) + ", " +
                               std::to_string(int(spec.max)) + "]");
        s.variants = static_cast<int>(x);
    }
    if (s.file.empty() == !s.graph.has_value())
        throw InvalidInput(where + " (\"" + s.name +
                           "\") needs exactly one of \"file\" or \"graph\"");
    return s;
}

PlacementDomain parseDomain(const Value& v, std::size_t i) {
    const std::string where = "domains[" + std::to_string(i) + "]";
    PlacementDomain d;
    d.id = idOf(v, where, kMaxDomainId);
    d.shape = v.string("shape", "rectangle");
    if (d.shape == "rectangle") {
        const Value* mn = v.find("min");
        const Value* mx = v.find("max");
        if (!mn || !mx)
            throw InvalidInput(where + ": a rectangle needs \"min\" and \"max\" [x, z]");
        d.min = vec2Of(*mn, where + ".min");
        d.max = vec2Of(*mx, where + ".max");
        if (!(d.min.x < d.max.x && d.min.y < d.max.y))
            throw InvalidInput(where + ": min must be below max in x and z");
    } else if (d.shape == "polygon") {
        const Value* pts = v.find("points");
        if (!pts) throw InvalidInput(where + ": a polygon needs \"points\" [[x, z], ...]");
        for (const Value& p : pts->toArray(where + ".points"))
            d.polygon.push_back(vec2Of(p, where + ".points"));
        if (d.polygon.size() < 3) throw InvalidInput(where + ": a polygon needs at least 3 points");
    } else if (d.shape == "terrain") {
        d.terrain = v.string("file", "");
        if (d.terrain.empty())
            throw InvalidInput(where + ": a terrain domain needs a mesh \"file\"");
    } else {
        throw InvalidInput(where + ": shape must be rectangle, polygon or terrain, got \"" +
                           d.shape + "\"");
    }
    if (const Value* counts = v.find("counts")) {
        for (const auto& [name, n] : counts->toObject(where + ".counts")) {
            const double c = n.toNumber(where + ".counts." + name);
            if (c < 0 || c != std::floor(c) || c > 1e8)
                throw InvalidInput(where + ".counts." + name +
                                   " must be a whole number in [0, 1e8]");
            d.counts[name] = static_cast<int>(c);
        }
    }
    return d;
}

/// \p name when it is empty or a season's name; else InvalidInput naming \p where.
std::string checkedSeason(const std::string& name, const std::string& where) {
    if (name.empty()) return name;
    try {
        return std::string(mesh::seasonName(mesh::parseSeason(name)));
    } catch (const InvalidInput& e) {
        throw InvalidInput(where + ": " + e.what());
    }
}

skel::BranchEdit parseBranchEdit(const Value& v, const std::string& where) {
    static const std::set<std::string> keys = {"branch", "prune", "bend",   "length",
                                               "radius", "lock",  "locked", "anchor"};
    for (const auto& [key, value] : v.toObject(where))
        if (!keys.count(key))
            throw InvalidInput(
                where + ": unknown key \"" + key +
                "\" (a branch edit has branch, prune, bend, length, radius, lock, locked, "
                "anchor)");
    skel::BranchEdit e;
    const Value* branch = v.find("branch");
    if (!branch || !branch->isString())
        throw InvalidInput(where + " needs a \"branch\" id such as \"0.3\"");
    e.branch = branch->toString();
    if (const Value* b = v.find("prune")) e.prune = b->toBool(where + ".prune");
    if (const Value* b = v.find("lock")) e.lock = b->toBool(where + ".lock");
    if (const Value* b = v.find("bend")) e.bend = vec3Of(*b, where + ".bend");
    if (const Value* x = v.find("length"))
        e.length = static_cast<float>(x->toNumber(where + ".length"));
    if (const Value* x = v.find("radius"))
        e.radius = static_cast<float>(x->toNumber(where + ".radius"));
    if (const Value* anchor = v.find("anchor")) {
        // [base x, y, z, direction x, y, z, length]: where the branch was when edited.
        const std::string at = where + ".anchor";
        const Value::Array& a = anchor->toArray(at);
        if (a.size() != 7)
            throw InvalidInput(at + " needs 7 numbers (base x, y, z, direction x, y, z, length)");
        float f[7];
        for (std::size_t i = 0; i < 7; ++i) {
            f[i] = static_cast<float>(a[i].toNumber(at));
            if (!std::isfinite(f[i])) throw InvalidInput(at + " must hold finite numbers");
        }
        skel::BranchAnchor an;
        an.base = {f[0], f[1], f[2]};
        an.direction = {f[3], f[4], f[5]};
        an.length = f[6];
        if (glm::length(an.direction) < 1e-3f || an.length < 0.0f)
            throw InvalidInput(at + ": the direction must not be zero, the length not negative");
        e.anchor = an;
    }
    if (const Value* locked = v.find("locked")) {
        const std::string at = where + ".locked";
        if (!e.lock) throw InvalidInput(at + " belongs to a locked edit (\"lock\": true)");
        auto numbers = [](const Value& row, std::size_t n, const std::string& what) {
            const Value::Array& a = row.toArray(what);
            if (a.size() != n)
                throw InvalidInput(what + " needs " + std::to_string(n) + " numbers");
            std::vector<double> out;
            for (const Value& x : a)
                out.push_back(x.toNumber(what));
            return out;
        };
        auto quat = [](const std::vector<double>& r, std::size_t i) {
            glm::quat q;
            q.x = static_cast<float>(r[i]);
            q.y = static_cast<float>(r[i + 1]);
            q.z = static_cast<float>(r[i + 2]);
            q.w = static_cast<float>(r[i + 3]);
            return q;
        };
        auto vec = [](const std::vector<double>& r, std::size_t i) {
            return glm::vec3(static_cast<float>(r[i]), static_cast<float>(r[i + 1]),
                             static_cast<float>(r[i + 2]));
        };
        e.lockedBase = vec3Or(*locked, "base", glm::vec3(0.0f), at);
        if (const Value* nodes = locked->find("nodes"))
            for (const Value& row : nodes->toArray(at + ".nodes")) {
                // [parent, order, radius, offset x, y, z, orientation x, y, z, w]
                const std::vector<double> r = numbers(row, 10, at + ".nodes[]");
                skel::LockedNode n;
                if (r[0] != std::floor(r[0]) || r[1] != std::floor(r[1]) || r[1] < 0 ||
                    r[1] > 65535 || r[0] < -1 || r[0] > 1e9)
                    throw InvalidInput(at + ".nodes[]: parent and order must be whole numbers");
                n.parent = static_cast<std::int32_t>(r[0]);
                n.order = static_cast<std::uint16_t>(r[1]);
                n.radius = static_cast<float>(r[2]);
                n.offset = vec(r, 3);
                n.orientation = quat(r, 6);
                e.locked.push_back(n);
            }
        if (const Value* leaves = locked->find("leaves"))
            for (const Value& row : leaves->toArray(at + ".leaves")) {
                // [node, size, offset x, y, z, orientation x, y, z, w]
                const std::vector<double> r = numbers(row, 9, at + ".leaves[]");
                if (r[0] != std::floor(r[0]) || r[0] < 0 || r[0] > 1e9)
                    throw InvalidInput(at + ".leaves[]: node must be a whole number");
                e.lockedLeaves.push_back({static_cast<std::int32_t>(r[0]), static_cast<float>(r[1]),
                                          vec(r, 2), quat(r, 5)});
            }
    }
    checkBranchEdit(e, where);
    return e;
}

/// Says where in the file a malformed branch edit is: (edit index, key or "", message).
using BranchEditError = std::function<void(std::size_t, const std::string&, const std::string&)>;

ProjectInstance parseInstance(const Value& v, std::size_t i, const BranchEditError& located) {
    const std::string where = "instances[" + std::to_string(i) + "]";
    ProjectInstance in;
    in.id = idOf(v, where, kMaxTreeId);
    in.species = v.string("species", "");
    if (in.species.empty()) throw InvalidInput(where + " needs a \"species\"");
    in.position = vec3Or(v, "position", in.position, where);
    in.rotation = v.number("rotation", 0.0);
    in.scale = v.number("scale", 1.0);
    requireRange((where + ".scale").c_str(), in.scale, 1e-3, 1e3);
    in.seed = static_cast<std::uint64_t>(v.integer("seed", 0));
    in.growth = v.number("growth", 1.0);
    requireRange((where + ".growth").c_str(), in.growth, 0.0, 1.0);
    in.season = checkedSeason(v.string("season", ""), where + ".season");
    if (const Value* edits = v.find("branch_edits")) {
        const Value::Array& a = edits->toArray(where + ".branch_edits");
        std::set<std::string> seen;
        for (std::size_t k = 0; k < a.size(); ++k) {
            const std::string at = where + ".branch_edits[" + std::to_string(k) + "]";
            skel::BranchEdit e;
            try {
                e = parseBranchEdit(a[k], at);
            } catch (const InvalidInput& x) {
                // file:line:col of the entry, or of its key the message names (".length ...").
                const std::string message = x.what();
                std::string key;
                if (message.rfind(at + ".", 0) == 0)
                    for (std::size_t c = at.size() + 1;
                         c < message.size() &&
                         (std::isalpha(static_cast<unsigned char>(message[c])) ||
                          message[c] == '_');
                         ++c)
                        key += message[c];
                located(k, key, message);
                throw;
            }
            if (!seen.insert(e.branch).second) {
                located(k, "branch", at + ": branch " + e.branch + " is edited twice");
                throw InvalidInput(at + ": branch " + e.branch + " is edited twice");
            }
            in.branchEdits.push_back(std::move(e));
        }
    }
    return in;
}

ProjectObstacle parseObstacle(const Value& v, std::size_t i) {
    const std::string where = "obstacles[" + std::to_string(i) + "]";
    ProjectObstacle o;
    o.file = v.string("file", "");
    if (o.file.empty()) throw InvalidInput(where + " needs a mesh \"file\"");
    o.translate = vec3Or(v, "translate", o.translate, where);
    o.rotate = vec3Or(v, "rotate", o.rotate, where);
    o.scale = vec3Or(v, "scale", o.scale, where);
    return o;
}

} // namespace

void checkBranchEdit(const skel::BranchEdit& e, const std::string& where) {
    const bool idOk = !e.branch.empty() && e.branch.front() != '.' && e.branch.back() != '.' &&
                      e.branch.find("..") == std::string::npos &&
                      std::all_of(e.branch.begin(), e.branch.end(),
                                  [](char c) { return c == '.' || (c >= '0' && c <= '9'); }) &&
                      e.branch.size() <= 200;
    if (!idOk)
        throw InvalidInput(where + ".branch \"" + e.branch +
                           "\" is not a branch id (ranks joined by dots, such as \"0.3.1\")");
    auto scale = [&](const char* name, float x) {
        if (!(x >= skel::kBranchScaleMin && x <= skel::kBranchScaleMax)) {
            throw InvalidInput(where + "." + name + " " + shortestDecimal(x) +
                               " is out of range [0.05, 20]");
        }
    };
    scale("length", e.length);
    scale("radius", e.radius);
    if (e.bend && !(std::isfinite(e.bend->x) && std::isfinite(e.bend->y) &&
                    std::isfinite(e.bend->z) && glm::length(*e.bend) > 1e-6f))
        throw InvalidInput(where + ".bend must be a non-zero direction [x, y, z]");
    if (e.prune && e.branch.find('.') == std::string::npos)
        throw InvalidInput(where + ": branch " + e.branch + " is a trunk and cannot be pruned");
    try {
        skel::validate(e); // the locked geometry's structure
    } catch (const InvalidInput& x) {
        throw InvalidInput(where + ": " + x.what());
    }
}

bool isEmptyEdit(const skel::BranchEdit& e) {
    return !e.prune && !e.bend && e.length == 1.0f && e.radius == 1.0f && !e.lock;
}

const std::vector<UpgradeStep>& projectUpgrades() {
    // format_version 1 is the first released format; steps go here, in order.
    static const std::vector<UpgradeStep> steps = {
        {1,
         "format 2: hand-placed trees and domains get stable ids (trees 1, 2, ... in file order, "
         "as the editor numbered them; domains 1, 2, ...); domains now scatter their trees "
         "independently of hand-placed trees, so the forest's domain trees change once",
         [](Value::Object& root) {
             std::uint64_t next = 1;
             if (auto it = root.find("instances"); it != root.end() && it->second.isArray())
                 for (Value& in : it->second.arrayRef())
                     if (in.isObject()) in.objectRef()["id"] = static_cast<double>(next++);
             root["next_tree_id"] = static_cast<double>(next);
             std::uint64_t domain = 1;
             if (auto it = root.find("domains"); it != root.end() && it->second.isArray())
                 for (Value& d : it->second.arrayRef())
                     if (d.isObject()) d.objectRef()["id"] = static_cast<double>(domain++);
         }},
        // Nothing to rewrite: format 3 only adds "branch_edits", which a format-2 file has
        // none of. No description, so that opening a format-2 file reports no upgrade.
        {2, "", [](Value::Object&) {}},
    };
    return steps;
}

void assignIds(Project& p) {
    std::set<std::uint64_t> trees;
    std::uint64_t maxTree = 0;
    for (const ProjectInstance& t : p.instances)
        maxTree = std::max(maxTree, t.id);
    p.nextTreeId = std::max(p.nextTreeId, maxTree + 1);
    for (ProjectInstance& t : p.instances) {
        if (t.id == 0 || !trees.insert(t.id).second) {
            if (p.nextTreeId > kMaxTreeId)
                throw LimitExceeded("a project's tree ids are limited to " +
                                    std::to_string(kMaxTreeId));
            t.id = p.nextTreeId++;
            trees.insert(t.id);
        }
    }
    std::set<std::uint64_t> domains;
    std::uint64_t maxDomain = 0;
    for (const PlacementDomain& d : p.domains)
        maxDomain = std::max(maxDomain, d.id);
    for (PlacementDomain& d : p.domains) {
        if (d.id == 0 || !domains.insert(d.id).second) {
            if (maxDomain >= kMaxDomainId)
                throw LimitExceeded("a project's domain ids are limited to " +
                                    std::to_string(kMaxDomainId));
            d.id = ++maxDomain;
            domains.insert(d.id);
        }
    }
}

QString Project::resolve(const std::string& relative) const {
    const QString p = QString::fromStdString(relative);
    if (QFileInfo(p).isAbsolute() || baseDir.isEmpty()) return p;
    return QDir(baseDir).filePath(p);
}

const ProjectSpecies* Project::findSpecies(const std::string& name) const {
    for (const ProjectSpecies& s : species)
        if (s.name == name) return &s;
    return nullptr;
}

std::uint64_t Project::newTreeSeed(std::size_t treesBefore) const {
    return treeSeed(mixSeed(seed, treesBefore + 1));
}

bool Project::usesSpecies(const std::string& name) const {
    for (const ProjectInstance& t : instances)
        if (t.species == name) return true;
    for (const PlacementDomain& d : domains)
        if (const auto count = d.counts.find(name); count != d.counts.end() && count->second > 0)
            return true;
    return false;
}

Project parseProject(const QByteArray& json, const QString& fileName, LoadReport* report) {
    const std::string file = fileName.toStdString();
    const std::string where = file.empty() ? std::string() : file + ": ";
    const std::string text = json.toStdString();
    Value root = Value::parseJson(text, file);
    if (!root.isObject()) throw InvalidInput(where + "a project file must hold a JSON object");
    const UpgradeReport upgrade = upgradeFormat(
        root.objectRef(), "sylva-project", kProjectFormatVersion, projectUpgrades(), file, false);
    if (report) {
        report->warnings = upgrade.warnings;
        report->upgrades = upgrade.applied;
    }
    try {
        Project p; // filled completely before it is returned: never half-loaded
        p.baseDir = QFileInfo(fileName).absolutePath();
        p.seed = static_cast<std::uint64_t>(root.integer("seed", 0));
        p.appVersion = root.string("app_version", "");
        if (const Value* v = root.find("species"))
            for (std::size_t i = 0; i < v->toArray("species").size(); ++i)
                p.species.push_back(parseSpeciesRef(v->toArray()[i], i));
        if (const Value* v = root.find("domains"))
            for (std::size_t i = 0; i < v->toArray("domains").size(); ++i)
                p.domains.push_back(parseDomain(v->toArray()[i], i));
        if (const Value* v = root.find("instances"))
            for (std::size_t i = 0; i < v->toArray("instances").size(); ++i)
                p.instances.push_back(parseInstance(
                    v->toArray()[i], i,
                    [&](std::size_t k, const std::string& key, const std::string& message) {
                        std::vector<JsonStep> path{std::string("instances"), i,
                                                   std::string("branch_edits"), k};
                        if (!key.empty()) path.emplace_back(key);
                        const JsonPlace place = locateJson(text, path);
                        throw InvalidInput(
                            std::vector<Diagnostic>{{file, place.line, place.column, message}});
                    }));
        if (const Value* v = root.find("obstacles"))
            for (std::size_t i = 0; i < v->toArray("obstacles").size(); ++i)
                p.obstacles.push_back(parseObstacle(v->toArray()[i], i));
        if (const Value* next = root.find("next_tree_id")) {
            const double x = next->toNumber("next_tree_id");
            if (!(x >= 1 && x <= static_cast<double>(kMaxTreeId) + 1 && x == std::floor(x)))
                throw InvalidInput("next_tree_id must be a whole number in [1, " +
                                   std::to_string(kMaxTreeId + 1) + "]");
            p.nextTreeId = static_cast<std::uint64_t>(x);
        }
        if (const Value* cam = root.find("camera")) {
            p.cameraPosition = vec3Or(*cam, "position", p.cameraPosition, "camera");
            p.cameraTarget = vec3Or(*cam, "target", p.cameraTarget, "camera");
        }
        if (const Value* light = root.find("light")) {
            p.lightDirection = vec3Or(*light, "direction", p.lightDirection, "light");
            if (glm::length(p.lightDirection) < 1e-6f)
                throw InvalidInput("light.direction must not be zero");
        }
        if (const Value* w = root.find("wind")) {
            wind::WindSettings wind;
            wind.direction = vec3Or(*w, "direction", wind.direction, "wind");
            wind.strength = static_cast<float>(w->number("strength", wind.strength));
            wind.gustiness = static_cast<float>(w->number("gustiness", wind.gustiness));
            wind.frequency = static_cast<float>(w->number("frequency", wind.frequency));
            sylva::wind::validate(wind); // names the setting and its allowed range
            p.wind = wind;
        }
        p.season = checkedSeason(root.string("season", ""), "season");
        // Species names must be unique and every reference must name one.
        for (std::size_t i = 0; i < p.species.size(); ++i)
            for (std::size_t j = 0; j < i; ++j)
                if (p.species[i].name == p.species[j].name)
                    throw InvalidInput("species \"" + p.species[i].name + "\" is defined twice");
        for (const PlacementDomain& d : p.domains)
            for (const auto& [name, count] : d.counts)
                if (!p.findSpecies(name))
                    throw InvalidInput("domain counts name unknown species \"" + name + "\"");
        for (const ProjectInstance& in : p.instances)
            if (!p.findSpecies(in.species))
                throw InvalidInput("instance names unknown species \"" + in.species + "\"");
        // Ids name trees in every export: two items with one id are an error, not a guess.
        // Missing ids (a hand-written file) are given.
        std::map<std::uint64_t, std::size_t> treeIds, domainIds;
        for (std::size_t i = 0; i < p.instances.size(); ++i)
            if (const std::uint64_t id = p.instances[i].id; id && !treeIds.emplace(id, i).second)
                throw InvalidInput("instances[" + std::to_string(treeIds[id]) + "] and instances[" +
                                   std::to_string(i) + "] have the same id " + std::to_string(id));
        for (std::size_t i = 0; i < p.domains.size(); ++i)
            if (const std::uint64_t id = p.domains[i].id; id && !domainIds.emplace(id, i).second)
                throw InvalidInput("domains[" + std::to_string(domainIds[id]) + "] and domains[" +
                                   std::to_string(i) + "] have the same id " + std::to_string(id));
        assignIds(p);
        for (const auto& [key, value] : root.toObject()) {
            bool known = false;
            for (const std::string& k : kKnownKeys)
                known = known || k == key;
            if (!known) p.extra[key] = value;
        }
        return p;
    } catch (const InvalidInput& e) {
        if (!e.diagnostics().empty()) throw;
        throw InvalidInput(where + e.what());
    }
}

Project loadProject(const QString& path, LoadReport* report) {
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly))
        throw IoError("cannot read " + path.toStdString() + ": " +
                      file.errorString().toStdString());
    return parseProject(file.readAll(), path, report);
}

Project loadProjectOrScene(const QString& path, LoadReport* report) {
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly))
        throw IoError("cannot read " + path.toStdString() + ": " +
                      file.errorString().toStdString());
    const QByteArray bytes = file.readAll();
    if (!bytes.contains("\"format\"") && bytes.contains("\"plants\""))
        return importReferenceScene(path);
    return parseProject(bytes, path, report);
}

QByteArray serializeProject(const Project& project) {
    // A project built in memory may lack ids: saved with the ids loading it would give.
    Project p = project;
    assignIds(p);
    Value::Object root = p.extra;
    root["format"] = "sylva-project";
    root["format_version"] = kProjectFormatVersion;
    root["app_version"] = p.appVersion.empty() ? std::string(SYLVA_VERSION) : p.appVersion;
    root["seed"] = static_cast<double>(p.seed);
    Value::Array species;
    for (const ProjectSpecies& s : p.species) {
        Value::Object o{{"name", s.name}, {"variants", s.variants}};
        if (s.graph) {
            o["graph"] = *s.graph;
            if (s.traits) o["traits"] = *s.traits;
        } else
            o["file"] = s.file;
        species.emplace_back(std::move(o));
    }
    root["species"] = Value(std::move(species));
    Value::Array domains;
    for (const PlacementDomain& d : p.domains) {
        Value::Object o{{"shape", d.shape}};
        if (d.id) o["id"] = static_cast<double>(d.id);
        if (d.shape == "rectangle") {
            o["min"] = arrayOf(d.min);
            o["max"] = arrayOf(d.max);
        } else if (d.shape == "polygon") {
            Value::Array pts;
            for (const glm::vec2& q : d.polygon)
                pts.push_back(arrayOf(q));
            o["points"] = Value(std::move(pts));
        } else {
            o["file"] = d.terrain;
        }
        Value::Object counts;
        for (const auto& [name, n] : d.counts)
            counts[name] = n;
        o["counts"] = Value(std::move(counts));
        domains.emplace_back(std::move(o));
    }
    root["domains"] = Value(std::move(domains));
    Value::Array instances;
    bool anyEdits = false;
    for (const ProjectInstance& in : p.instances) {
        Value::Object o{{"id", static_cast<double>(in.id)},
                        {"species", in.species},
                        {"position", arrayOf(in.position)},
                        {"rotation", in.rotation},
                        {"scale", in.scale},
                        {"seed", static_cast<double>(in.seed)},
                        {"growth", in.growth}};
        // Only when set: a project without seasons saves as it did before they existed.
        if (!in.season.empty()) o["season"] = in.season;
        if (!in.branchEdits.empty()) {
            Value::Array edits;
            for (const skel::BranchEdit& e : in.branchEdits) {
                Value::Object eo{{"branch", e.branch}};
                if (e.prune) eo["prune"] = true;
                if (e.bend) eo["bend"] = arrayOf(*e.bend);
                if (e.length != 1.0f) eo["length"] = decimalOf(e.length);
                if (e.radius != 1.0f) eo["radius"] = decimalOf(e.radius);
                if (e.lock) eo["lock"] = true;
                if (e.anchor) {
                    Value::Array a;
                    for (float f : {e.anchor->base.x, e.anchor->base.y, e.anchor->base.z,
                                    e.anchor->direction.x, e.anchor->direction.y,
                                    e.anchor->direction.z, e.anchor->length})
                        a.emplace_back(decimalOf(f));
                    eo["anchor"] = Value(std::move(a));
                }
                if (e.lock && !e.locked.empty()) {
                    auto q = [](Value::Array& row, const glm::quat& r) {
                        for (float f : {r.x, r.y, r.z, r.w})
                            row.emplace_back(decimalOf(f));
                    };
                    Value::Array nodes, leaves;
                    for (const skel::LockedNode& n : e.locked) {
                        Value::Array row{
                            static_cast<double>(n.parent), static_cast<double>(n.order),
                            decimalOf(n.radius),           decimalOf(n.offset.x),
                            decimalOf(n.offset.y),         decimalOf(n.offset.z)};
                        q(row, n.orientation);
                        nodes.emplace_back(std::move(row));
                    }
                    for (const skel::LockedLeaf& l : e.lockedLeaves) {
                        Value::Array row{static_cast<double>(l.node), decimalOf(l.size),
                                         decimalOf(l.offset.x), decimalOf(l.offset.y),
                                         decimalOf(l.offset.z)};
                        q(row, l.orientation);
                        leaves.emplace_back(std::move(row));
                    }
                    eo["locked"] = Value::Object{{"base", arrayOf(e.lockedBase)},
                                                 {"nodes", Value(std::move(nodes))},
                                                 {"leaves", Value(std::move(leaves))}};
                }
                edits.emplace_back(std::move(eo));
            }
            o["branch_edits"] = Value(std::move(edits));
            anyEdits = true;
        }
        instances.emplace_back(std::move(o));
    }
    root["instances"] = Value(std::move(instances));
    Value::Array obstacles;
    for (const ProjectObstacle& o : p.obstacles)
        obstacles.emplace_back(Value::Object{{"file", o.file},
                                             {"translate", arrayOf(o.translate)},
                                             {"rotate", arrayOf(o.rotate)},
                                             {"scale", arrayOf(o.scale)}});
    root["obstacles"] = Value(std::move(obstacles));
    root["next_tree_id"] = static_cast<double>(p.nextTreeId);
    root["camera"] =
        Value::Object{{"position", arrayOf(p.cameraPosition)}, {"target", arrayOf(p.cameraTarget)}};
    root["light"] = Value::Object{{"direction", arrayOf(p.lightDirection)}};
    if (p.wind)
        root["wind"] = Value::Object{{"direction", arrayOf(p.wind->direction)},
                                     {"strength", decimalOf(p.wind->strength)},
                                     {"gustiness", decimalOf(p.wind->gustiness)},
                                     {"frequency", decimalOf(p.wind->frequency)}};
    if (!p.season.empty()) root["season"] = p.season;
    // Format 3 only adds branch edits: a project without any is a format-2 file, and a file
    // written before keeps its bytes through opening and saving.
    if (!anyEdits) root["format_version"] = 2;
    return QByteArray::fromStdString(Value(std::move(root)).toPrettyJson() + "\n");
}

void saveProject(const Project& project, const QString& path) {
    const QByteArray bytes = serializeProject(project);
    writeFileAtomically(
        path.toStdString(),
        std::string_view(bytes.constData(), static_cast<std::size_t>(bytes.size())));
}

Project importReferenceScene(const QString& path) {
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly))
        throw IoError("cannot read " + path.toStdString() + ": " +
                      file.errorString().toStdString());
    const std::string name = path.toStdString();
    const Value root = Value::parseJson(file.readAll().toStdString(), name);
    Project p;
    p.baseDir = QFileInfo(path).absolutePath();
    p.seed = static_cast<std::uint64_t>(root.integer("seed", 0));
    PlacementDomain domain;
    if (const Value* d = root.find("domain")) {
        if (const Value* mn = d->find("min")) domain.min = vec2Of(*mn, "domain.min");
        if (const Value* mx = d->find("max")) domain.max = vec2Of(*mx, "domain.max");
    }
    const Value* plants = root.find("plants");
    if (!plants) throw InvalidInput(name + ": a reference scene needs \"plants\"");
    for (const Value& plant : plants->toArray("plants")) {
        ProjectSpecies s;
        s.file = plant.string("file", "");
        if (s.file.empty()) throw InvalidInput(name + ": each plant needs a \"file\"");
        s.name = plant.string(
            "name", QFileInfo(QString::fromStdString(s.file)).completeBaseName().toStdString());
        if (!p.findSpecies(s.name)) p.species.push_back(s);
        // Summed per species within the limit of a project's counts (an int overflowed here).
        const std::int64_t quantity = plant.integer("quantity", 1);
        int& count = domain.counts[s.name];
        if (quantity < 0 || quantity > 100'000'000 - count)
            throw InvalidInput(name + ": the quantities of \"" + s.name +
                               "\" must be whole numbers in [0, 1e8], also summed");
        count += static_cast<int>(quantity);
    }
    p.domains.push_back(domain);
    if (const Value* meshes = root.find("collision_meshes"))
        for (const Value& m : meshes->toArray("collision_meshes")) {
            ProjectObstacle o;
            o.file = m.isString() ? m.toString() : m.string("file", "");
            p.obstacles.push_back(o);
        }
    assignIds(p);
    return p;
}

} // namespace sylva::doc
