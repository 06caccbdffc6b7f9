#pragma once

#include <cstdint>
#include <filesystem>
#include <functional>
#include <map>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include <glm/glm.hpp>

#include "engine/mesh/mesh.h"
#include "engine/skeleton/skeleton.h"
#include "engine/util/progress.h"
#include "engine/util/value.h"

namespace sylva::env {
class ObstacleScene;
struct CrownVolume;
} // namespace sylva::env

namespace sylva::graph {

/// Where one tree of a scene stands, for the nodes that react to it (adapt, LOD meshing).
/// Absent (nullptr) when a species is evaluated on its own.
struct TreeContext {
    glm::mat4 transform{1.0f};                     ///< tree local frame → world
    const env::ObstacleScene* obstacles = nullptr; ///< the scene's obstacles, or none
    const env::CrownVolume* neighbours = nullptr;  ///< neighbouring crowns (world space)
    std::size_t neighbourCount = 0;
    glm::vec3 lightDirection{0.0f, -1.0f, 0.0f}; ///< direction the light travels
    double cameraDistance = -1.0;                ///< metres from the camera; < 0: no camera
    /// The species' leaf cards (tube_mesh's leaf_scale, leaf_aspect), so that adaptation drops
    /// the leaves whose cards would touch an obstacle.
    float leafScale = 1.0f;
    float leafAspect = 0.5f;
    std::uint64_t key = 0; ///< identifies this context in the evaluator's cache (instance id+1)
};

/// Whole-tree traits of a species used by forests and metrics (species file "traits").
struct SpeciesTraits {
    double woodDensity = 550.0;   ///< oven-dry wood density, kg/m³, (0, 2000]
    double carbonFraction = 0.47; ///< carbon per dry mass, (0, 1]
    double crownRadius = 0.0;     ///< metres; 0: measured from a generated tree
};

/// One node of a species graph as written in a species file.
struct NodeDesc {
    std::string id;
    std::string type;
    Value params = Value::Object{};
    std::vector<std::string> inputs;
};

/// A species: a small DAG of nodes whose `output` node yields the tree.
struct SpeciesGraph {
    std::string name;
    std::vector<NodeDesc> nodes;
    std::string output;
    /// Folder that relative paths in parameters (grammar_file, mesh files) resolve against.
    std::filesystem::path baseDir;
    /// The file this graph came from, for diagnostics ("" when built in code).
    std::string sourceFile;
    SpeciesTraits traits;

    const NodeDesc* findNode(const std::string& id) const;
    NodeDesc* findNode(const std::string& id);
    /// The node whose result is the tree's skeleton before meshing: the output node's single
    /// input when the output is a mesher (meshOutput()), else the output node itself.
    const std::string& skeletonSource() const;
};

/// What a node type is for, declared by the type (engine/nodes), so that code outside nodes/
/// asks the role instead of testing a type's name.
enum class NodeRole {
    Other,     ///< passes or adds data
    Leaves,    ///< places leaves on the skeleton it passes on
    Generator, ///< grows a skeleton
    Adapt,     ///< reacts to the scene's obstacles and neighbours
    Mesher,    ///< makes the tree's mesh from one skeleton input
};

/// One tree of a stand (NodeType::stand): where it stands, its seed and its generator node's
/// parameters.
struct StandMember {
    glm::vec3 position{0.0f};
    std::uint64_t seed = 0;
    const Value* params = nullptr;
};

/// The trait of a generator whose trees of one scene grow together, competing for light and
/// space (self_organizing), instead of each from its seed alone: the forest grows them in a
/// stage of their own, standing upright at their placed position, and never instances them.
struct StandGrowth {
    /// The stand a tree joins, from its generator's parameters: trees of one key grow together.
    /// \throw InvalidInput for parameters the generator refuses.
    std::function<int(const Value& params)> standOf;
    /// Grows one stand's trees together among the obstacles (triangles, three points each);
    /// one skeleton per member, in the members' order, relative to its position.
    std::function<std::vector<skel::Skeleton>(const std::vector<StandMember>& members,
                                              const std::vector<glm::vec3>& obstacleTriangles,
                                              Progress& progress)>
        grow;
};

struct NodeType;

/// The registered node type \p type, null when unknown; registers the built-in types first.
/// What code outside engine/nodes asks instead of testing a type's name: its role, its stand
/// growth, its parameters (findParam).
const NodeType* findType(const std::string& type);

/// The role of the registered node type \p type (NodeRole::Other when unknown); registers the
/// built-in types first.
NodeRole roleOf(const std::string& type);

/// The stand growth of the registered node type \p type; null when its trees grow alone (or
/// the type is unknown). Registers the built-in types first.
const StandGrowth* standGrowthOf(const std::string& type);

/// The graph's output node when it is a mesher with one input (the skeleton it meshes), else
/// null: the one test of "does this species end in a mesher" (forest plans, LOD chains,
/// seasons, wind data).
const NodeDesc* meshOutput(const SpeciesGraph& graph);

/// What a node produces. Generators fill `skeleton`, meshing nodes fill `mesh` (and pass the
/// skeleton through). `stats` holds counts ("symbols", "segments", ...) and `timingsMs` the time
/// of each stage ("expand", "interpret", "mesh"), both accumulated along the inputs.
struct NodeOutput {
    std::shared_ptr<const skel::Skeleton> skeleton;
    std::shared_ptr<const mesh::Mesh> mesh;
    std::map<std::string, double> stats;
    std::map<std::string, double> timingsMs;
};

/// Everything a node's evaluate function may look at. It must be a pure function of these.
struct NodeContext {
    const NodeDesc& node;
    const Value& params;                   ///< node.params, with overrides applied
    std::vector<const NodeOutput*> inputs; ///< in the order of node.inputs
    std::uint64_t seed = 0;                ///< evaluation seed (instance seed)
    bool seedOverridden = false;           ///< true when the caller set the seed explicitly
    const std::filesystem::path& baseDir;
    const std::string& sourceFile;
    Progress& progress;
    const TreeContext* tree = nullptr; ///< set when the species grows as part of a scene
    /// Generators record where each skeleton node came from (Skeleton::sourceLine); set by
    /// Evaluator::setTraceSources for the species editor's preview.
    bool traceSources = false;

