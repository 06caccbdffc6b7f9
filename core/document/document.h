#pragma once

#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <QList>
#include <QObject>
#include <QString>
#include <QStringList>
#include <QUndoStack>

#include "document/project.h"
#include "engine/graph/graph.h"

namespace sylva::doc {

/// A hand-placed tree's identity: ProjectInstance::id, saved in the project file, kept by every
/// edit (undo of a removal gives the tree its id back) and never given to another tree
/// (Project::nextTreeId). Exports name the tree by it. At most kMaxTreeId, so 32 bits hold it.
using TreeId = std::uint32_t;

/// What an edit changed, so that views update and generation regrows only that.
struct DocumentChange {
    enum What : unsigned {
        Trees = 1u << 0,     ///< trees moved, changed, added or removed (ids in `trees`)
        Species = 1u << 1,   ///< a species' graph or grammar (`species`, `node`)
        Obstacles = 1u << 2, ///< an obstacle added, removed or transformed
        Domains = 1u << 3,   ///< a placement domain or its counts
        Settings = 1u << 4,  ///< seed, camera, light, season or wind
        Reset = 1u << 5,     ///< a new or opened document: everything
    };
    unsigned what = 0;
    /// With Settings: which ones changed (doc::settingChange: "seed", "camera", "light", "season",
    /// "wind"), so that a view redraws its wind without regrowing anything.
    QStringList settings;
    QList<TreeId> trees;
    QString species;
    QString node;
};

/// One selectable thing of the document (the selection is not undoable, as in Tiled).
struct ItemRef {
    enum class Kind { Tree, Species, Obstacle, Domain, Camera, Light, Project };
    Kind kind = Kind::Project;
    std::uint32_t id = 0; ///< tree id, or index of the species, obstacle or domain
    bool operator==(const ItemRef&) const = default;
};

/// The editor's only state: the open project (species with their graphs and grammar texts,
/// trees, domains, obstacles, camera, light, seed), its undo history and the selection.
/// Widgets, scripts and tests never change the project directly: they call the edit functions
/// below, each of which validates its input (InvalidInput with the allowed range, nothing
/// changed) and pushes one undoable command (core/document/commands). Signals say exactly what
/// changed.
class Document : public QObject {
    Q_OBJECT

public:
    explicit Document(QObject* parent = nullptr);
    ~Document() override;

    const Project& project() const { return mProject; }
    QUndoStack* undoStack() { return &mUndo; }
    const QUndoStack* undoStack() const { return &mUndo; }

    /// The file the document was opened from or saved to; empty for a new document.
    QString path() const { return mPath; }
    /// Title for a window: the file's name (or "Untitled"), without the modified marker.
    QString displayName() const;
    bool isModified() const { return !mUndo.isClean(); }

    // --- files -------------------------------------------------------------------------
    /// An empty project (no species, trees or obstacles); clears the undo history.
    void newProject();
    /// Opens a `.sylva` project or a reference scene. On any error (InvalidInput with file,
    /// line and column; IoError) the document is left exactly as it was. Returns the loader's
    /// warnings (a newer file, upgrades applied).
    std::vector<std::string> open(const QString& path);
    /// Saves atomically to \p path (the current path when empty) and marks the undo stack
    /// clean. Relative paths in the project are rewritten for the new folder (Save As).
    /// \throw IoError when it cannot be written (the document keeps its state and path).
    void save(const QString& path = {});
    /// Replaces the document by \p project read from elsewhere (an autosave): its path is \p
    /// path, the undo history is empty and the document counts as modified.
    void restore(Project project, const QString& path);
    /// The project as it would be saved (canonical JSON).
    QByteArray serialized() const { return serializeProject(mProject); }

