#include "engine/growth/selforganizing.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <string>
#include <tuple>

#include <glm/gtx/quaternion.hpp>
#include <omp.h>

#include "engine/growth/optimaldirection.h"
#include "engine/growth/pipemodel.h"
#include "engine/skeleton/radii.h"
#include "engine/util/error.h"
#include "engine/util/parallelfor.h"
#include "engine/util/randomvector.h"
#include "engine/util/safenormalize.h"
#include "engine/util/seedsalts.h"

namespace sylva::growth {

namespace {

constexpr float kPi = 3.14159265358979f;
/// Metamers::deadBuds bits of a live bud that perceives no marker and never will.
constexpr std::uint8_t kBarrenTerminal = 4u, kBarrenAxillary = 8u;
/// Items from which a loop runs on several threads: cheap ones (a voxel look-up, a copy: ns
/// each) and costly ones (a shoot, a bud's markers: about a microsecond each). Below, a
/// parallel region saves less than it costs, and under libgomp's default waiting (Python, the
/// editor) leaves the other threads spinning for milliseconds after it: a 5,000-internode
/// broadleaf took twice its CPU time on two threads. A 100k-internode tree stays parallel.
constexpr std::int64_t kParallelCheap = 16384, kParallelCostly = 2048;
float radians(double degrees) {
    return static_cast<float>(degrees) * kPi / 180.0f;
}
std::size_t sz(std::int32_t i) {
    return static_cast<std::size_t>(i);
}

const glm::vec3 kUp(0.0f, 1.0f, 0.0f);

/// Direction of the axillary bud of a metamer with frame \p q: its heading pitched by the
/// branching angle about the frame's up axis (towards its left).
glm::quat lateralFrame(const glm::quat& q, float branchAngle) {
    return q * glm::angleAxis(branchAngle, glm::vec3(0, 0, 1));
}

/// Minimal rotation turning the unit heading \p h of \p q into the unit \p dir, then the
/// phyllotaxis roll. The rotation is the unnormalized half-way quaternion (1 + h·d, h × d):
/// one normalization of the product instead of one per factor.
glm::quat steer(const glm::quat& q, const glm::vec3& h, const glm::vec3& dir,
                const glm::quat& roll) {
    const float c = glm::dot(h, dir);
    glm::quat r;
    if (c < -0.9999f) {
        r = glm::angleAxis(kPi, skel::leftOf(q));
    } else {
        const glm::vec3 a = glm::cross(h, dir);
        r = glm::quat(1.0f + c, a.x, a.y, a.z);
    }
    return glm::normalize(r * q * roll);
}

} // namespace

void SelfOrganizingParams::validate() const {
    requireRange("cycles", cycles, 1, 200);
    requireRange("alpha", alpha, 1e-6, 100);
    requireRange("lambda", lambda, 0, 1);
    requireRange("w_max", wMax, 1e-6, 10);
    requireRange("w_min", wMin, 0, wMax);
    requireRange("kappa", kappa, 1e-6, 1);
    requireRange("perception_angle", perceptionAngle, 1, 360);
    requireRange("perception_radius", perceptionRadius, 0.5, 100);
    requireRange("occupancy_radius", occupancyRadius, 0.1, std::min(100.0, perceptionRadius));
    requireRange("markers", markers, 0, 5'000'000);
    requireRange("crown_radius", crownRadius, 1e-3, 500);
    requireRange("crown_base", crownBase, 0, 500);
    requireRange("crown_top", crownTop, crownBase + 1e-3, 1000);
    requireRange("shadow_a", shadowA, 1e-6, 100);
    requireRange("shadow_b", shadowB, 1.000001, 100);
    requireRange("shadow_depth", shadowDepth, 0, 32);
    requireRange("full_exposure", fullExposure, 1e-6, 100);
    requireRange("voxel_size", voxelSize, 0.1, 100);
    requireRange("internode_length", internodeLength, 0.001, 10);
    requireRange("branch_angle", branchAngle, 0, 180);
    requireRange("divergence_angle", divergenceAngle, 0, 360);
    requireRange("optimal_weight", optimalWeight, 0, 10);
    requireRange("tropism_weight", tropismWeight, -10, 10);
    requireRange("lateral_tropism_weight", lateralTropismWeight, -10, 10);
    requireRange("direction_noise", directionNoise, 0, 1);
    requireRange("max_shoot_length", maxShootLength, 1, 1000);
    requireRange("shedding_threshold", sheddingThreshold, 0, 100);
    requireRange("tip_radius", tipRadius, 1e-6, 1);
    requireRange("pipe_exponent", pipeExponent, 1, 4);
    requireRange("taper", taper, 0, 1);
    requireRange("junction_slope", junctionSlope, 0, 10);
    requireRange("leaf_size", leafSize, 0, 10);
    requireRange("leaf_age", leafAge, 0, 200);
    requireRange("max_internodes", static_cast<double>(maxInternodes), 1, 50'000'000);
}

// ---------------------------------------------------------------------------------------------

SelfOrganizingSimulation::SelfOrganizingSimulation(std::vector<StandTree> trees,
                                                   std::vector<glm::vec3> obstacles,
                                                   SimulationOptions options)
    : mTrees(std::move(trees)), mObstacles(std::move(obstacles)), mOptions(options) {
    if (mTrees.empty()) throw InvalidInput("a stand needs at least one tree");
    if (mTrees.size() > 65535)
        throw LimitExceeded("a stand of self-organizing trees holds at most 65,535 trees, got " +
                            std::to_string(mTrees.size()) +
                            "; lower the domains' counts or split the scene into several projects");
    if (mObstacles.size() % 3 != 0)
        throw InvalidInput("obstacle triangles need 3 points each, got " +
                           std::to_string(mObstacles.size()) + " points");
    for (const glm::vec3& p : mObstacles)
        if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z))
            throw InvalidInput("obstacle triangles contain a non-finite coordinate");
    mEnv = mTrees[0].params.environment;
    if (!mObstacles.empty()) {
        // Shoots are tested against the obstacles with Embree: a brute-force loop over every
        // triangle made a stand beside a 10k-triangle boulder 60x slower.
        std::vector<glm::uvec3> triangles(mObstacles.size() / 3);
        for (std::size_t t = 0; t < triangles.size(); ++t)
            triangles[t] = glm::uvec3(3 * t, 3 * t + 1, 3 * t + 2);
        std::vector<env::ObstacleMesh> meshes;
        meshes.push_back(env::makeObstacleMesh("obstacles", mObstacles, triangles));
        mObstacleScene = std::make_shared<const env::ObstacleScene>(std::move(meshes));
        mObstacleLo = mObstacleHi = mObstacles[0];
        for (const glm::vec3& p : mObstacles) {
            mObstacleLo = glm::min(mObstacleLo, p);
            mObstacleHi = glm::max(mObstacleHi, p);
        }
    }
    for (std::size_t t = 0; t < mTrees.size(); ++t) {
        const StandTree& tree = mTrees[t];
        tree.params.validate();
        const glm::vec3& p = tree.position;
        if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z))
            throw InvalidInput("tree " + std::to_string(t) + " has a non-finite position");
        if (tree.params.environment != mEnv)
            throw InvalidInput("all trees of a stand must use the same environment (tree " +
                               std::to_string(t) + " differs from tree 0)");
        const SelfOrganizingParams& sp = tree.params;
        mAlloc.push_back({sp.alpha, sp.lambda, sp.wMin, sp.wMax, sp.kappa});
        mShedThreshold.push_back(sp.sheddingThreshold);
        mTotalCycles = std::max(mTotalCycles, sp.cycles);
        mRng.emplace_back(mixSeed(tree.seed, salt::kSelfOrganizingTree));
        mLateralTurn.push_back(glm::angleAxis(radians(sp.branchAngle), glm::vec3(0, 0, 1)));
        mRoll.push_back(glm::angleAxis(radians(sp.divergenceAngle), glm::vec3(0, 1, 0)));
        mCosHalfCone.push_back(
            static_cast<float>(std::cos(0.5 * sp.perceptionAngle * kPi / 180.0)));
    }
    mCount.assign(mTrees.size(), 0);
    mShedTree.assign(mTrees.size(), 0);
    const SelfOrganizingParams& p0 = mTrees[0].params;

    if (mEnv == SoEnvironment::ShadowPropagation) {
        int margin = 0;
        float floorY = std::numeric_limits<float>::max();
        for (const StandTree& t : mTrees) {
            mKernels.push_back(
                ShadowKernel::make(t.params.shadowA, t.params.shadowB, t.params.shadowDepth));
            margin = std::max(margin, t.params.shadowDepth);
            floorY = std::min(floorY, t.position.y);
        }
        const float h = static_cast<float>(p0.voxelSize * p0.internodeLength);
        mShadow.emplace(h, floorY - h, margin);
        mObstacleKernel = mKernels[0];
        // Voxelize obstacles by sampling each triangle at half the voxel size.
        for (std::size_t i = 0; i + 2 < mObstacles.size(); i += 3) {
            const glm::vec3 a = mObstacles[i], b = mObstacles[i + 1], c = mObstacles[i + 2];
            const float len = std::max(glm::length(b - a), glm::length(c - a));
            const int steps = std::min(4096, static_cast<int>(std::ceil(len / (0.5f * h))) + 1);
            for (int u = 0; u <= steps; ++u)
                for (int v = 0; u + v <= steps; ++v) {
                    const float fu = static_cast<float>(u) / static_cast<float>(steps);
                    const float fv = static_cast<float>(v) / static_cast<float>(steps);
                    mObstacleVoxels.push_back(mShadow->voxelOf(a + (b - a) * fu + (c - a) * fv));
                }
        }
        std::sort(mObstacleVoxels.begin(), mObstacleVoxels.end(),
                  [](const glm::ivec3& l, const glm::ivec3& r) {
                      return std::tie(l.y, l.x, l.z) < std::tie(r.y, r.x, r.z);
                  });
        mObstacleVoxels.erase(std::unique(mObstacleVoxels.begin(), mObstacleVoxels.end()),
                              mObstacleVoxels.end());
        for (const glm::ivec3& v : mObstacleVoxels) {
            mShadow->setBlocked(v);
            mShadow->addPyramid(v, mObstacleKernel, 1);
        }
    } else {
        std::vector<glm::vec3> markers;
        float cell = std::numeric_limits<float>::max();
        for (std::size_t t = 0; t < mTrees.size(); ++t) {
            const SelfOrganizingParams& sp = mTrees[t].params;
            Rng rng(mixSeed(mTrees[t].seed, salt::kSelfOrganizingMarkers));
            const glm::vec3 radii(static_cast<float>(sp.crownRadius),
                                  static_cast<float>(0.5 * (sp.crownTop - sp.crownBase)),
                                  static_cast<float>(sp.crownRadius));
            const glm::vec3 centre =
                mTrees[t].position +
                glm::vec3(0, static_cast<float>(0.5 * (sp.crownTop + sp.crownBase)), 0);
            for (int k = 0; k < sp.markers;) {
                const glm::vec3 u(rng.uniformf(-1, 1), rng.uniformf(-1, 1), rng.uniformf(-1, 1));
                if (glm::dot(u, u) > 1.0f) continue;
                markers.push_back(centre + u * radii);
                ++k;
            }
            cell = std::min(cell, static_cast<float>(sp.occupancyRadius * sp.internodeLength));
        }
        // Cells twice the occupancy radius: its queries (one a new metamer) then visit about
        // 2 x 2 x 2 cells instead of 3 x 3 x 3 (~7 % of a tree's time less).
        mMarkers.emplace(std::move(markers), 2.0f * cell);
        const float rho = static_cast<float>(p0.occupancyRadius * p0.internodeLength);
        for (std::size_t i = 0; i + 2 < mObstacles.size(); i += 3)
            mMarkers->removeNearTriangle(mObstacles[i], mObstacles[i + 1], mObstacles[i + 2], rho);
    }
}

