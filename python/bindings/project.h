#pragma once

// The project types both Python front doors share: `sylva.Project` and `sylva.Tree` of
// `import sylva`, and the conversions of a project's parts (trees, obstacles, domains) that the
// editor's `sylva.Document` uses over its open project. One code path for each, so that a tree,
// an obstacle or a domain reads and is given the same way in python3, Blender and the editor.
#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "convert.h"

#include "document/project.h"
#include "engine/environment/obstaclemesh.h"
#include "engine/forest/forestbuild.h"

namespace sylva::python {

/// sylva.Project: a project file's content plus what only lives in memory, obstacles and a
/// ground given as arrays (they are not saved).
struct Project {
    doc::Project project;
    std::vector<env::ObstacleMesh> arrayObstacles;
    std::optional<env::ObstacleMesh> ground;
    std::map<std::string, int> groundCounts;

    /// The scene `sylva-cli forest` would build, with the array obstacles and ground added.
    /// \throw InvalidInput when a terrain domain and an array ground are both given.
    forest::ForestScene makeScene() const;
};

/// A copy of \p project as a sylva.Project (the editor's document as `import sylva` sees a
/// project); relative paths resolve against its folder, or the working directory when untitled.
Project projectFrom(const doc::Project& project);

/// sylva.Tree: a hand-placed tree, a snapshot of its values. \c id is its stable id
/// (doc::ProjectInstance::id), in the editor's document and in a sylva.Project alike.
struct Tree {
    std::uint64_t id = 0;
    std::string species;
    glm::vec3 position{0.0f};
    double rotation = 0, scale = 1, growth = 1; ///< rotation in degrees about +Y
    std::uint64_t seed = 0;
    std::string season; ///< the tree's own season; empty: the project's
};

/// A season name from Python: None → "" (unset), else the canonical name (InvalidInput →
/// ValueError for another).
std::string seasonFrom(const py::object& season);
/// "" → None, else the name.
py::object seasonTo(const std::string& season);
/// A project's wind as Python sees it: None when unset, else a dict of direction, strength,
/// gustiness and frequency (`sylva.Project.wind` and the editor's `doc.wind()`).
py::object windTo(const std::optional<wind::WindSettings>& wind);

Tree treeOf(std::uint64_t id, const doc::ProjectInstance& t);

/// A new hand-placed tree; without \p seed one is derived from the project seed and the number
/// of trees it will be (\p treesBefore + 1), the same rule in the editor and in a sylva.Project.
doc::ProjectInstance newTree(const doc::Project& project, std::size_t treesBefore,
                             const std::string& species, const py::handle& position,
                             double rotation, double scale, std::optional<std::uint64_t> seed,
                             double growth);

/// Species names in project order.
std::vector<std::string> speciesNames(const doc::Project& project);

/// Obstacle files as dicts: file, translate, rotate (degrees about x, y, z), scale.
py::list obstaclesList(const std::vector<doc::ProjectObstacle>& obstacles);
/// Sets the parts of \p o's transform that are given (not None). \throw InvalidInput
void applyTransform(doc::ProjectObstacle& o, const py::handle& translate, const py::handle& rotate,
                    const py::handle& scale);
/// The transform of an obstacle given as arrays (unit where None). \throw InvalidInput
env::MeshTransform transformFrom(const py::handle& translate, const py::handle& rotate,
                                 const py::handle& scale);

/// A tree's branch edits as dicts: branch, and of prune, bend (x, y, z), length, radius, lock
/// those that are set (docs/branch-edits.md).
py::list branchEditsList(const std::vector<skel::BranchEdit>& edits);
/// The edit of \p branch in \p edits (a default one when it has none) with the given settings
/// changed: None leaves a setting; prune=False, bend=False or (), length=1.0, radius=1.0 and
/// lock=False clear it. Ranges are checked where the edit is set (doc::checkBranchEdit).
skel::BranchEdit branchEditFrom(const std::vector<skel::BranchEdit>& edits,
                                const std::string& branch, const py::object& prune,
                                const py::object& bend, const py::object& length,
                                const py::object& radius, const py::object& lock);
/// \p edits with \p edit set (replacing the edit of its branch; removed when it changes
/// nothing). \throw InvalidInput for an edit out of range.
std::vector<skel::BranchEdit> withBranchEdit(std::vector<skel::BranchEdit> edits,
                                             const skel::BranchEdit& edit);
/// Branches as dicts: id, parent (None for a trunk), order, base and tip (x, y, z) through
/// \p transform, length and radius times \p scale (docs/branch-edits.md).
py::list branchesList(const std::vector<skel::Branch>& branches, const glm::mat4& transform,
                      float scale);

/// Placement domains as dicts: id, shape, min, max (x, z), counts.
py::list domainsList(const std::vector<doc::PlacementDomain>& domains);
/// An (x, z) pair on the ground. \throw InvalidInput naming \p what
glm::vec2 toXZ(const py::handle& o, const char* what);

/// Binds sylva.Tree (bindForest binds sylva.Project over the struct above).
void bindTree(py::module_& m);

} // namespace sylva::python