    // --- trees ---------------------------------------------------------------------------
    const std::vector<TreeId>& treeIds() const { return mTreeIds; }
    /// Index of \p id in project().instances, or -1.
    int treeIndex(TreeId id) const;
    const ProjectInstance& tree(TreeId id) const; ///< \throw InvalidInput for an unknown id
    TreeId addTree(const ProjectInstance& tree);
    /// Replaces a tree's placement, seed or species. With \p commit false (a drag in progress)
    /// the next change of the same tree merges into the same undo step.
    void setTree(TreeId id, const ProjectInstance& tree, bool commit = true);
    void removeTrees(const QList<TreeId>& ids);
    /// Copies of the trees, offset by \p offset metres with fresh seeds; returns their ids.
    QList<TreeId> duplicateTrees(const QList<TreeId>& ids, glm::vec3 offset = {1.0f, 0, 0});

    // --- species ---------------------------------------------------------------------------
    int speciesIndex(const std::string& name) const;
    /// Adds a species from a species file (kept as a reference to the file).
    void addSpecies(const std::string& name, const QString& file);
    /// Renames a species and every tree and domain count that uses it (one undo step).
    void renameSpecies(const std::string& from, const std::string& to);
    /// Removes a species no tree and no domain uses.
    void removeSpecies(const std::string& name);
    /// Sets K, how many variants the species' instanced trees share (ProjectSpecies::variants;
    /// 0: every tree of the species is grown for its place). One undo step; none when K is
    /// unchanged. \throw InvalidInput for an unknown species or K outside 0..256.
    void setSpeciesVariants(const std::string& species, int variants);
    /// The species' graph as JSON ({"nodes": [...], "output": ...}), read from its file when it
    /// is not inline. \throw InvalidInput / IoError.
    sylva::Value speciesGraph(const std::string& name) const;
    /// The species as the engine evaluates it (relative files resolve from the project).
    graph::SpeciesGraph engineSpecies(const std::string& name) const;
    /// A parameter "node.param" of a species (null when unset).
    sylva::Value param(const std::string& species, const std::string& path) const;
    /// Sets "node.param". A species read from a file becomes inline in the project on its first
    /// edit (the file itself is never written: other projects may use it); its relative file
    /// parameters are rewritten for the project's folder. \throw InvalidInput for an unknown
    /// species, node or parameter, or a graph that no longer validates.
    void setParam(const std::string& species, const std::string& path, const sylva::Value& value,
                  bool commit = true);
    /// Sets an lsystem node's grammar text (inline; replaces a grammar_file).
    void setGrammar(const std::string& species, const std::string& node, const std::string& text,
                    bool commit = true);
    /// The grammar text of an lsystem node (inline, or read from its grammar_file).
    std::string grammar(const std::string& species, const std::string& node) const;

    /// Replaces a species' graph and traits with those of a species file (a preset), keeping
    /// its name; one undo step. Relative files in the preset resolve from the project.
    /// \throw InvalidInput / IoError for an unreadable or invalid file (nothing changes).
    void applyPreset(const std::string& species, const QString& file);
    /// Writes a species as a self-contained species file at \p path (atomically): grammar files
    /// are inlined, other relative files rebased to the new folder. \throw IoError.
    void saveSpeciesAs(const std::string& species, const QString& path) const;