void SelfOrganizingSimulation::addSource(std::size_t metamer, int sign) {
    mShadow->addPyramid(mShadow->voxelOf(mM.end[metamer]), mKernels[mM.tree[metamer]], sign);
}

void SelfOrganizingSimulation::rebuildShadow() {
    mShadow->clearShadow();
    for (const glm::ivec3& v : mObstacleVoxels)
        mShadow->addPyramid(v, mObstacleKernel, 1);
    for (std::size_t i = 0; i < mM.size(); ++i)
        addSource(i, 1);
}

ShadowGrid SelfOrganizingSimulation::recomputeShadow() const {
    if (!mShadow) throw InvalidInput("this stand has no shadow grid");
    int margin = 0;
    float floorY = std::numeric_limits<float>::max();
    for (const StandTree& t : mTrees) {
        margin = std::max(margin, t.params.shadowDepth);
        floorY = std::min(floorY, t.position.y);
    }
    const float h = mShadow->voxelSize();
    ShadowGrid g(h, floorY - h, margin);
    for (const glm::ivec3& v : mObstacleVoxels)
        g.addPyramid(v, mObstacleKernel, 1);
    for (std::size_t i = 0; i < mM.size(); ++i)
        g.addPyramid(g.voxelOf(mM.end[i]), mKernels[mM.tree[i]], 1);
    return g;
}

