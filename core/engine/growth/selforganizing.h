#pragma once

#include <cstdint>
#include <optional>
#include <vector>

#include <glm/glm.hpp>
#include <glm/gtc/quaternion.hpp>

#include <memory>

#include "engine/environment/obstaclescene.h"
#include "engine/growth/allocation.h"
#include "engine/growth/markerset.h"
#include "engine/growth/shadowgrid.h"
#include "engine/skeleton/skeleton.h"
#include "engine/util/progress.h"
#include "engine/util/random.h"
#include "engine/util/rawvector.h"

namespace sylva::growth {

/// How a bud perceives its environment (Palubicki et al. 2009, §4).
enum class SoEnvironment {
    SpaceColonization, ///< marker points, perception cone, occupancy zone
    ShadowPropagation, ///< voxel grid of shadow pyramids
};

/// How the light gathered by a tree becomes vigour of its buds (§5).
enum class SoAllocation {
    BorchertHonda, ///< basipetal light, acropetal vigour with apical control λ
    Priority,      ///< buds ranked by light, weights from w_max down to w_min
};

/// Every parameter of the self-organizing tree model. Lengths in metres unless said otherwise,
/// angles in degrees. validate() throws InvalidInput naming the parameter and its range.
struct SelfOrganizingParams {
    int cycles = 14; ///< growth cycles (years), [1, 200]
    SoEnvironment environment = SoEnvironment::ShadowPropagation;
    SoAllocation allocation = SoAllocation::BorchertHonda;

    // Resource allocation.
    double alpha = 2.0;  ///< α: v_base = α·Q_base, (0, 100]
    double lambda = 0.5; ///< λ: apical control, [0, 1]; > 0.5 favours the main axis
    double wMin = 0.06;  ///< priority model: smallest weight, [0, w_max]
    double wMax = 1.0;   ///< priority model: largest weight, (0, 10]
    double kappa = 0.5;  ///< priority model: fraction of buds over which w falls, (0, 1]

    // Space colonization environment.
    double perceptionAngle = 90.0; ///< θ: apex angle of the perception cone, [1, 360]
    double perceptionRadius = 4.0; ///< r, in internode lengths, [0.5, 100]
    double occupancyRadius = 2.0;  ///< ρ, in internode lengths, [0.1, 100]; ≤ r
    int markers = 20000;           ///< markers in the crown envelope, [0, 5,000,000]
    double crownRadius = 3.0;      ///< half-width of the ellipsoidal envelope, (0, 500]
    double crownBase = 1.0;        ///< lowest point of the envelope above the base, [0, 500]
    double crownTop = 7.0;         ///< highest point of the envelope, (crown_base, 1000]

    // Shadow propagation environment.
    double shadowA = 1.0;      ///< a: shadow a bud casts into its own voxel, (0, 100]
    double shadowB = 2.0;      ///< b: attenuation base, Δs = a·b^(−q), (1, 100]
    int shadowDepth = 5;       ///< q_max: voxels a pyramid reaches down, [0, 32]
    double fullExposure = 1.0; ///< C: light of an unshaded bud, Q = max(C − s + a, 0), (0, 100]
    double voxelSize = 1.0;    ///< voxel edge in internode lengths, [0.1, 100]

    // Shoots.
    double internodeLength = 0.1;   ///< metres per unit of vigour/metamer, [0.001, 10]
    double branchAngle = 45.0;      ///< lateral bud angle from its axis, [0, 180]
    double divergenceAngle = 137.5; ///< phyllotaxis roll between metamers, [0, 360]
    double optimalWeight = 0.2;     ///< ξ: weight of the optimal growth direction, [0, 10]
    double tropismWeight =
        0.05; ///< η: tropism weight (+Y) of the trunk axis, [-10, 10]; < 0 droops
    double lateralTropismWeight = 0.05; ///< η of lateral branches (order ≥ 1), [-10, 10]
    double directionNoise = 0.02;       ///< weight of a random unit vector per metamer, [0, 1]
    int maxShootLength = 20;            ///< most metamers one bud makes per cycle, [1, 1000]

