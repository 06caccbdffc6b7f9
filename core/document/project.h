#pragma once

#include <QByteArray>
#include <QString>

#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "document/formatupgrade.h"
#include "engine/skeleton/branches.h"
#include "engine/util/value.h"
#include "engine/wind/windmodel.h"

namespace sylva::doc {

/// Current version of the project format ("format": "sylva-project").
/// 2 (Sylva 0.30, issue 30): trees and domains carry stable ids, species their variant count,
/// and domains scatter independently of hand-placed trees (see projectUpgrades()).
/// 3 (issue 43): hand-placed trees may carry "branch_edits"; a project without any is still
/// saved as format 2, so files written before keep their bytes (see serializeProject()).
inline constexpr int kProjectFormatVersion = 3;

/// Ids of hand-placed trees are in [1, kMaxTreeId] (domain trees' ids are above: see
/// placement::kDomainIdStride); domain ids in [1, kMaxDomainId].
inline constexpr std::uint64_t kMaxTreeId = 999'999'999ull;
inline constexpr std::uint64_t kMaxDomainId = 9'000'000'000ull;
/// Default number of variants per species (ProjectSpecies::variants).
inline constexpr int kDefaultVariants = 8;

/// A species used by the project: a species file (relative to the project) or an inline graph.
struct ProjectSpecies {
    std::string name;
    std::string file;                  ///< relative to the project file; empty when inline
    std::optional<sylva::Value> graph; ///< inline {"nodes": [...], "output": ...}
    /// Inline species only: the species file's "traits" (wood density, carbon, crown radius).
    std::optional<sylva::Value> traits;
    /// K: how many variants the species' instanced trees share (0..256; "variants"); 0: none,
    /// every tree of the species is grown for its place.
    int variants = kDefaultVariants;
    bool operator==(const ProjectSpecies&) const = default;
};

/// Where trees are scattered and how many of each species.
struct PlacementDomain {
    /// Stable id: seeds the domain's own scattering and names its trees (domain id · 10^9 +
    /// slot). 0 until assignIds() gives it one.
    std::uint64_t id = 0;
    std::string shape = "rectangle";   ///< "rectangle" | "polygon" | "terrain"
    glm::vec2 min{-50.0f}, max{50.0f}; ///< x and z on the ground (rectangle), metres
    std::vector<glm::vec2> polygon;    ///< x,z corners (polygon)
    std::string terrain;               ///< mesh file (terrain), relative to the project
    std::map<std::string, int> counts; ///< species name → number of trees
    bool operator==(const PlacementDomain&) const = default;
};

/// A tree placed by hand.
struct ProjectInstance {
    /// Stable id, kept in the file and by every edit, never reused within a project (see
    /// Project::nextTreeId). 0 until assignIds() gives it one.
    std::uint64_t id = 0;
    std::string species;
    glm::vec3 position{0.0f};
    double rotation = 0.0; ///< degrees about +Y
    double scale = 1.0;
    std::uint64_t seed = 0;
    double growth = 1.0; ///< growth stage 0..1
    /// The tree's own season ("spring", "summer", "autumn", "winter"); empty: the project's.
    std::string season;
    /// Hand edits of single branches by their stable ids ("branch_edits"; docs/branch-edits.md),
    /// applied after growth and before adaptation. At most one edit a branch; bend is a world
    /// direction.
    std::vector<skel::BranchEdit> branchEdits;
    bool operator==(const ProjectInstance&) const = default;
};

/// Tree seeds are kept below this prime: short to read and type, and exact through JSON's
/// doubles.
inline constexpr std::uint64_t kTreeSeedLimit = 1000000007ull;
/// A tree seed made from any 64-bit value (a mixed seed, a random draw).
constexpr std::uint64_t treeSeed(std::uint64_t any) {
    return any % kTreeSeedLimit;
}

/// An obstacle mesh with its transform (rotate in degrees about x, y, z, applied in that order).
struct ProjectObstacle {
    std::string file; ///< relative to the project file
    glm::vec3 translate{0.0f}, rotate{0.0f}, scale{1.0f};
    bool operator==(const ProjectObstacle&) const = default;
};

/// The document behind a `.sylva` file. Paths are kept as written (relative to the project) and
/// resolved with resolve().
struct Project {
    std::uint64_t seed = 0;
    std::string appVersion;
    std::vector<ProjectSpecies> species;
    std::vector<PlacementDomain> domains;
    std::vector<ProjectInstance> instances;
    std::vector<ProjectObstacle> obstacles;
    /// The id the next hand-placed tree gets: above every id the project ever gave, so a removed
    /// tree's id is never given again ("next_tree_id" in the file).
    std::uint64_t nextTreeId = 1;
    glm::vec3 cameraPosition{0.0f, 20.0f, 80.0f}, cameraTarget{0.0f};
    glm::vec3 lightDirection{0.3f, -1.0f, 0.2f};
    /// The project's wind ("wind" in the file; docs/wind.md): what the viewport plays and what
    /// wind exports use; the model's own settings, stored once. Unset: the engine's default,
    /// nothing saved (files that never set it keep their bytes). Its period (a clip's length)
    /// is an export's setting: a project's wind keeps the default one, and the file has none.
    std::optional<wind::WindSettings> wind;
    /// The season of every tree without its own ("spring", "summer", "autumn", "winter");
    /// empty: each species' own (summer, the look of files written before seasons existed).
    std::string season;
    /// Keys this version does not know, kept so that saving never drops another tool's data.
    sylva::Value::Object extra;