std::int32_t SelfOrganizingSimulation::appendMetamer(std::int32_t parent, bool lateral,
                                                     const glm::vec3& end, const glm::quat& frame,
                                                     std::uint16_t tree, std::uint16_t order) {
    const SelfOrganizingParams& sp = mTrees[tree].params;
    if (++mCount[tree] > sp.maxInternodes)
        throw LimitExceeded("self-organizing tree " + std::to_string(tree) + " exceeded " +
                            std::to_string(sp.maxInternodes) +
                            " internodes (max_internodes) in cycle " + std::to_string(mCycle + 1) +
                            " of " + std::to_string(sp.cycles) +
                            "; lower alpha or cycles, or raise max_internodes");
    const auto index = static_cast<std::int32_t>(mM.size());
    mM.end.push_back(end);
    mM.frame.push_back(frame);
    mM.parent.push_back(parent);
    mM.mainChild.push_back(-1);
    mM.lateralChild.push_back(-1);
    mM.tree.push_back(tree);
    mM.order.push_back(order);
    mM.born.push_back(static_cast<std::uint16_t>(mCycle));
    mM.deadBuds.push_back(0);
    if (parent >= 0) (lateral ? mM.lateralChild : mM.mainChild)[sz(parent)] = index;
    return index;
}

void SelfOrganizingSimulation::plant(std::size_t t) {
    const StandTree& tree = mTrees[t];
    Rng& rng = mRng[t];
    const glm::quat frame = glm::angleAxis(rng.uniformf(0, 2 * kPi), kUp);
    const float len = static_cast<float>(tree.params.internodeLength);
    const auto i = appendMetamer(-1, false, tree.position + kUp * len, frame,
                                 static_cast<std::uint16_t>(t), 0);
    if (mShadow && !mOptions.naiveShadow) addSource(sz(i), 1);
    if (mMarkers)
        mMarkers->removeWithin(mM.end[sz(i)],
                               static_cast<float>(tree.params.occupancyRadius * len));
}

