#pragma once

#include <functional>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include <QDateTime>
#include <QList>
#include <QString>
#include <QStringList>

#include <glm/glm.hpp>

#include "engine/export/treeexport.h"
#include "engine/forest/metrics.h"
#include "engine/util/progress.h"
#include "ui/generation/treelodsource.h"

namespace sylva::mesh {
struct Mesh;
}
namespace sylva::skel {
struct Skeleton;
}
namespace sylva::graph {
struct SpeciesGraph;
}
namespace sylva::env {
class ObstacleScene;
}

namespace sylva::ui {

/// One tree of a project's forest as the viewport draws it: its own mesh (shared with the next
/// generation when the tree did not change) placed by its instance transform.
struct DrawnTree {
    std::uint32_t docId = 0; ///< the document's tree id (hand-placed trees); 0 for domain trees
    std::uint64_t instanceId = 0; ///< the forest's stable tree id (name suffix)
    std::uint32_t species = 0;    ///< index into the project's species
    std::shared_ptr<const mesh::Mesh> mesh;
    glm::mat4 transform{1.0f};
    forest::TreeMetrics metrics;
    TreeLodSource lod; ///< what the viewport makes coarser levels from
    /// The skeleton as grown, before branch edits and adaptation (forest::ForestTree::grown):
    /// the branches scripts list and edits name (docs/branch-edits.md).
    std::shared_ptr<const skel::Skeleton> grown;
    /// Branch edits of the tree whose branch the grown tree lacks (kept, not applied).
    std::vector<std::string> orphanedEdits;
};

/// What one generation run produced. Plain data: it is handed from the worker thread to the UI
/// through a QFuture, so no exception ever crosses threads or signals.
struct GenerationResult {
    QString path;        ///< the species file that was loaded
    QString speciesName; ///< its "name", or the file's base name
    /// A species: its tree. A project: its obstacles and terrain (world space, submeshes
    /// "obstacle" and "ground"); the trees are in `trees`.
    std::shared_ptr<const mesh::Mesh> mesh;
    std::shared_ptr<const skel::Skeleton> skeleton;
    std::vector<DrawnTree> trees; ///< a project's trees, in instance order
    /// A project's obstacles as built (for picking them and refusing trees in their footprint).
    std::shared_ptr<const env::ObstacleScene> obstacles;
    /// A project's terrain (a terrain domain's mesh), where trees stand; null: the plane y = 0.
    std::shared_ptr<const env::ObstacleScene> ground;
    std::map<std::string, double> stats;     ///< from the graph's output node
    std::map<std::string, double> timingsMs; ///< per stage, from the graph's output node
    double elapsedMs = 0.0;                  ///< load + evaluate, wall clock
    QString error;                           ///< user-facing message; empty on success
    QString warning; ///< loaded with a warning (e.g. a project from a newer Sylva); may be empty
    /// What File ▸ Export writes: the species' tree at the origin, or every tree of a project
    /// placed as sylva-cli forest places it (objects named as the CLI names them).
    std::vector<exporter::ExportTree> exportTrees;
    /// The variants exportTrees' ExportTree::variant indexes (a project's forest only).
    std::vector<exporter::ExportVariant> exportVariants;
    bool compactObj = false; ///< OBJ precision: compact for forests, full for one tree (as the CLI)
    /// The files the result was read from (absolute): the species or project file, grammar and
    /// other files its nodes name, a project's species and obstacle meshes. Filled as far as
    /// loading got, so a file with an error is known too. The editor reloads when one changes.
    QStringList sources;
    /// Modification time of each of sources when it was about to be read (invalid: missing),
    /// so that a change during the generation is still seen (stampSources()).
    QList<QDateTime> sourceStamps;
    /// A project's camera (its LOD reference), which the viewport starts from.
    bool hasCamera = false;
    glm::vec3 cameraEye{0.0f}, cameraTarget{0.0f};
    bool cancelled = false;

    bool ok() const { return error.isEmpty() && !cancelled && mesh != nullptr; }
    /// Vertices and triangles of the mesh and every tree.
    std::size_t vertexCount() const;
    std::size_t triangleCount() const;
    /// Tree height in metres: the output's "height" stat, else the mesh's vertical extent.
    double height() const;
    /// Number of branch segments: the "segments" stat, else the skeleton's segment count.
    double segments() const;
};

/// Loads the species file at \p path and evaluates its graph with the file's own seed. Runs on
/// any thread and never throws: this is the action boundary where engine exceptions
/// (InvalidInput, IoError, LimitExceeded, Cancelled) become a message in the result.
GenerationResult generateTree(const QString& path, Progress& progress = noProgress());

/// Records the modification time of every source that has none yet (call before reading them).
void stampSources(GenerationResult& result);

/// A generation of the file at \p path: a result with its path and its base name as the
/// species name, the node types registered, then \p body fills it. The engine's exceptions
/// (InvalidInput with its diagnostics, IoError, LimitExceeded, Cancelled, out of memory, anything
/// else) become the result's error or cancelled flag, so none leaves a generation; elapsedMs is
/// the time \p body took.
GenerationResult runGuarded(const QString& path,
                            const std::function<void(GenerationResult&)>& body);

} // namespace sylva::ui