    // --- species graphs (the node editor; each call is one undo step) ----------------------
    /// Adds a node of \p type (with \p params; an id made from the type when \p id is empty)
    /// at \p position in the node editor. Returns its id. \throw InvalidInput for an unknown
    /// type, a taken id or bad parameters.
    std::string addNode(const std::string& species, const std::string& type,
                        const sylva::Value& params = sylva::Value::Object{},
                        const std::string& id = {}, glm::vec2 position = glm::vec2(0.0f));
    /// Removes a node and the edges from it. \throw InvalidInput for the output node, or when
    /// a node the tree needs would lose its only input.
    void removeNode(const std::string& species, const std::string& id);
    /// Feeds \p from's result into \p to. A node that takes one input has it replaced.
    /// \throw InvalidInput with engine's reason (graph::connectionError): a kind the input does
    /// not take, a cycle, an unknown node.
    void connectNodes(const std::string& species, const std::string& from, const std::string& to);
    /// Removes the edge \p from → \p to. \throw InvalidInput when the tree needs that input.
    void disconnectNodes(const std::string& species, const std::string& from,
                         const std::string& to);
    /// Makes \p id the node whose result is the tree.
    void setOutputNode(const std::string& species, const std::string& id);
    /// Where a node is drawn in the node editor (stored in the project, not used by growth).
    /// With \p commit false (a drag in progress) successive moves merge into one undo step.
    void moveNode(const std::string& species, const std::string& id, glm::vec2 position,
                  bool commit = true);
    /// Moves several nodes as one undo step (one node: moveNode).
    void moveNodes(const std::string& species,
                   const std::vector<std::pair<std::string, glm::vec2>>& positions);
    /// Deletes the edges \p edges (those not touching a deleted node) and then the nodes \p ids
    /// as one undo step, all or nothing. \throw InvalidInput as removeNode and disconnectNodes.
    void removeNodes(const std::string& species, const std::vector<std::string>& ids,
                     const std::vector<std::pair<std::string, std::string>>& edges = {});
    /// Adds copies of \p nodes (the node editor's clipboard: id, type, params, inputs,
    /// editor_position) with fresh ids, and the edges among them, as one undo step, all or
    /// nothing. The copied layout is kept with its top-left corner at \p at. Returns the new
    /// ids in the order of \p nodes. \throw InvalidInput as addNode and connectNodes.
    std::vector<std::string> pasteNodes(const std::string& species,
                                        const sylva::Value::Array& nodes, glm::dvec2 at);
    /// A node's position in the node editor; nullopt when it has none yet (laid out by depth).
    std::optional<glm::vec2> nodePosition(const std::string& species, const std::string& id) const;

    // --- obstacles, domains, settings ----------------------------------------------------
    void addObstacle(const ProjectObstacle& obstacle);
    void removeObstacle(int index);
    void setObstacle(int index, const ProjectObstacle& obstacle, bool commit = true);
    void addDomain(const PlacementDomain& domain);
    void removeDomain(int index);
    void setDomain(int index, const PlacementDomain& domain, bool commit = true);
    void setSeed(std::uint64_t seed);
    void setCamera(const glm::vec3& position, const glm::vec3& target, bool commit = true);
    void setLight(const glm::vec3& direction, bool commit = true);
    /// The project's season ("spring", "summer", "autumn", "winter"; empty: each species'
    /// own). \throw InvalidInput for another name.
    void setSeason(const std::string& season);
    /// A tree's own season (empty: the project's); one undo step like setTree.
    void setTreeSeason(TreeId id, const std::string& season);
    /// Sets the project's wind (nullopt: unset, the engine's default, nothing saved); one undo
    /// step. \throw InvalidInput naming the setting and its allowed range (wind::validate).
    void setWind(const std::optional<wind::WindSettings>& wind);

    // --- hand edits of single branches (docs/branch-edits.md) -------------------------------
    /// \throw InvalidInput for an unknown tree.
    const std::vector<skel::BranchEdit>& branchEdits(TreeId id) const;
    /// Replaces all of a tree's branch edits; one undo step. \throw InvalidInput for an
    /// unknown tree, an edit out of range (naming its setting and range) or a branch edited
    /// twice. Whether the branches exist is not checked here: an edit of a branch the grown
    /// tree lacks is kept and reported (orphaned).
    void setBranchEdits(TreeId id, const std::vector<skel::BranchEdit>& edits);
    /// Sets the edit of one branch (edit.branch), replacing its former one; an edit that changes
    /// nothing removes it. One undo step, like setBranchEdits.
    void editBranch(TreeId id, const skel::BranchEdit& edit);
    /// Removes every branch edit of a tree; one undo step (none when it had none).
    void clearBranchEdits(TreeId id);