void SelfOrganizingSimulation::evaluateLight(std::vector<double>& terminal,
                                             std::vector<double>& axillary) {
    const std::size_t n = mM.size();
    auto terminalAlive = [&](std::size_t i) {
        return mM.mainChild[i] < 0 && !(mM.deadBuds[i] & 1u);
    };
    auto axillaryAlive = [&](std::size_t i) {
        return mM.lateralChild[i] < 0 && !(mM.deadBuds[i] & 2u);
    };
    if (mEnv == SoEnvironment::ShadowPropagation) {
        // Every slot is written below (in parallel), so the arrays need no zeroing first.
        terminal.resize(n);
        axillary.resize(n);
        const ShadowGrid& grid = *mShadow;
        const auto count = static_cast<std::int64_t>(n);
        // Few trees, many metamers: look the light constants up per tree, not per metamer.
        std::vector<double> full(mTrees.size()), a(mTrees.size());
        for (std::size_t t = 0; t < mTrees.size(); ++t) {
            full[t] = mTrees[t].params.fullExposure;
            a[t] = mTrees[t].params.shadowA;
        }
        // Two passes: the grid cell of every bud first (arithmetic), then the scattered reads,
        // each prefetched kAhead buds early so that their cache misses overlap.
        constexpr std::int64_t kNoBud = -2, kAhead = 24;
        mCells.resize(n);
        forEachIndex(count, count >= kParallelCheap, [&](std::int64_t k) {
            const auto i = static_cast<std::size_t>(k);
            mCells[i] = terminalAlive(i) || axillaryAlive(i) ? grid.cellOf(grid.voxelOf(mM.end[i]))
                                                             : kNoBud;
        });
        const bool anyBlocked = grid.anyBlocked();
        forEachIndex(count, count >= kParallelCheap, [&](std::int64_t k) {
            const auto i = static_cast<std::size_t>(k);
            if (k + kAhead < count) grid.prefetchCell(mCells[i + kAhead]);
            const std::int64_t cell = mCells[i];
            double q = 0.0;
            if (cell != kNoBud) {
                const std::uint16_t t = mM.tree[i];
                q = anyBlocked && grid.blocked(grid.voxelOf(mM.end[i]))
                        ? 0.0
                        : std::max(full[t] - grid.rawAt(cell) / ShadowGrid::kScale + a[t], 0.0);
            }
            terminal[i] = terminalAlive(i) ? q : 0.0;
            axillary[i] = axillaryAlive(i) ? q : 0.0;
        });
        return;
    }
    terminal.assign(n, 0.0);
    axillary.assign(n, 0.0);

    // Space colonization: each marker belongs to the closest bud that perceives it.
    struct Bud {
        glm::vec3 pos, dir;
        float r, r2, cosHalf;
        std::uint32_t key; ///< 2·metamer + (0 terminal | 1 axillary)
    };
    std::vector<Bud> buds;
    for (std::size_t i = 0; i < n; ++i) {
        const SelfOrganizingParams& sp = mTrees[mM.tree[i]].params;
        const float r = static_cast<float>(sp.perceptionRadius * sp.internodeLength);
        const float c = std::cos(0.5f * radians(sp.perceptionAngle));
        // A barren bud (kBarrenTerminal, kBarrenAxillary) perceived no marker once: markers
        // are only ever removed and a bud never moves, so it never will; it is not asked again
        // (most of a grown crown's buds, inside it).
        if (terminalAlive(i) && !(mM.deadBuds[i] & kBarrenTerminal))
            buds.push_back({mM.end[i], skel::headingOf(mM.frame[i]), r, r * r, c,
                            static_cast<std::uint32_t>(2 * i)});
        if (axillaryAlive(i) && !(mM.deadBuds[i] & kBarrenAxillary))
            buds.push_back({mM.end[i],
                            skel::headingOf(lateralFrame(mM.frame[i], radians(sp.branchAngle))), r,
                            r * r, c, static_cast<std::uint32_t>(2 * i + 1)});
    }
    mOptimalTerminal.assign(n, glm::vec3(0.0f));
    mOptimalAxillary.assign(n, glm::vec3(0.0f));
    if (buds.empty()) return;
    // Each bud asks the marker grid for the markers it perceives, and every marker keeps the
    // closest (ties: the lower bud index): the lexicographic minimum of (distance², bud), the
    // same owner whatever the order the pairs come in. Buds are 5-20 times fewer than the alive
    // markers, so this asks far fewer queries than a query per marker over a grid of the buds
    // did (that was ~75 % of a self-organizing broadleaf's time). On several threads each
    // takes a share of the buds into its own minimum, merged after: the same owners.
    const std::vector<std::uint32_t> alive = mMarkers->aliveIndices();
    const std::vector<glm::vec3>& mp = mMarkers->positions();
    if (alive.empty()) return;
    // Built once over the alive markers, then thinned each cycle: markers are only ever
    // removed (rebuilding it every cycle was a quarter of the tree's time).
    mMarkers->compact();
    const MarkerSet& markers = *mMarkers;
    if (!mAliveGrid) {
        float rMax = 0.0f;
        for (const StandTree& t : mTrees)
            rMax = std::max(
                rMax, static_cast<float>(t.params.perceptionRadius * t.params.internodeLength));
        mAliveGrid.emplace(mp, rMax); // the dead (near obstacles) are dropped just below
    }
    mAliveGrid->keepOnly([&](std::uint32_t m) { return markers.alive(m); });
    const PointGrid& grid = *mAliveGrid;
    const auto budCount = static_cast<std::int64_t>(buds.size());
    const int threads = budCount >= 2 * kParallelCostly ? std::max(1, omp_get_max_threads()) : 1;
    struct Best {
        std::vector<float> d2;
        std::vector<std::int32_t> bud;
    };
    std::vector<Best> best(static_cast<std::size_t>(threads));
    auto perceive = [&](std::int64_t k, Best& mine) {
        const Bud& bud = buds[static_cast<std::size_t>(k)];
        const auto b = static_cast<std::int32_t>(k);
        bool perceives = false;
        // The bud perceives a spherical sector (radius r, half-angle θ): the sphere through
        // its apex and rim, centre r / (2 cos θ) along the axis, holds it and is smaller than
        // the ball for θ < 60° (0.71 r at the usual 45°: a third of the ball's markers to
        // test). Made 1 % larger against rounding; each marker is then tested as before, its
        // distance to the bud included, so the same markers pass.
        glm::vec3 centre = bud.pos;
        float reach = bud.r;
        if (bud.cosHalf > 0.5f) {
            const float half = bud.r / (2.0f * bud.cosHalf);
            centre = bud.pos + bud.dir * half;
            reach = 1.01f * half;
        }
        grid.forEachInRadius(centre, reach, [&](std::uint32_t m, float) {
            const float d2 = distance2(mp[m], bud.pos);
            if (!(d2 < bud.r2)) return;
            float& bestD2 = mine.d2[m];
            if (perceives && d2 > bestD2) return;
            const glm::vec3 d = mp[m] - bud.pos;
            if (glm::dot(d, bud.dir) < bud.cosHalf * std::sqrt(d2)) return;
            perceives = true;
            if (d2 > bestD2) return;
            if (d2 < bestD2 || b < mine.bud[m]) {
                bestD2 = d2;
                mine.bud[m] = b;
            }
        });
        if (!perceives)
            mM.deadBuds[bud.key >> 1] |= (bud.key & 1u) ? kBarrenAxillary : kBarrenTerminal;
    };
    auto start = [&](Best& mine) {
        mine.d2.assign(mp.size(), std::numeric_limits<float>::max());
        mine.bud.assign(mp.size(), -1);
    };
    // The region only where it has threads: a team of one still ends at a barrier (a futex).
    if (threads > 1) {
#pragma omp parallel num_threads(threads)
        {
            Best& mine = best[static_cast<std::size_t>(omp_get_thread_num())];
            start(mine);
#pragma omp for schedule(static)
            for (std::int64_t k = 0; k < budCount; ++k)
                perceive(k, mine);
        }
    } else {
        start(best[0]);
        for (std::int64_t k = 0; k < budCount; ++k)
            perceive(k, best[0]);
    }
    std::vector<std::int32_t> owner(alive.size());
    for (std::size_t k = 0; k < alive.size(); ++k) {
        const std::uint32_t m = alive[k];
        std::int32_t b = best[0].bud[m];
        float d2 = best[0].d2[m];
        for (std::size_t t = 1; t < best.size(); ++t) {
            const std::int32_t tb = best[t].bud[m];
            if (tb < 0) continue;
            if (b < 0 || best[t].d2[m] < d2 || (best[t].d2[m] == d2 && tb < b)) {
                d2 = best[t].d2[m];
                b = tb;
            }
        }
        owner[k] = b;
    }
    std::vector<glm::vec3> sum(buds.size(), glm::vec3(0.0f));
    std::vector<std::uint8_t> seen(buds.size(), 0);
    for (std::size_t k = 0; k < alive.size(); ++k) {
        if (owner[k] < 0) continue;
        const Bud& bud = buds[sz(owner[k])];
        sum[sz(owner[k])] += safeNormalize(mp[alive[k]] - bud.pos, bud.dir);
        seen[sz(owner[k])] = 1;
    }
    for (std::size_t b = 0; b < buds.size(); ++b) {
        if (!seen[b]) continue;
        const std::size_t i = buds[b].key >> 1;
        const glm::vec3 v = safeNormalize(sum[b], buds[b].dir);
        if (buds[b].key & 1u) {
            axillary[i] = 1.0;
            mOptimalAxillary[i] = v;
        } else {
            terminal[i] = 1.0;
            mOptimalTerminal[i] = v;
        }
    }
}