    /// Resolves a path parameter against baseDir.
    std::filesystem::path resolve(const std::string& relative) const;
    /// Throws InvalidInput "<sourceFile>: node '<id>': <message>".
    [[noreturn]] void fail(const std::string& message) const;
};

/// What a parameter holds, for validation and for the editor's typed panels.
enum class ParamKind {
    Number,  ///< a real number in [min, max]
    Integer, ///< a whole number in [min, max]
    Bool,
    Enum,   ///< one of `choices`
    Vector, ///< [x, y, z], each component in [min, max]
    File,   ///< a path, relative to the species file
    Curve,  ///< a list of [t, value] points (a profile), or a named shape
    Text,   ///< multi-line text (an L-system grammar)
    Object, ///< a structured value edited as JSON (an envelope, a list of obstacles)
};

/// One parameter of a node type: the single description that validation, `docs/species.md`,
/// `sylva-cli nodes`, Python and the editor's panels all read.
struct ParamSpec {
    std::string name;
    ParamKind kind = ParamKind::Number;
    Value defaultValue;  ///< null: unset by default (the node works without it)
    double min = -1e300; ///< Number, Integer, Vector components
    double max = 1e300;
    bool minOpen = false;             ///< the range excludes min, e.g. (0, 100]
    std::string unit;                 ///< "m", "°", "px", "" (a count or a ratio)
    std::string doc;                  ///< one line; names the paper's symbol where there is one
    std::vector<std::string> choices; ///< Enum
    std::string group;                ///< panel section ("Growth", "Bending", ...)

    /// "[1, 2000000]" or "(0, 100] m": the allowed range as a user reads it.
    std::string rangeText() const;
    /// "Leaf scale" for leaf_scale, "LOD distance" for lod_distance: the name as a panel shows it
    /// (Python, files and the command line keep the name itself).
    std::string label() const;
};

/// A parameter's name in words, lower case but for acronyms: "leaf scale", "LOD distance",
/// "node IDs". Undo steps say "Change leaf scale"; ParamSpec::label capitalises the first.
std::string paramWords(std::string_view name);

/// What flows along an edge of the species graph.
enum class PortKind {
    Skeleton, ///< branches (and grammar or placed leaves)
    Mesh,     ///< a mesh, with the skeleton it was made from
};
const char* portKindName(PortKind kind);

/// A node type: its name, the inputs it accepts, its parameters and its evaluate function.
struct NodeType {
    std::string name;
    int minInputs = 0;
    int maxInputs = 0;
    std::function<NodeOutput(const NodeContext&)> evaluate;
    /// Parameter names this type understands; unknown keys in a species file are an error.
    /// Filled from `params` by NodeRegistry::add() when left empty.
    std::vector<std::string> knownParams;
    std::vector<ParamSpec> params;                     ///< every parameter, in panel order
    std::string doc;                                   ///< one line: what the node does
    std::string category;                              ///< "Generator", "Environment", "Geometry"
    std::vector<PortKind> accepts{PortKind::Skeleton}; ///< kinds an input may carry
    /// What the node yields; `Mesh` when it meshes, `Skeleton` for generators. A node whose
    /// output is the same kind as its input (leaves) says so with outputFollowsInput.
    PortKind output = PortKind::Skeleton;
    bool outputFollowsInput = false;
    NodeRole role = NodeRole::Other; ///< what the type is for (forest plans ask it)
    /// Set by a generator whose trees grow in a stand (see StandGrowth); null: each tree grows
    /// from its seed alone.
    std::shared_ptr<const StandGrowth> stand = nullptr;

