#pragma once

#include <cstdint>
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "engine/environment/adapt.h"
#include "engine/environment/obstaclescene.h"
#include "engine/forest/metrics.h"
#include "engine/graph/graph.h"
#include "engine/mesh/lodchain.h"
#include "engine/mesh/mesh.h"
#include "engine/mesh/treemesh.h"
#include "engine/mesh/tubemesh.h"
#include "engine/placement/placement.h"
#include "engine/skeleton/branches.h"
#include "engine/skeleton/skeleton.h"
#include "engine/util/progress.h"

namespace sylva::forest {

class TreeCache;

/// A species of a scene: its graph (output = a meshing node whose input yields the skeleton).
struct SceneSpecies {
    std::string name;
    graph::SpeciesGraph graph;
    /// K, the number of variants instanced trees of this species share (the project's per-species
    /// setting), 0..256; 0: none, every tree of the species is grown for its place (hero
    /// species); -1: ForestOptions::variantsPerSpecies.
    int variants = -1;
};

/// Everything a forest is built from; the document layer fills it from a `.sylva` project.
struct ForestScene {
    std::uint64_t seed = 0;
    std::vector<SceneSpecies> species;
    std::vector<placement::Domain> domains;
    std::vector<placement::Instance> handPlaced; ///< species index, position, rotation (radians)...
    std::shared_ptr<const env::ObstacleScene> obstacles; ///< may be null
    std::shared_ptr<const env::ObstacleScene> ground;    ///< terrain; null = flat ground y = 0
    glm::vec3 camera{0.0f, 20.0f, 80.0f};
    glm::vec3 lightDirection{0.3f, -1.0f, 0.2f};
    /// The season of every tree without one of its own (Instance::season); unset: each
    /// species' tube_mesh `season` (summer unless the species says otherwise).
    std::optional<mesh::Season> season;
    /// Hand edits of single branches by tree id (hand-placed trees; docs/branch-edits.md),
    /// bend directions in the world frame: applied after growth and before adaptation.
    std::map<std::uint64_t, std::vector<skel::BranchEdit>> branchEdits;
};

/// One of a species' K variants: grown once from the species at a seed derived from the project
/// seed, at full growth, never adapted; instanced trees share it (drawn with their transform).
struct ForestVariant {
    std::uint32_t species = 0; ///< index into ForestScene::species
    std::uint32_t index = 0;   ///< 0..K-1 within its species
    std::string name;          ///< "<species>_v<index>"
    std::uint64_t seed = 0;
    std::shared_ptr<const mesh::Mesh> mesh;
    std::shared_ptr<const skel::Skeleton> skeleton;
    std::shared_ptr<const mesh::TreeMeshSettings> meshSettings;
    forest::TreeMetrics metrics; ///< at scale 1
    /// With ForestOptions::useLod: the variant's levels of detail, made once (level 0 = mesh;
    /// mesh::buildDistanceLevels); an instance seen from d metres at scale s draws
    /// mesh::levelFor(levels, d / s). Empty without useLod or with meshInstances off
    /// (instancing writers); with windData each level carries node ids, as the mesh does.
    std::vector<mesh::DistanceLevel> levels;
};
using VariantSink = std::function<void(const std::vector<ForestVariant>&)>;

struct ForestOptions {
    int tile = 0;            ///< 0-based tile to build
    int tileCount = 1;       ///< 1 = the whole forest
    bool useLod = true;      ///< mesh resolution from the distance to the camera
    bool adapt = true;       ///< bend/prune trees against obstacles and neighbouring crowns
    bool neighbours = true;  ///< neighbouring crowns count as obstacles
    bool buildMeshes = true; ///< false: skeletons and metrics only (sylva-cli stats)
    /// Meshes carry node ids and the trees their skeletons: what the wind writer derives the
    /// wind model's per-vertex data from (wind::addWindData; docs/wind.md).
    bool windData = false;
    std::size_t batchSize = 64; ///< trees generated in parallel before they are handed on
    placement::PlacementMethod placement = placement::PlacementMethod::Grid;
    /// Trees of an earlier build of the same scene to reuse when their inputs are unchanged
    /// (the editor's regeneration after an edit); null: every tree is grown.
    TreeCache* cache = nullptr;
    /// Identifies the obstacle and ground meshes for the cache: the caller changes it whenever
    /// they change (the pointers alone could be reused by a new scene).
    std::uint64_t obstaclesKey = 0;
    /// K for species that do not set their own (SceneSpecies::variants), 1..256.
    int variantsPerSpecies = 8;
    /// true: a domain tree that touches no obstacle and no neighbour's crown is an instance of
    /// one of its species' variants (hand-placed trees are always grown from their own seed);
    /// false: every tree is grown and adapted uniquely.
    bool instancing = true;
    /// With instancing: a domain tree that does touch an obstacle or a neighbour's crown, of a
    /// species whose growth does not see the tree's place (no adapt node in its graph, not
    /// self-organizing: its skeleton is a function of the seed alone), starts from the skeleton
    /// of the variant its seed picks and is then adapted (bent, pruned, leaf cards dropped) and
    /// meshed for its place, so its geometry is still its own. Growing it from its own seed is
    /// about two thirds of a unique tree's cost and gives another skeleton of the same species
    /// that the adaptation then changes in the same way. A tree clear of the obstacles that the
    /// coarse crown-cylinder test made unique but whose variant, placed, reaches no neighbour's
    /// crown core (adaptation changes nothing) is an instance after all. false: every unique
    /// tree is grown from its own seed (hand-placed trees always are).
    bool adaptVariants = true;
    /// Called once, before the first tree batch, with every variant of the built tile's
    /// species (see ForestVariant); may be empty.
    VariantSink onVariants;
    /// With useLod: true, each instanced tree's mesh is its variant meshed at the tree's
    /// distance (for consumers that draw every tree's own mesh: OBJ, FBX, the viewport);
    /// false, it is the variant's shared mesh (writers that instance the variants, glTF, USD:
    /// no mesh is made per instance).
    bool meshInstances = true;
    /// Keep each unique tree's skeleton as grown, before its branch edits and adaptation
    /// (ForestTree::grown): what an editor lists the branches and their ids of.
    bool keepGrown = false;
};

/// One finished tree, in its own local frame; `instance.transform()` places it in the world.
struct ForestTree {
    placement::Instance instance;
    std::string name; ///< "<species>_<id>"
    /// Index into the variant list handed to ForestOptions::onVariants; -1: a unique tree
    /// (grown and adapted for its place). An instanced tree's skeleton and meshSettings are its
    /// variant's (shared, not copied), in the tree's local frame like a unique tree's; so is its
    /// mesh without the camera LOD (ForestOptions::useLod false) or with meshInstances false.
    /// Otherwise the mesh is the variant's skeleton meshed at the tree's camera distance, as a
    /// unique tree's is.
    std::int32_t variant = -1;
    /// A unique tree adapted from a variant's skeleton (ForestOptions::adaptVariants): that
    /// variant's index; -1 otherwise (instanced, or grown from its own seed).
    std::int32_t adaptedFrom = -1;
    /// An instance that adaptation's test found touching no neighbour's crown core (the coarse
    /// crown-cylinder test had not cleared it): work was done for it, as for a unique tree.
    bool instanceChecked = false;
    std::shared_ptr<const mesh::Mesh> mesh;
    /// The skeleton the mesh was made from (adapted, in the tree's frame; shared, not copied).
    std::shared_ptr<const skel::Skeleton> skeleton;
    /// How `mesh` was made, so that a viewer can make coarser meshes of the same tree without
    /// deriving anything again: the species' meshing settings seeded for this tree, before the
    /// camera's level of detail was applied (no project camera, every leaf card). Null when no
    /// mesh was built (ForestOptions::buildMeshes false).
    std::shared_ptr<const mesh::TreeMeshSettings> meshSettings;
    /// The distance (m) from the project camera the mesh's level of detail was chosen for; 0
    /// when the forest was built without the camera LOD (ForestOptions::useLod false).
    double meshCameraDistance = 0.0;
    forest::TreeMetrics metrics;
    env::AdaptStats adapt;
    /// With ForestOptions::keepGrown: the skeleton as grown, before branch edits and adaptation
    /// (an instance: its variant's); the ids edits name are this skeleton's branches'.
    std::shared_ptr<const skel::Skeleton> grown;
    /// What the tree's branch edits did (ForestScene::branchEdits; empty without edits).
    skel::BranchEditReport branchEdits;
};

/// What a build did. CPU times are summed over threads; `wallMs` is elapsed time.
struct ForestStats {
    std::size_t treesInScene = 0; ///< all trees of all tiles
    std::size_t trees = 0;        ///< trees of the built tile
    std::size_t vertices = 0, triangles = 0;
    std::size_t collidingTrees = 0, prunedNodes = 0;
    std::size_t instanced =
        0;                  ///< trees of the tile drawn as a variant (instanced + unique == trees)
    std::size_t unique = 0; ///< trees of the tile grown and adapted for their place
    /// Of the unique trees, those adapted from their variant's skeleton (adaptVariants).
    std::size_t adaptedVariants = 0;
    /// Of the instanced trees, those ForestTree::instanceChecked.
    std::size_t instancedByCheck = 0;
    /// Variants grown and handed to onVariants (each counted once): K for each species with a
    /// domain tree in the tile, none for a species whose trees are all hand-placed.
    std::size_t variants = 0;
    std::vector<placement::Shortfall> shortfalls;
    /// Branch edits applied, and those whose branch the grown tree does not have (orphaned:
    /// kept in the project, reported in `warnings`, never an error).
    std::size_t branchEdits = 0, orphanedEdits = 0;
    /// What a user should hear of, in instance order ("tree 3: branch 0.9 of the edits not
    /// found").
    std::vector<std::string> warnings;
    forest::SceneMetrics metrics;
    std::map<std::string, double> cpuMs;  ///< generate, adapt, mesh
    std::map<std::string, double> wallMs; ///< load, place, build (set by callers too)
};

/// Receives finished trees in instance order, one batch at a time (streaming exporters).
using TreeSink = std::function<void(const std::vector<ForestTree>& batch)>;

/// Crown radius (m) and crown height band of a species at scale 1, measured on one sample tree
/// when the species' traits do not give a radius; and the trunk's bark radius at its base (m,
/// the larger of the root's and its trunk child's rings as \p tubes draws them, or the
/// skeleton's radii without \p tubes).
struct CrownShape {
    float radius = 1.0f, bottom = 0.0f, top = 1.0f;
    float trunk = 0.0f;
};
CrownShape measureCrown(const graph::SpeciesGraph& species, std::uint64_t seed,
                        const mesh::TubeSettings* tubes = nullptr);

/// Builds a forest: places the trees (hand-placed ones first, then the domains'), selects the
/// tile, and for each of its trees evaluates the species graph with the tree's seed, adapts the
/// skeleton to the obstacles and neighbouring crowns (from the rest pose), meshes it at the LOD
/// its distance to the camera asks for, and measures it. Trees are built in parallel batches and
/// handed to \p sink in instance order, so the output is identical on any thread count, and the
/// union of the tiles' trees equals the whole forest's.
/// \throw InvalidInput, IoError, LimitExceeded, Cancelled (through \p progress).
ForestStats buildForest(const ForestScene& scene, const ForestOptions& options,
                        const TreeSink& sink, Progress& progress = noProgress());

} // namespace sylva::forest