glm::vec3 SelfOrganizingSimulation::optimalShadowDirection(const glm::ivec3& voxel,
                                                           const glm::vec3& dir,
                                                           float cosHalf) const {
    std::int32_t s[27];
    mShadow->neighbourhood(voxel, s);
    return leastShadowedDirection(s, dir, cosHalf);
}

void SelfOrganizingSimulation::shed() {
    const std::size_t n = mM.size();
    const bool incremental = mShadow && !mOptions.naiveShadow;
    const bool sc = mEnv == SoEnvironment::SpaceColonization;
    mRemap.resize(n);
    // First pass, forward: a metamer is shed when it is a marked root or its parent is shed;
    // each survivor gets its new slot. The root of a shed branch leaves a scar: its parent's bud
    // is gone for good (written at the parent's old slot, which the moves below carry along).
    std::int32_t next = 0;
    for (std::size_t i = 0; i < n; ++i) {
        const std::int32_t p = mM.parent[i];
        const std::uint8_t mark = mMarks[i];
        if (!(mark & 1u) && (p < 0 || mRemap[sz(p)] >= 0)) {
            mRemap[i] = next++;
            continue;
        }
        mRemap[i] = -1;
        const std::uint16_t t = mM.tree[i];
        if (incremental) mSources.push_back({mShadow->voxelOf(mM.end[i]), -1, t});
        --mCount[t];
        ++mShedTree[t];
        ++mShed;
        if (p >= 0 && mRemap[sz(p)] >= 0) {
            const std::size_t k = sz(p);
            if (mark & 2u) {
                mM.deadBuds[k] |= 2u;
                mAxillaryLight[k] = 0.0;
            } else {
                mM.deadBuds[k] |= 1u;
                mTerminalLight[k] = 0.0;
            }
        }
    }
    const auto kept = static_cast<std::size_t>(next);
    // Then the survivors move down in place (stable: slot k never passes slot i), the arrays in
    // two groups that two threads move at once (each group in one pass, so no array is read
    // and written by both). Child links are set from the child's side (its mark says whether
    // it is its parent's lateral child), after the parent's own slot has been reset.
    auto moveA = [&] {
        for (std::size_t i = 0; i < n; ++i) {
            const std::int32_t r = mRemap[i];
            if (r < 0) continue;
            const std::size_t k = sz(r);
            mM.end[k] = mM.end[i];
            mM.frame[k] = mM.frame[i];
            mM.tree[k] = mM.tree[i];
            mM.order[k] = mM.order[i];
            mM.born[k] = mM.born[i];
            if (sc) {
                mOptimalTerminal[k] = mOptimalTerminal[i];
                mOptimalAxillary[k] = mOptimalAxillary[i];
            }
        }
    };
    auto moveB = [&] {
        for (std::size_t i = 0; i < n; ++i) {
            const std::int32_t r = mRemap[i];
            if (r < 0) continue;
            const std::size_t k = sz(r);
            const std::int32_t p = mM.parent[i];
            const std::int32_t newParent = p < 0 ? -1 : mRemap[sz(p)];
            mM.parent[k] = newParent;
            mM.mainChild[k] = -1;
            mM.lateralChild[k] = -1;
            mM.deadBuds[k] = mM.deadBuds[i];
            mTerminalLight[k] = mTerminalLight[i];
            mAxillaryLight[k] = mAxillaryLight[i];
            mGathered[k] = mGathered[i];
            mInternodes[k] = mInternodes[i];
            if (newParent >= 0)
                ((mMarks[i] & 2u) ? mM.lateralChild : mM.mainChild)[sz(newParent)] = r;
        }
    };
    if (n >= kParallelCheap) {
#pragma omp parallel sections
        {
#pragma omp section
            moveA();
#pragma omp section
            moveB();
        }
    } else {
        // Not `parallel sections if (...)`: a failed if still starts a team of one (a futex).
        moveA();
        moveB();
    }
    resizeMetamers(kept);
    mTerminalLight.resize(kept);
    mAxillaryLight.resize(kept);
    mGathered.resize(kept);
    mInternodes.resize(kept);
    if (sc) {
        mOptimalTerminal.resize(kept);
        mOptimalAxillary.resize(kept);
    }
    // The shed pyramids stay in the grid until the end of the cycle (step()): the environment
    // of this cycle's buds is the one they perceived when it began.
}

void SelfOrganizingSimulation::resizeMetamers(std::size_t n) {
    mM.end.resize(n);
    mM.frame.resize(n);
    mM.parent.resize(n);
    mM.mainChild.resize(n);
    mM.lateralChild.resize(n);
    mM.tree.resize(n);
    mM.order.resize(n);
    mM.born.resize(n);
    mM.deadBuds.resize(n);
}

void SelfOrganizingSimulation::allocate(std::span<const double> gathered,
                                        std::span<const double> terminal,
                                        std::span<const double> axillary, Vigour& out) const {
    const MetamerTopology topo = mM.topology();
    // Trees may mix models: run both where needed and pick per tree.
    bool anyBH = false, anyPriority = false;
    for (const StandTree& t : mTrees)
        (t.params.allocation == SoAllocation::BorchertHonda ? anyBH : anyPriority) = true;
    if (!anyBH) {
        allocatePriority(topo, gathered, terminal, axillary, mAlloc, out);
        return;
    }
    if (mOptions.naiveAllocation)
        out = allocateBorchertHondaNaive(topo, terminal, axillary, mAlloc);
    else
        allocateBorchertHonda(topo, gathered, terminal, axillary, mAlloc, out);
    if (!anyPriority) return;
    const Vigour pr = allocatePriority(topo, gathered, terminal, axillary, mAlloc);
    for (std::size_t i = 0; i < mM.size(); ++i)
        if (mTrees[mM.tree[i]].params.allocation == SoAllocation::Priority) {
            out.metamer[i] = pr.metamer[i];
            out.terminal[i] = pr.terminal[i];
            out.axillary[i] = pr.axillary[i];
        }
}

bool SelfOrganizingSimulation::hitsObstacle(const glm::vec3& from, const glm::vec3& to) const {
    if (mObstacles.empty()) return false;
    const glm::vec3 lo = glm::min(from, to), hi = glm::max(from, to);
    if (glm::any(glm::lessThan(hi, mObstacleLo)) || glm::any(glm::greaterThan(lo, mObstacleHi)))
        return false;
    return mObstacleScene->occluded(env::Segment{from, to});
}