    // --- selection (not undoable) ----------------------------------------------------------
    const QList<ItemRef>& selection() const { return mSelection; }
    QList<TreeId> selectedTrees() const;
    void setSelection(const QList<ItemRef>& items);
    void selectTrees(const QList<TreeId>& ids);
    /// The branch the Branch tool selected (docs/editor.md#the-branch-tool): a hand-placed tree
    /// and a branch id of its grown tree; its tree is then the selection. Cleared when the
    /// selection changes to anything else or the tree goes.
    struct BranchRef {
        TreeId tree = 0;
        std::string branch;
        bool operator==(const BranchRef&) const = default;
    };
    const std::optional<BranchRef>& selectedBranch() const { return mSelectedBranch; }
    /// Selects \p branch (and its tree), or none. \throw InvalidInput for an unknown tree.
    void setSelectedBranch(const std::optional<BranchRef>& branch);

    // --- for commands only (core/document/commands): raw changes with their signals --------
    void rawInsertTree(int index, TreeId id, const ProjectInstance& tree);
    ProjectInstance rawRemoveTree(TreeId id);
    void rawSetTree(TreeId id, const ProjectInstance& tree);
    void rawSetBranchEdits(TreeId id, const std::vector<skel::BranchEdit>& edits);
    void rawSetSpecies(int index, const ProjectSpecies& species, const QString& node);
    void rawInsertSpecies(int index, const ProjectSpecies& species);
    void rawRemoveSpecies(int index);
    void rawInsertObstacle(int index, const ProjectObstacle& obstacle);
    void rawRemoveObstacle(int index);
    void rawSetObstacle(int index, const ProjectObstacle& obstacle);
    void rawInsertDomain(int index, const PlacementDomain& domain);
    void rawRemoveDomain(int index);
    void rawSetDomain(int index, const PlacementDomain& domain);
    struct Settings {
        std::uint64_t seed = 0;
        glm::vec3 cameraPosition{0.0f}, cameraTarget{0.0f}, lightDirection{0.0f};
        std::string season; ///< Project::season
        std::optional<wind::WindSettings> wind;
        bool operator==(const Settings&) const = default;
    };
    Settings settings() const;
    void rawSetSettings(const Settings& settings);
    /// The id the next added tree gets (Project::nextTreeId; adding it raises nextTreeId, and
    /// undoing the add lowers it again, so undo gives back the exact bytes while no existing or
    /// removed tree's id is ever given again). \throw LimitExceeded past kMaxTreeId.
    TreeId nextTreeId() const;
    void rawSetNextTreeId(std::uint64_t next) { mProject.nextTreeId = next; }

Q_SIGNALS:
    void changed(const sylva::doc::DocumentChange& change);
    void selectionChanged();
    /// The file path or the modified state changed (for the window title).
    void titleChanged();

private:
    void replace(Project project, const QString& path);
    void emitChange(unsigned what, QList<TreeId> trees = {}, QString species = {},
                    QString node = {});
    void validateTree(const ProjectInstance& tree) const;
    ProjectSpecies inlined(const ProjectSpecies& species) const;
    /// An inline species as the engine reads it (files resolve from the project's folder).
    graph::SpeciesGraph toEngine(const ProjectSpecies& species) const;
    /// Inlines the species, applies \p edit to its graph JSON, validates and pushes one command.
    void editGraph(const std::string& species, const QString& node, const QString& label,
                   bool commit, const std::function<void(sylva::Value& graph)>& edit);
    /// The same with the whole inlined species (an edit of several steps validates each).
    void editSpecies(const std::string& species, const QString& node, const QString& label,
                     bool commit, const std::function<void(ProjectSpecies& species)>& edit);
    void validateSpecies(const ProjectSpecies& species) const;
    void pruneSelection();

    Project mProject;
    std::vector<TreeId> mTreeIds; ///< parallel to mProject.instances (their ids)
    QString mPath;
    QUndoStack mUndo;
    QList<ItemRef> mSelection;
    std::optional<BranchRef> mSelectedBranch;
};

} // namespace sylva::doc