    QString baseDir; ///< folder of the project file (not saved)
    QString resolve(const std::string& relative) const;
    const ProjectSpecies* findSpecies(const std::string& name) const;
    /// Whether any tree grows from species \p name: a hand-placed tree of it, or a domain that
    /// scatters at least one. An edit of a species nobody uses regrows nothing.
    bool usesSpecies(const std::string& name) const;
    /// The seed of a tree added without one after \p treesBefore others: it depends only on
    /// the project seed and that count, so scripts and the editor's menus are repeatable.
    std::uint64_t newTreeSeed(std::size_t treesBefore) const;
    bool operator==(const Project&) const = default;
};

/// Gives an id to every tree and domain without one (0) or with one an earlier item already has:
/// trees from nextTreeId on, domains above the largest domain id; raises nextTreeId above every
/// tree id. Loading, the document and makeForestScene call it, so projects built in memory
/// (scripts) get ids too. \throw LimitExceeded when the ids run out.
void assignIds(Project& project);

/// Warnings produced while loading (upgrades applied, newer file).
struct LoadReport {
    std::vector<std::string> warnings;
    std::vector<std::string> upgrades;
};

/// Parses a project; throws InvalidInput (naming the file, and line/column for JSON syntax) and
/// never returns a half-loaded project. A file from a newer Sylva loads with a warning.
Project parseProject(const QByteArray& json, const QString& fileName, LoadReport* report = nullptr);
Project loadProject(const QString& path, LoadReport* report = nullptr);
/// Canonical, indented JSON; load → save reproduces a saved file byte for byte.
QByteArray serializeProject(const Project& project);
/// Atomic save (temporary + rename).
void saveProject(const Project& project, const QString& path);

/// Imports the JSON scene description of the reference implementation (reference 000 §4.1):
/// {"plants": [{"file": "alder.txt", "quantity": 100}, ...], "collision_meshes": ["wall.obj"],
///  optional "domain": {"min": [x, z], "max": [x, z]}, "seed"}. Grammar files become species.
Project importReferenceScene(const QString& path);

/// A `.sylva` project (loadProject), or the reference implementation's scene description (it
/// has "plants" and no "format"; importReferenceScene). What sylva-cli and the editor open.
Project loadProjectOrScene(const QString& path, LoadReport* report = nullptr);

/// Checks one branch edit as the file and the Document accept it; InvalidInput names \p where,
/// the setting and its range.
void checkBranchEdit(const skel::BranchEdit& edit, const std::string& where);
/// Whether \p edit changes nothing (no prune, bend, length, radius or lock): not kept.
bool isEmptyEdit(const skel::BranchEdit& edit);

/// The project format's upgrade steps (exposed for tests).
const std::vector<UpgradeStep>& projectUpgrades();

} // namespace sylva::doc