std::int32_t SelfOrganizingSimulation::makeShoot(const Growing& g, glm::vec3* ends,
                                                 glm::quat* frames) const {
    const std::size_t from = sz(g.metamer);
    const std::uint16_t t = mM.tree[from];
    const SelfOrganizingParams& sp = mTrees[t].params;
    // Every bud draws from a stream of its own (tree seed, cycle, bud), so shoots can be made
    // in any order on any number of threads.
    Rng rng(mixSeed(
        mixSeed(mTrees[t].seed, salt::kSelfOrganizingCycle + static_cast<std::uint64_t>(mCycle)),
        2 * from + (g.lateral ? 1 : 0)));
    const int n = g.planned;
    const float len = static_cast<float>(sp.internodeLength * std::min(g.vigour / n, 2.0));
    glm::quat frame = g.lateral ? mM.frame[from] * mLateralTurn[t] : mM.frame[from];
    glm::vec3 pos = mM.end[from];
    const int order = mM.order[from] + (g.lateral ? 1 : 0);
    const float xi = static_cast<float>(sp.optimalWeight);
    const float eta = static_cast<float>(order == 0 ? sp.tropismWeight : sp.lateralTropismWeight);
    const float noise = static_cast<float>(sp.directionNoise);
    const float ground = mTrees[t].position.y;
    // The heading is carried from metamer to metamer instead of read back from each frame:
    // steering turns the heading into d exactly and the phyllotaxis roll is about the heading,
    // so the next heading is d. That keeps the frame maths off the loop's dependency chain.
    const glm::vec3 pull = xi * g.optimal + eta * kUp;
    const glm::quat roll = mRoll[t];
    const bool blockedVoxels = mShadow && mShadow->anyBlocked();
    const bool obstacles = !mShadow && !mObstacles.empty();
    glm::vec3 h = skel::headingOf(frame);
    for (int k = 0; k < n; ++k) {
        glm::vec3 d = h + pull;
        if (noise > 0.0f) d += noise * randomUnitVector(rng);
        d = safeNormalize(d, h);
        const glm::vec3 end = pos + d * len;
        // A shoot that runs into the ground or an obstacle stops there.
        if (end.y < ground || (blockedVoxels && mShadow->blocked(mShadow->voxelOf(end))) ||
            (obstacles && hitsObstacle(pos, end)))
            return k;
        frame = steer(frame, h, d, roll);
        ends[k] = end;
        frames[k] = frame;
        pos = end;
        h = d;
    }
    return n;
}

void SelfOrganizingSimulation::commitShoots() {
    // Per-tree limit first, so that a throw leaves the arrays untouched.
    std::vector<std::int64_t> added(mTrees.size(), 0);
    std::size_t total = 0;
    for (const Growing& g : mGrowing) {
        added[mM.tree[sz(g.metamer)]] += g.made;
        total += static_cast<std::size_t>(g.made);
    }
    for (std::size_t t = 0; t < mTrees.size(); ++t) {
        const SelfOrganizingParams& sp = mTrees[t].params;
        if (mCount[t] + added[t] > sp.maxInternodes)
            throw LimitExceeded("self-organizing tree " + std::to_string(t) + " exceeded " +
                                std::to_string(sp.maxInternodes) +
                                " internodes (max_internodes) in cycle " +
                                std::to_string(mCycle + 1) + " of " + std::to_string(sp.cycles) +
                                "; lower alpha or cycles, or raise max_internodes");
        mCount[t] += added[t];
    }
    const std::size_t n0 = mM.size();
    resizeMetamers(n0 + total);
    // The new metamers, shoot after shoot in bud order: the bud's metamer links to the first,
    // each links to the next along the axis.
    std::size_t first = n0;
    for (Growing& g : mGrowing) {
        const std::size_t from = sz(g.metamer);
        if (g.made == 0) {
            mM.deadBuds[from] |= g.lateral ? 2u : 1u;
            continue;
        }
        (g.lateral ? mM.lateralChild : mM.mainChild)[from] = static_cast<std::int32_t>(first);
        g.first = first;
        first += static_cast<std::size_t>(g.made);
    }
    const auto count = static_cast<std::int64_t>(mGrowing.size());
    const auto cycle = static_cast<std::uint16_t>(mCycle);
    forEachIndex(count, total >= kParallelCheap, [&](std::int64_t k) {
        const Growing& g = mGrowing[static_cast<std::size_t>(k)];
        if (g.made == 0) return;
        const std::size_t from = sz(g.metamer);
        const std::size_t scratch = g.slot;
        const std::uint16_t tree = mM.tree[from];
        const auto order = static_cast<std::uint16_t>(mM.order[from] + (g.lateral ? 1 : 0));
        for (std::int32_t j = 0; j < g.made; ++j) {
            const std::size_t i = g.first + sz(j);
            mM.end[i] = mShootEnd[scratch + sz(j)];
            mM.frame[i] = mShootFrame[scratch + sz(j)];
            mM.parent[i] = j == 0 ? g.metamer : static_cast<std::int32_t>(i - 1);
            mM.mainChild[i] = j + 1 < g.made ? static_cast<std::int32_t>(i + 1) : -1;
            mM.lateralChild[i] = -1;
            mM.tree[i] = tree;
            mM.order[i] = order;
            mM.born[i] = cycle;
            // A shoot cut short loses its terminal bud.
            mM.deadBuds[i] = j + 1 == g.made && g.made < g.planned ? 1u : 0u;
        }
    });
}