    // Shedding.
    double sheddingThreshold = 0.1; ///< shed lateral branches with Q/internodes below, [0, 100]

    // Thickness (pipe model) and leaves.
    double tipRadius = 0.004;    ///< radius of a shoot tip, (0, 1]
    double pipeExponent = 2.5;   ///< r^e = Σ r_child^e, [1, 4]
    double taper = 0.1;          ///< skel::RadiusShaping::taper, 1/m, [0, 1]
    double junctionSlope = 0.08; ///< skel::RadiusShaping::junctionSlope, [0, 10]
    double leafSize = 0.08;      ///< leaf card length, 0 = no leaves, [0, 10]
    int leafAge = 2;             ///< metamers younger than this many cycles carry a leaf, [0, 200]

    /// Runaway guard: more internodes than this in one tree throws LimitExceeded.
    std::int64_t maxInternodes = 1'000'000; ///< [1, 50,000,000]

    void validate() const;
};

/// One tree of a stand: its base position (metres, world), parameters and seed. A tree with
/// fewer cycles than the stand's longest starts later (is planted younger).
struct StandTree {
    glm::vec3 position{0.0f};
    SelfOrganizingParams params;
    std::uint64_t seed = 0;
};

/// A grown tree with the per-node attributes the editor colours by. All arrays are indexed like
/// skeleton nodes; node 0 is the base.
struct SelfOrganizingResult {
    skel::Skeleton skeleton;        ///< relative to the tree's base (StandTree::position)
    std::vector<float> light;       ///< light gathered by the node's subtree (units of C)
    std::vector<float> vigour;      ///< vigour flowing through the node (metamer units)
    std::vector<std::uint16_t> age; ///< cycles since the node's metamer grew
    std::size_t internodes = 0;
    std::size_t shed = 0; ///< metamers this tree shed over the whole run
    /// Metamers in branches whose light per internode is below the shedding threshold now:
    /// the next cycle would shed them (their skeleton nodes carry skel::kStarved).
    std::size_t starved = 0;
    int cycles = 0;
};

/// Grows one tree alone. \throw InvalidInput for bad parameters, LimitExceeded past
/// max_internodes, Cancelled when \p progress asks.
skel::Skeleton growSelfOrganizing(const SelfOrganizingParams& params, std::uint64_t seed,
                                  Progress& progress = noProgress());
SelfOrganizingResult growSelfOrganizingDetailed(const SelfOrganizingParams& params,
                                                std::uint64_t seed,
                                                Progress& progress = noProgress());

/// Grows several trees in one shared environment (one shadow grid or one marker set) so they
/// compete for light and space. \p obstacleTriangles (3 points per triangle, world metres) cast
/// shadow / remove markers and block growth. All trees must use the same environment; the
/// shadow grid's voxel edge, and the obstacles' shadow kernel, come from the first tree.
/// Skeletons are relative to each tree's position, in the input order.
std::vector<skel::Skeleton> growStand(const std::vector<StandTree>& trees,
                                      const std::vector<glm::vec3>& obstacleTriangles,
                                      Progress& progress = noProgress());
std::vector<SelfOrganizingResult> growStandDetailed(const std::vector<StandTree>& trees,
                                                    const std::vector<glm::vec3>& obstacleTriangles,
                                                    Progress& progress = noProgress());

/// Switches for the benchmark and the tests: the naive variants recompute from scratch what
/// the default path updates incrementally.
struct SimulationOptions {
    bool naiveShadow = false;     ///< rebuild the whole shadow grid every cycle
    bool naiveAllocation = false; ///< Borchert–Honda by per-bud path products
};

/// Wall-clock milliseconds of the stages of the last step() (for the benchmark's profile).
struct CycleTimings {
    double light = 0;       ///< bud light from the environment
    double shedding = 0;    ///< gather, shed, compaction
    double allocation = 0;  ///< Borchert–Honda or priority, and which buds grow how far
    double shoots = 0;      ///< optimal directions and new metamers (the three below)
    double directions = 0;  ///<   of which: buds' optimal growth directions
    double making = 0;      ///<   of which: the shoots' metamers (parallel, into scratch)
    double commit = 0;      ///<   of which: appending them to the arrays
    double environment = 0; ///< shadow update (shed and new pyramids) / marker removal
    double total = 0;
};

/// The metamers of all trees, parents before children (see MetamerTopology).
/// (RawVector: the new shoots' slots are written right after the resize, so it does not zero
/// them first.)
struct MetamerArrays {
    RawVector<glm::vec3> end;   ///< node at the end of the internode (world metres)
    RawVector<glm::quat> frame; ///< turtle frame of the internode
    RawVector<std::int32_t> parent, mainChild, lateralChild;
    RawVector<std::uint16_t> tree, order, born;
    /// bit 0: terminal bud dead, bit 1: axillary bud dead; bits 2 and 3 (kBarrenTerminal,
    /// kBarrenAxillary): the bud, alive, perceives no marker and never will (space colonization).
    RawVector<std::uint8_t> deadBuds;