    const ParamSpec* findParam(const std::string& name) const;
};

/// Checks one parameter value against its spec (kind, range, choices); throws InvalidInput
/// "<name> must be in [lo, hi] unit, got v" (the caller adds where: file and node).
void checkParam(const ParamSpec& spec, const Value& value);

/// The table of node types. registerBuiltinNodeTypes() fills it with every engine node
/// (lsystem, tube_mesh, space_colonization, ...); tests may register their own.
class NodeRegistry {
public:
    static NodeRegistry& instance();
    void add(NodeType type);
    const NodeType* find(const std::string& name) const;
    std::vector<std::string> names() const;

private:
    std::map<std::string, NodeType> mTypes;
};

/// Registers every built-in node type once (idempotent, thread-safe). Defined by the node
/// types' own folder (engine/nodes), which graph/ does not include: graph is the model and the
/// evaluator, nodes are plug-ins to it.
void registerBuiltinNodeTypes();

/// The kind of value node \p id yields in \p graph (follows inputs for pass-through nodes).
/// \throw InvalidInput for an unknown node or type.
PortKind outputKind(const SpeciesGraph& graph, const std::string& id);

/// Why an edge \p from → \p to (from's output into a new input of to) cannot be added: an
/// unknown node, a node that takes no more inputs, a kind the input does not accept, or a
/// cycle. Empty when the edge is allowed. The editor shows this to the user.
std::string connectionError(const SpeciesGraph& graph, const std::string& from,
                            const std::string& to);

/// Evaluates a species graph. Each node is evaluated once per change: results are cached by a
/// hash of (type, parameters, seed, input hashes), so changing one parameter re-runs only that
/// node and what depends on it.
class Evaluator {
public:
    explicit Evaluator(SpeciesGraph graph);

    const SpeciesGraph& graph() const { return mGraph; }
    /// The graph as a shared, immutable copy (a grown tree keeps the graph it grew from): made
    /// once after each change of the graph, then handed out again without copying.
    std::shared_ptr<const SpeciesGraph> sharedGraph() const;
    /// Checks ids, types, parameters (against the metadata), port kinds, cycles and the output
    /// node; nodes the output does not depend on may still lack inputs. Throws InvalidInput.
    void validate() const;

    /// Sets node.param (a --set override or an editor edit). Throws InvalidInput for an
    /// unknown node.
    void setParam(const std::string& nodeId, const std::string& key, Value value);
    /// Replaces the whole graph, keeping cached results of unchanged nodes.
    void setGraph(SpeciesGraph graph);

    /// Evaluates the output node (or \p nodeId) with the given seed. When \p seed is absent, the
    /// generators use their own seed parameter (e.g. a grammar's `seed:`).
    const NodeOutput& evaluate(Progress& progress = noProgress());
    const NodeOutput& evaluate(std::uint64_t seed, Progress& progress = noProgress());
    const NodeOutput& evaluateNode(const std::string& nodeId, bool seedOverridden,
                                   std::uint64_t seed, Progress& progress = noProgress());
    /// Evaluates the output node for one tree of a scene: nodes that react to the scene
    /// (adapt, LOD meshing) read \p tree; the cache key includes tree.key.
    const NodeOutput& evaluateTree(std::uint64_t seed, const TreeContext& tree,
                                   Progress& progress = noProgress(),
                                   const std::string& nodeId = {});

    /// Generators that can (lsystem) record where each skeleton node came from
    /// (Skeleton::sourceLine), so the editor can show the rule behind a clicked branch. Off by
    /// default (it costs the derivation its fast path); changing it drops the cached results.
    void setTraceSources(bool on);
    bool traceSources() const { return mTraceSources; }

    /// How many node evaluations ran (cache misses) since construction; for tests.
    std::size_t evaluations() const { return mEvaluations; }

    /// What the last evaluation did at one node: the editor shows each node's compute time and
    /// error state.
    struct NodeRun {
        double ms = 0.0;             ///< time of the node's own last computation
        bool ran = false;            ///< computed by the last evaluate() (else cached or unused)
        std::size_t evaluations = 0; ///< computations since construction (cache misses)
        std::string error;           ///< the node's error in the last evaluate(), if it failed
    };
    const std::map<std::string, NodeRun>& runs() const { return mRuns; }

private:
    struct CacheEntry {
        std::uint64_t key = 0;
        std::shared_ptr<NodeOutput> output;
    };
    std::uint64_t nodeKey(const NodeDesc& node, std::uint64_t seed, bool seedOverridden,
                          const std::vector<std::uint64_t>& inputKeys) const;
    const TreeContext* mTree = nullptr; ///< during evaluateTree() only
    bool mTraceSources = false;

    /// Called whenever mGraph changes: the parameters' hashes and the shared copy.
    void graphChanged();

    SpeciesGraph mGraph;
    /// mGraph.nodes[i].params.hash(), computed once a graph (Value::hash prints the JSON).
    std::vector<std::uint64_t> mParamHashes;
    mutable std::shared_ptr<const SpeciesGraph> mShared; ///< sharedGraph()'s copy, or null
    std::map<std::string, CacheEntry> mCache;
    std::map<std::string, NodeRun> mRuns;
    std::size_t mEvaluations = 0;
};

} // namespace sylva::graph