void SelfOrganizingSimulation::step() {
    if (done()) return;
    using Clock = std::chrono::steady_clock;
    auto ms = [](Clock::time_point a, Clock::time_point b) {
        return std::chrono::duration<double, std::milli>(b - a).count();
    };
    const Clock::time_point t0 = Clock::now();
    for (std::size_t t = 0; t < mTrees.size(); ++t)
        if (mCycle == mTotalCycles - mTrees[t].params.cycles) plant(t);
    if (mShadow && mOptions.naiveShadow) rebuildShadow();
    mSources.clear(); // shadow changes of this cycle: shed pyramids, then new ones

    evaluateLight(mTerminalLight, mAxillaryLight);
    const Clock::time_point t1 = Clock::now();
    const std::size_t n = mM.size();
    mGathered.resize(n);
    mInternodes.resize(n);
    mMarks.resize(n);
    if (gatherLightAndMarkShed(mM.topology(), mTerminalLight, mAxillaryLight, mShedThreshold,
                               mGathered, mInternodes, mMarks, mShedSums)) {
        shed();
    }
    const Clock::time_point t2 = Clock::now();

    // Buds that grow, in metamer order (terminal before axillary). Their shoots are made in
    // parallel into scratch slots (prefix sums of the planned lengths), then appended in order.
    mGrowing.clear();
    const std::size_t n0 = mM.size();
    std::size_t slots = 0;
    auto plan = [&](std::size_t i, bool lateral, double vigour, bool seedling,
                    const glm::vec3& optimal) {
        const int maxLength = mTrees[mM.tree[i]].params.maxShootLength;
        Growing g;
        g.metamer = static_cast<std::int32_t>(i);
        g.planned = static_cast<std::int32_t>(std::min(std::floor(vigour), double(maxLength)));
        g.slot = slots;
        g.vigour = vigour;
        g.optimal = optimal;
        g.lateral = lateral;
        g.seedling = seedling;
        slots += sz(g.planned);
        mGrowing.push_back(g);
    };
    auto planBud = [&](std::size_t i, bool lateral, double vigour) {
        if (vigour >= 1.0 && !(mM.deadBuds[i] & (lateral ? 2u : 1u)))
            plan(i, lateral, vigour, false, glm::vec3(0.0f));
    };
    bool allBorchertHonda = !mOptions.naiveAllocation;
    for (const StandTree& t : mTrees)
        allBorchertHonda = allBorchertHonda && t.params.allocation == SoAllocation::BorchertHonda;
    if (allBorchertHonda) {
        // The common case in one forward scan: vigour split and shoots planned as the scan
        // reaches each bud (the same buds, in the same order, as the general path below).
        mVigour.metamer.resize(n0);
        forEachBudVigourBorchertHonda(mM.topology(), mGathered, mTerminalLight, mAxillaryLight,
                                      mAlloc, mVigour.metamer, planBud);
    } else {
        allocate(mGathered, mTerminalLight, mAxillaryLight, mVigour);
        for (std::size_t i = 0; i < n0; ++i) {
            if (mM.mainChild[i] < 0) planBud(i, false, mVigour.terminal[i]);
            if (mM.lateralChild[i] < 0) planBud(i, true, mVigour.axillary[i]);
        }
    }
    const Clock::time_point t3 = Clock::now();

    if (mEnv == SoEnvironment::SpaceColonization) {
        // A tree that perceives no marker at all (a seedling below its crown envelope) grows
        // its leader straight up, max_shoot_length metamers per cycle, until it reaches them.
        for (std::size_t i = 0; i < n0; ++i) {
            if (mM.parent[i] >= 0 || mGathered[i] > 0.0) continue;
            std::size_t tip = i;
            while (mM.mainChild[tip] >= 0)
                tip = sz(mM.mainChild[tip]);
            if (mM.deadBuds[tip] & 1u) continue;
            plan(tip, false, static_cast<double>(mTrees[mM.tree[i]].params.maxShootLength), true,
                 kUp);
        }
    }
    mShootEnd.resize(slots);
    mShootFrame.resize(slots);
    // Optimal directions first (scattered grid reads, fetched a few buds ahead), then shoots.
    const auto count = static_cast<std::int64_t>(mGrowing.size());
    const Clock::time_point s0 = Clock::now();
    constexpr std::int64_t kAhead = 8;
    if (mShadow) {
        mBudVoxels.resize(mGrowing.size());
        forEachIndex(count, count >= kParallelCheap, [&](std::int64_t k) {
            const auto b = static_cast<std::size_t>(k);
            mBudVoxels[b] = mShadow->voxelOf(mM.end[sz(mGrowing[b].metamer)]);
        });
    }
    forEachIndexDynamic(count, count >= kParallelCostly, 64, [&](std::int64_t k) {
        Growing& g = mGrowing[static_cast<std::size_t>(k)];
        const std::size_t i = sz(g.metamer);
        if (g.seedling) {
            // Grows straight up (optimal = +Y, set when planned).
        } else if (mEnv == SoEnvironment::SpaceColonization) {
            g.optimal = g.lateral ? mOptimalAxillary[i] : mOptimalTerminal[i];
        } else {
            const std::uint16_t t = mM.tree[i];
            if (k + kAhead < count)
                mShadow->prefetchNeighbourhood(mBudVoxels[static_cast<std::size_t>(k + kAhead)]);
            const glm::quat f = g.lateral ? mM.frame[i] * mLateralTurn[t] : mM.frame[i];
            g.optimal = optimalShadowDirection(mBudVoxels[static_cast<std::size_t>(k)],
                                               skel::headingOf(f), mCosHalfCone[t]);
        }
    });
    const Clock::time_point s1 = Clock::now();
    forEachIndexDynamic(count, count >= kParallelCostly, 64, [&](std::int64_t k) {
        Growing& g = mGrowing[static_cast<std::size_t>(k)];
        g.made = makeShoot(g, mShootEnd.data() + g.slot, mShootFrame.data() + g.slot);
    });
    const Clock::time_point s2 = Clock::now();
    commitShoots();
    const Clock::time_point t4 = Clock::now();

    // Environment update: only the metamers shed and added this cycle, in one batch.
    const std::size_t n1 = mM.size();
    if (mShadow && !mOptions.naiveShadow) {
        const std::size_t removed = mSources.size();
        mSources.resize(removed + (n1 - n0));
        const auto added = static_cast<std::int64_t>(n1 - n0);
        forEachIndex(added, added >= kParallelCheap, [&](std::int64_t k) {
            const std::size_t i = n0 + static_cast<std::size_t>(k);
            mSources[removed + static_cast<std::size_t>(k)] = {mShadow->voxelOf(mM.end[i]), 1,
                                                               mM.tree[i]};
        });
        mShadow->applyBatch(mSources, mKernels);
    }
    if (mMarkers)
        for (std::size_t i = n0; i < n1; ++i) {
            const SelfOrganizingParams& sp = mTrees[mM.tree[i]].params;
            mMarkers->removeWithin(mM.end[i],
                                   static_cast<float>(sp.occupancyRadius * sp.internodeLength));
        }
    if (mShadow && mOptions.naiveShadow) rebuildShadow();
    ++mCycle;
    const Clock::time_point t5 = Clock::now();
    mTimings = {ms(t0, t1), ms(t1, t2), ms(t2, t3), ms(t3, t4), ms(s0, s1),
                ms(s1, s2), ms(s2, t4), ms(t4, t5), ms(t0, t5)};
}