    std::size_t size() const { return end.size(); }
    MetamerTopology topology() const { return {parent, mainChild, lateralChild, tree}; }
};

/// The growth loop, cycle by cycle (growStand runs it to the end). Exposed for tests and the
/// benchmark, which step it and look inside.
class SelfOrganizingSimulation {
public:
    SelfOrganizingSimulation(std::vector<StandTree> trees, std::vector<glm::vec3> obstacles,
                             SimulationOptions options = {});

    /// Switches between incremental and naive updates (the benchmark grows a tree the fast way,
    /// then times one cycle each way). Takes effect from the next step().
    void setOptions(SimulationOptions options) { mOptions = options; }

    int cycle() const { return mCycle; }
    int totalCycles() const { return mTotalCycles; }
    bool done() const { return mCycle >= mTotalCycles; }
    /// One growth cycle of every planted tree: light, shedding, allocation, shoots,
    /// environment update.
    void step();

    const MetamerArrays& metamers() const { return mM; }
    const CycleTimings& lastTimings() const { return mTimings; }
    std::size_t shedCount() const { return mShed; }
    const ShadowGrid* shadowGrid() const { return mShadow ? &*mShadow : nullptr; }
    const MarkerSet* markerSet() const { return mMarkers ? &*mMarkers : nullptr; }
    /// The shadow grid rebuilt from every current source (oracle for the incremental one).
    ShadowGrid recomputeShadow() const;

    /// Light of every bud for the current structure (0 where the slot holds a child or a dead
    /// bud): the first stage of a cycle.
    void evaluateLight(std::vector<double>& terminal, std::vector<double>& axillary);

