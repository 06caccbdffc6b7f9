#include "engine/growth/spacecolonization.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <memory>
#include <string>

#include <glm/gtx/quaternion.hpp>

#include "engine/growth/attraction.h"
#include "engine/growth/colonizationsearch.h"
#include "engine/growth/nodeframes.h"
#include "engine/growth/pipemodel.h"
#include "engine/growth/spatialgrid.h"
#include "engine/util/error.h"
#include "engine/util/floatsincos.h"
#include "engine/util/random.h"
#include "engine/util/safenormalize.h"
#include "engine/util/seedsalts.h"

namespace sylva::growth {

void validate(const ColonizationParams& p) {
    requireRange("influence_distance", p.influenceDistance, 0.0, 1000.0);
    requireRange("segment_length", p.segmentLength, 0.0, 100.0);
    requireRange("kill_distance", p.killDistance, 0.0, 1000.0);
    if (!(p.segmentLength > 0.0f)) throw InvalidInput("segment_length must be in (0, 100], got 0");
    if (!(p.killDistance < p.influenceDistance))
        throw InvalidInput("kill_distance must be smaller than influence_distance (" +
                           std::to_string(p.influenceDistance) + "), got " +
                           std::to_string(p.killDistance));
    if (!(p.killDistance > p.segmentLength))
        throw InvalidInput("kill_distance must be larger than segment_length (" +
                           std::to_string(p.segmentLength) + "), got " +
                           std::to_string(p.killDistance) +
                           "; otherwise a branch can step over its points and circle them");
    requireRange("randomness", p.randomness, 0.0, 1.0);
    for (int a = 0; a < 3; ++a)
        requireRange("tropism component", p.tropism[a], -1.0, 1.0);
    if (glm::length(p.tropism) > 1.0f)
        throw InvalidInput("tropism must have length in [0, 1], got " +
                           std::to_string(glm::length(p.tropism)));
    requireRange("trunk_height", p.trunkHeight, 0.0, 1000.0);
    requireRange("clear_trunk", p.clearTrunk, 0.0, 1000.0);
    for (int a = 0; a < 3; ++a)
        requireRange("root component", p.root[a], -1e6, 1e6);
    requireRange("max_iterations", p.maxIterations, 1, 100000);
    requireRange("pipe_exponent", p.pipeExponent, kMinPipeExponent, kMaxPipeExponent);
    requireRange("tip_radius", p.tipRadius, 0.0, 10.0);
    if (!(p.tipRadius > 0.0f)) throw InvalidInput("tip_radius must be in (0, 10], got 0");
}

namespace {

glm::vec3 randomUnit(Rng& rng) {
    const double z = rng.uniform(-1.0, 1.0);
    const double phi = rng.uniform(0.0, 2.0 * 3.14159265358979323846);
    const double r = std::sqrt(std::max(0.0, 1.0 - z * z));
    // static_cast<float>(r * std::cos(phi)) and of r * std::sin(phi), mostly without libm's
    // sincos (~10 ns a node).
    const FloatSinCos t = floatSinCos(phi, r);
    return glm::vec3(t.cos, static_cast<float>(z), t.sin);
}

void buildTrunk(skel::Skeleton& skel, const std::vector<glm::vec3>& points,
                const ColonizationParams& p) {
    const glm::quat up(1, 0, 0, 0);
    skel.addNode(p.root, -1, 0.0f, 0, up);
    if (p.trunkHeight > 0.0f) {
        const int n =
            std::max(1, static_cast<int>(std::ceil(p.trunkHeight / p.segmentLength - 1e-4f)));
        for (int i = 1; i <= n; ++i)
            skel.addNode(p.root + glm::vec3(0, p.trunkHeight * static_cast<float>(i) / n, 0),
                         static_cast<std::int32_t>(skel.size() - 1), 0.0f, 0, up);
    }
    // Grow the trunk on up to the crown, as Runions et al. do, when it stops short of it.
    float top = -std::numeric_limits<float>::max();
    for (const glm::vec3& a : points)
        top = std::max(top, a.y);
    const float di2 = p.influenceDistance * p.influenceDistance;
    for (;;) {
        const glm::vec3 tip = skel.position.back();
        bool inReach = false;
        for (const glm::vec3& a : points)
            if (distance2(a, tip) < di2) {
                inReach = true;
                break;
            }
        if (inReach || tip.y >= top || skel.size() >= kMaxColonizationNodes) break;
        skel.addNode(tip + glm::vec3(0, p.segmentLength, 0),
                     static_cast<std::int32_t>(skel.size() - 1), 0.0f, 0, up);
    }
}

} // namespace

ColonizationResult colonize(const std::vector<glm::vec3>& attractors,
                            const ColonizationParams& params, const skel::Skeleton* initial,
                            NeighbourSearch search, Progress& progress) {
    validate(params);
    for (const glm::vec3& a : attractors)
        if (!std::isfinite(a.x) || !std::isfinite(a.y) || !std::isfinite(a.z))
            throw InvalidInput("attraction points must be finite");
    if (attractors.size() > std::numeric_limits<std::int32_t>::max())
        throw LimitExceeded("too many attraction points");

    ColonizationResult result;
    skel::Skeleton& skel = result.skeleton;
    if (initial != nullptr && !initial->empty()) {
        initial->validate();
        skel = *initial;
    } else {
        buildTrunk(skel, attractors, params);
    }
    result.initialNodes = skel.size();
    // A crown grows about a node a point (the oak: ~2,600 from ~2,200): room for 5/4 of them
    // up front instead of the vectors' doublings and copies as the nodes are appended.
    const std::size_t room =
        std::min(skel.size() + attractors.size() + attractors.size() / 4, kMaxColonizationNodes);
    skel.reserve(room);

    // The nodes the search sees: the skeleton's, but with the clear trunk's initial nodes moved
    // far out of everyone's reach (appended to as the skeleton grows; only when needed).
    std::vector<glm::vec3> searchPositions;
    if (params.clearTrunk > 0.0f && !skel.empty()) {
        float base = std::numeric_limits<float>::max();
        for (const glm::vec3& p : skel.position)
            base = std::min(base, p.y);
        searchPositions = skel.position;
        constexpr float kOutOfReach = 1e15f;
        bool any = false;
        for (glm::vec3& p : searchPositions)
            if (p.y < base + params.clearTrunk) {
                p = glm::vec3(kOutOfReach);
                any = true;
            }
        if (!any) searchPositions.clear();
    }
    const bool clearing = !searchPositions.empty();

    const float di2 = params.influenceDistance * params.influenceDistance;
    const float dk2 = params.killDistance * params.killDistance;
    const float D = params.segmentLength;

    PointState s{attractors,
                 std::vector<float>(attractors.size(), di2),
                 std::vector<std::int32_t>(attractors.size(), -1),
                 std::vector<std::uint8_t>(attractors.size(), 0),
                 {}};
    s.live.resize(attractors.size());
    for (std::size_t i = 0; i < attractors.size(); ++i)
        s.live[i] = static_cast<std::uint32_t>(i);

    std::unique_ptr<AcceleratedSearch> fast;
    if (search == NeighbourSearch::Accelerated && !attractors.empty())
        fast = std::make_unique<AcceleratedSearch>(attractors, params.influenceDistance);

    // Per-node scratch, grown with the skeleton.
    Attraction at;
    // Did node j keep the points it had when it grew last iteration? Its points now are a
    // subset of those: a point's closest node changes only to a node added since, and j was
    // not (it grew last iteration, so it was searched then), and points only die. So the same
    // count is the same set, and the hash of the set adds nothing: the accelerated path skips
    // it (its sum loop's longest chain); the naive path, the oracle, keeps hash and count,
    // and the tests hold both to the same skeleton.
    const bool hashSets = search == NeighbourSearch::Naive;
    std::vector<std::uint64_t> lastHash;
    std::vector<std::uint32_t> lastCount;
    std::vector<int> lastGrown;
    std::vector<glm::vec3> dirs;      ///< of the attracted nodes, this iteration
    std::vector<std::uint8_t> fix;    ///< per attracted node: 1 its vectors cancel, 2 it repeats
    std::vector<std::uint32_t> fixed; ///< the attracted nodes with a fix
    std::vector<float> lens;          ///< per attracted node: the length of its sum
    std::vector<glm::quat> frames;    ///< per attracted node: its new node's frame
    // The per-node arrays the same room (resized each iteration as the nodes come).
    at.sum.reserve(room + 1); // a spare entry past the nodes (see sumAttraction)
    at.count.reserve(room + 1);
    at.node4.reserve(room + 8); // the packed sums' nodes and spares (see sumAttraction)
    at.met.reserve(room + 16);
    at.setHash.reserve(room);
    at.marks.reserve(room / 64 + 1);
    lastHash.reserve(room);
    lastCount.reserve(room);
    lastGrown.reserve(room);

    Rng rng(mixSeed(params.seed, salt::kSpaceColonization));
    std::size_t firstNew = 0;
    std::size_t stale = 0; ///< killed points still in s.live (the accelerated search's)
    for (int iteration = 0;; ++iteration) {
        progress.checkCancelled();
        // 1. closest nodes and the kill zone
        if (clearing)
            searchPositions.insert(searchPositions.end(),
                                   skel.position.begin() +
                                       static_cast<std::ptrdiff_t>(searchPositions.size()),
                                   skel.position.end());
        const std::vector<glm::vec3>& searched = clearing ? searchPositions : skel.position;
        if (fast)
            stale += fast->update(s, searched, firstNew, dk2);
        else
            updateNaive(s, searched, di2, dk2);
        firstNew = skel.size();
        // The accelerated search sets a killed point's node to −1, so the sums pass it by: the
        // live list keeps the killed points until they are an eighth of it (or all of it), or
        // the loop ends; the naive search's are dropped at once.
        const bool last = iteration >= params.maxIterations;
        if (hashSets || last || stale * 8 >= s.live.size()) {
            dropKilled(s);
            stale = 0;
            if (s.live.empty()) {
                result.stopReason = StopReason::NoPointsLeft;
                break;
            }
            if (last) {
                result.stopReason = StopReason::IterationCap;
                break;
            }
        }

        // 2. sum the unit vectors per node, in point index order
        const std::size_t n = skel.size();
        if (hashSets) {
            sumAttraction(at, s.live, s.points, s.best2.data(), s.bestNode.data(),
                          skel.position.data(), n, true);
        } else {
            sumAttraction(at, s.live, s.points, s.best2.data(), s.bestNode.data(),
                          skel.position.data(), n, false);
        }
        lastHash.resize(n, 0);
        lastCount.resize(n, 0);
        lastGrown.resize(n, -2);
        const std::vector<std::uint32_t>& attracted = at.attracted;
        if (attracted.empty()) {
            result.stopReason = StopReason::NothingInReach;
            break;
        }

        // 3. grow one segment from every attracted node, in node index order
        if (skel.size() + attracted.size() > kMaxColonizationNodes)
            throw LimitExceeded("space colonization would exceed " +
                                std::to_string(kMaxColonizationNodes) +
                                " nodes; use fewer attraction points or a longer segment_length");
        // The directions first, then the nodes: each node's chain of square roots and
        // divisions (the mean, the random unit, the normalisation, then transport's rotation)
        // overlaps the next one's instead of waiting behind the skeleton's appends.
        // The nodes that grow straight toward their closest point (their vectors cancel, or
        // they kept last iteration's points), and those points, in one pass.
        fix.resize(attracted.size());
        lens.resize(attracted.size());
        fixed.clear();
        for (std::size_t k = 0; k < attracted.size(); ++k) {
            const std::uint32_t j = attracted[k];
            const float len = glm::length(at.sum[j]);
            const bool cancelled = len <= 1e-5f * static_cast<float>(at.count[j]);
            const bool repeated = !cancelled && lastGrown[j] == iteration - 1 &&
                                  lastCount[j] == at.count[j] &&
                                  (!hashSets || lastHash[j] == at.setHash[j]);
            fix[k] = cancelled ? 1 : repeated ? 2 : 0;
            lens[k] = len;
            if (fix[k] != 0) fixed.push_back(j);
        }
        if (!fixed.empty()) nearestPoints(at, fixed, s.live, s.best2.data(), s.bestNode.data());
        dirs.resize(attracted.size());
        for (std::size_t k = 0; k < attracted.size(); ++k) {
            const std::uint32_t j = attracted[k];
            const glm::vec3 origin = skel.position[j];
            glm::vec3 dir;
            if (fix[k] != 0) {
                dir = (s.points[at.nearest[j]] - origin) * (1.0f / std::sqrt(at.nearest2[j]));
                ++(fix[k] == 1 ? result.zeroAverageFixes : result.oscillationFixes);
            } else {
                const glm::vec3 mean = at.sum[j] / lens[k];
                dir = mean;
                if (params.randomness > 0.0f) dir += params.randomness * randomUnit(rng);
                dir += params.tropism;
                dir = safeNormalize(dir, mean);
            }
            dirs[k] = dir;
            lastGrown[j] = iteration;
            lastHash[j] = at.setHash[j];
            lastCount[j] = at.count[j];
            at.count[j] = 0;
        }
        // The new nodes' frames sixteen at a time where the processor has AVX-512 (each a chain
        // of two square roots and divisions, the rotation's and the normalisation's).
        transportFrames(skel.orientation, attracted, dirs, frames);
        for (std::size_t k = 0; k < attracted.size(); ++k) {
            const std::uint32_t j = attracted[k];
            skel.addNode(skel.position[j] + D * dirs[k], static_cast<std::int32_t>(j), 0.0f,
                         skel.order[j], frames[k]);
        }
        result.iterations = iteration + 1;
        progress.report(static_cast<double>(iteration + 1) / params.maxIterations, "grow");
    }

    if (stale > 0) dropKilled(s);
    result.killed = std::move(s.killed);
    result.killedCount = attractors.size() - s.live.size();

    // Thickness, then branch orders: the thickest new child continues its parent's axis.
    applyPipeModel(skel, params.tipRadius, params.pipeExponent);
    const std::size_t n0 = result.initialNodes;
    std::vector<std::uint8_t> hasInitialChild(skel.size(), 0);
    for (std::size_t i = 0; i < n0; ++i)
        if (skel.parent[i] >= 0) hasInitialChild[static_cast<std::size_t>(skel.parent[i])] = 1;
    std::vector<std::int32_t> mainChild(skel.size(), -1);
    for (std::size_t i = n0; i < skel.size(); ++i) {
        const auto p = static_cast<std::size_t>(skel.parent[i]);
        if (hasInitialChild[p]) continue;
        const std::int32_t cur = mainChild[p];
        if (cur < 0 || skel.radius[i] > skel.radius[static_cast<std::size_t>(cur)])
            mainChild[p] = static_cast<std::int32_t>(i);
    }
    for (std::size_t i = n0; i < skel.size(); ++i) {
        const auto p = static_cast<std::size_t>(skel.parent[i]);
        const int o = skel.order[p] + (mainChild[p] == static_cast<std::int32_t>(i) ? 0 : 1);
        skel.order[i] = static_cast<std::uint16_t>(std::min(o, 65535));
    }
    skel.finalize();
    return result;
}

} // namespace sylva::growth