std::vector<SelfOrganizingResult> SelfOrganizingSimulation::results() {
    const std::size_t n = mM.size();
    std::vector<double> terminal, axillary;
    if (mShadow && mOptions.naiveShadow) rebuildShadow();
    evaluateLight(terminal, axillary);
    std::vector<double> gathered(n);
    std::vector<std::int32_t> internodes(n);
    gatherLight(mM.topology(), terminal, axillary, gathered, internodes);
    Vigour vig;
    allocate(gathered, terminal, axillary, vig);
    // The branches the next cycle would shed, decided exactly as step() decides them (same
    // light, same scan), so the editor can show which branches starve and why.
    std::vector<std::uint8_t> starved(n, 0);
    {
        std::vector<double> keptGathered(n);
        std::vector<std::int32_t> keptInternodes(n);
        std::vector<ShedSums> scratch;
        if (gatherLightAndMarkShed(mM.topology(), terminal, axillary, mShedThreshold, keptGathered,
                                   keptInternodes, starved, scratch)) {
            for (std::size_t i = 0; i < n; ++i)
                starved[i] =
                    (starved[i] & 1u) || (mM.parent[i] >= 0 && starved[sz(mM.parent[i])]) ? 1u : 0u;
        } else {
            std::fill(starved.begin(), starved.end(), std::uint8_t{0});
        }
    }

    std::vector<SelfOrganizingResult> out(mTrees.size());
    std::vector<std::int32_t> local(n, -1);
    for (std::size_t t = 0; t < mTrees.size(); ++t) {
        out[t].internodes = static_cast<std::size_t>(mCount[t]);
        out[t].cycles = mTrees[t].params.cycles;
        out[t].skeleton.reserve(static_cast<std::size_t>(mCount[t]) + 1);
    }
    for (std::size_t i = 0; i < n; ++i) {
        const std::uint16_t t = mM.tree[i];
        const SelfOrganizingParams& sp = mTrees[t].params;
        SelfOrganizingResult& r = out[t];
        const glm::vec3 base = mTrees[t].position;
        const float radius = static_cast<float>(sp.tipRadius);
        std::int32_t parentNode;
        if (mM.parent[i] < 0) {
            parentNode = r.skeleton.addNode(glm::vec3(0.0f), -1, radius, 0, mM.frame[i]);
            r.light.push_back(static_cast<float>(gathered[i]));
            r.vigour.push_back(static_cast<float>(vig.metamer[i]));
            r.age.push_back(static_cast<std::uint16_t>(mCycle - mM.born[i]));
        } else {
            parentNode = local[sz(mM.parent[i])];
        }
        local[i] = r.skeleton.addNode(mM.end[i] - base, parentNode, radius, mM.order[i],
                                      mM.frame[i], starved[i] ? skel::kStarved : 0);
        r.starved += starved[i];
        r.light.push_back(static_cast<float>(gathered[i]));
        r.vigour.push_back(static_cast<float>(vig.metamer[i]));
        const int age = mCycle - mM.born[i];
        r.age.push_back(static_cast<std::uint16_t>(age));
        if (sp.leafSize > 0.0 && age < sp.leafAge && mM.lateralChild[i] < 0) {
            skel::Leaf leaf;
            leaf.position = mM.end[i] - base;
            leaf.orientation = lateralFrame(mM.frame[i], radians(sp.branchAngle));
            leaf.size = static_cast<float>(sp.leafSize);
            leaf.node = local[i];
            r.skeleton.leaves.push_back(leaf);
        }
    }
    for (std::size_t t = 0; t < mTrees.size(); ++t) {
        out[t].shed = mShedTree[t];
        out[t].skeleton.shedThreshold = static_cast<float>(mTrees[t].params.sheddingThreshold);
        out[t].skeleton.finalize();
        applyPipeModel(out[t].skeleton, static_cast<float>(mTrees[t].params.tipRadius),
                       static_cast<float>(mTrees[t].params.pipeExponent));
        skel::shapeRadii(out[t].skeleton, {static_cast<float>(mTrees[t].params.taper),
                                           static_cast<float>(mTrees[t].params.junctionSlope)});
    }
    return out;
}

// ---------------------------------------------------------------------------------------------

std::vector<SelfOrganizingResult> growStandDetailed(const std::vector<StandTree>& trees,
                                                    const std::vector<glm::vec3>& obstacles,
                                                    Progress& progress) {
    SelfOrganizingSimulation sim(trees, obstacles);
    while (!sim.done()) {
        progress.checkCancelled();
        progress.report(static_cast<double>(sim.cycle()) / sim.totalCycles(), "grow");
        sim.step();
    }
    progress.report(1.0, "grow");
    return sim.results();
}

std::vector<skel::Skeleton> growStand(const std::vector<StandTree>& trees,
                                      const std::vector<glm::vec3>& obstacles, Progress& progress) {
    std::vector<SelfOrganizingResult> r = growStandDetailed(trees, obstacles, progress);
    std::vector<skel::Skeleton> out;
    out.reserve(r.size());
    for (SelfOrganizingResult& x : r)
        out.push_back(std::move(x.skeleton));
    return out;
}

SelfOrganizingResult growSelfOrganizingDetailed(const SelfOrganizingParams& params,
                                                std::uint64_t seed, Progress& progress) {
    std::vector<SelfOrganizingResult> r =
        growStandDetailed({StandTree{glm::vec3(0.0f), params, seed}}, {}, progress);
    return std::move(r[0]);
}

skel::Skeleton growSelfOrganizing(const SelfOrganizingParams& params, std::uint64_t seed,
                                  Progress& progress) {
    return growSelfOrganizingDetailed(params, seed, progress).skeleton;
}

} // namespace sylva::growth