    /// Per-tree results for the current state (light and vigour evaluated afresh).
    std::vector<SelfOrganizingResult> results();

private:
    void plant(std::size_t treeIndex);
    void addSource(std::size_t metamer, int sign);
    void rebuildShadow();
    /// Least shadowed direction among the 26 neighbours of the bud's voxel inside its cone.
    glm::vec3 optimalShadowDirection(const glm::ivec3& voxel, const glm::vec3& dir,
                                     float cosHalf) const;
    /// A bud that grows this cycle and the slots its shoot fills.
    struct Growing {
        std::int32_t metamer;
        std::int32_t planned;  ///< metamers the vigour allows
        std::int32_t made = 0; ///< metamers made (fewer where the shoot hit ground or obstacle)
        std::size_t slot = 0;  ///< first scratch slot of the shoot
        std::size_t first = 0; ///< index of its first metamer once committed
        double vigour;
        glm::vec3 optimal{0.0f};
        bool lateral;
        bool seedling = false; ///< leader of a tree that perceives nothing yet
    };
    /// Removes the branches marked in mMarks (gatherLightAndMarkShed) in place, stable, with
    /// everything they carry; keeps the bud light, gathered light and the space colonization
    /// directions aligned; queues their pyramids' removal in mSources for the cycle's one
    /// shadow update at its end.
    void shed();
    void resizeMetamers(std::size_t n);
    std::int32_t appendMetamer(std::int32_t parent, bool lateral, const glm::vec3& end,
                               const glm::quat& frame, std::uint16_t tree, std::uint16_t order);
    /// Space colonization: does a new internode cross an obstacle triangle? (Brute force over
    /// the triangles inside a bounding-box test; the shadow grid uses blocked voxels instead.)
    bool hitsObstacle(const glm::vec3& from, const glm::vec3& to) const;
    /// Computes one shoot into the scratch slots (thread-safe: reads only the current state;
    /// its random numbers come from a stream of its own bud); returns the metamers made.
    std::int32_t makeShoot(const Growing& g, glm::vec3* ends, glm::quat* frames) const;
    /// Appends the shoots made this cycle, in bud order.
    void commitShoots();
    void allocate(std::span<const double> gathered, std::span<const double> terminal,
                  std::span<const double> axillary, Vigour& out) const;

    std::vector<StandTree> mTrees;
    std::vector<glm::vec3> mObstacles;
    glm::vec3 mObstacleLo{0.0f}, mObstacleHi{0.0f};
    /// BVH over mObstacles for the shoot-vs-obstacle test (shared by copies: immutable).
    std::shared_ptr<const env::ObstacleScene> mObstacleScene;
    SimulationOptions mOptions;
    SoEnvironment mEnv;
    std::vector<AllocationParams> mAlloc;
    std::vector<double> mShedThreshold;
    std::vector<ShadowKernel> mKernels;
    ShadowKernel mObstacleKernel;
    std::vector<glm::ivec3> mObstacleVoxels;
    std::optional<ShadowGrid> mShadow;
    std::optional<MarkerSet> mMarkers;
    std::vector<Rng> mRng;
    std::vector<std::int64_t> mCount;                          ///< internodes per tree
    std::vector<std::size_t> mShedTree;                        ///< metamers shed per tree
    std::vector<glm::vec3> mOptimalTerminal, mOptimalAxillary; ///< space colonization V
    std::vector<glm::quat> mLateralTurn, mRoll; ///< per tree: bud angle and phyllotaxis rotations
    std::vector<float> mCosHalfCone;            ///< per tree: cos(θ/2)
    MetamerArrays mM;
    CycleTimings mTimings;
    // Per-cycle buffers, kept to avoid reallocating them every cycle.
    std::vector<double> mTerminalLight, mAxillaryLight;
    RawVector<double> mGathered;
    RawVector<std::int32_t> mInternodes, mRemap;
    std::vector<ShedSums> mShedSums;
    RawVector<std::uint8_t> mMarks;   ///< gatherLightAndMarkShed: shed roots, lateral children
    std::vector<std::int64_t> mCells; ///< shadow grid cell of each metamer's buds (light pass)
    /// The alive markers by the buds' perception radius (space colonization): built at the
    /// first light pass, then only thinned (PointGrid::keepOnly) as markers are consumed.
    std::optional<PointGrid> mAliveGrid;
    std::vector<glm::ivec3> mBudVoxels; ///< voxel of each growing bud (optimal directions)
    Vigour mVigour;
    std::vector<Growing> mGrowing;
    RawVector<glm::vec3> mShootEnd;
    RawVector<glm::quat> mShootFrame;
    std::vector<ShadowSource> mSources;
    int mCycle = 0;
    int mTotalCycles = 0;
    std::size_t mShed = 0;
};

} // namespace sylva::growth
