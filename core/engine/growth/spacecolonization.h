#pragma once

#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "engine/skeleton/skeleton.h"
#include "engine/util/progress.h"

namespace sylva::growth {

/// Parameters of space colonization (Runions, Lane, Prusinkiewicz 2007, open venation).
/// Distances in metres. validate() states and enforces the ranges.
struct ColonizationParams {
    float influenceDistance =
        3.0f; ///< d_i: a point attracts its closest node within d_i; (0, 1000]
    float killDistance =
        0.6f; ///< d_k: a point dies once a node is this close; (segmentLength, d_i)
    float segmentLength = 0.2f; ///< D: length of every new segment; (0, 100]
    float randomness = 0.147f;  ///< weight of a random unit vector added to each direction; [0, 1]
    glm::vec3 tropism{0.0f};    ///< bias added to each direction (gravity: (0,-g,0)); |t| <= 1
    float trunkHeight = 0.0f;   ///< straight trunk from root before colonizing; [0, 1000]
    glm::vec3 root{0.0f};       ///< trunk base when there is no initial skeleton
    /// No shoot grows from a node of the initial skeleton (or the straight trunk) lower than
    /// this above its lowest node (metres, [0, 1000], 0: off): a bare bole, no sprays hanging
    /// off the lower trunk. Such nodes neither attract nor kill points.
    float clearTrunk = 0.0f;
    int maxIterations = 1000;   ///< growth steps at most; [1, 100000]
    float pipeExponent = 2.41f; ///< see applyPipeModel(); [1, 4]
    float tipRadius = 0.01f;    ///< radius of tips in metres; (0, 10]
    std::uint64_t seed = 1;     ///< random directions (the attraction points have their own)
};

/// Throws InvalidInput "<name> must be ..." with the allowed range for the first bad value,
/// including the reference's findings d_k < d_i and d_k > D.
void validate(const ColonizationParams& params);

/// How the closest node of each attraction point is found. Both give the identical skeleton.
enum class NeighbourSearch {
    Accelerated, ///< cached closest node per point, updated with the new nodes only, grid-pruned
    Naive,       ///< all points × all nodes every iteration; the test oracle
};

enum class StopReason {
    NoPointsLeft,   ///< every attraction point was killed
    NothingInReach, ///< no live point is within d_i of any node: the iteration would add nothing
    IterationCap,   ///< maxIterations growth steps ran
};

struct ColonizationResult {
    skel::Skeleton skeleton;          ///< radii by the pipe model, orders, flags finalized
    std::vector<std::uint8_t> killed; ///< per attraction point
    int iterations = 0;               ///< growth steps run
    StopReason stopReason = StopReason::NothingInReach;
    std::size_t initialNodes = 0; ///< nodes of the initial skeleton or the trunk
    std::size_t killedCount = 0;
    std::size_t zeroAverageFixes = 0; ///< nodes whose attraction vectors cancelled
    std::size_t oscillationFixes = 0; ///< nodes that kept the same points after growing
};

/// Hard cap on nodes; colonize() throws LimitExceeded past it.
inline constexpr std::size_t kMaxColonizationNodes = 4'000'000;

/// Grows a skeleton toward \p attractors.
///
/// Without \p initial (or with an empty one) the tree starts as a straight trunk from
/// params.root, trunkHeight tall in segments of about segmentLength, extended upward while no
/// point is within d_i of its top (never above the highest point). With \p initial, colonization
/// continues from all its nodes (they keep their positions, orders and orientations, and its
/// leaves are kept); radii of the whole result come from the pipe model.
///
/// Each iteration: every live point finds its closest node within d_i (ties: lower node index);
/// points with a node closer than d_k die; every node attracted by at least one point grows one
/// segment of length D in the direction of the normalized sum of the unit vectors to its points
/// (summed in point index order), plus randomness × a random unit vector plus the tropism.
/// Two classic failures are handled explicitly: a node whose unit vectors cancel (the sum is
/// shorter than 1e-5 × their count) and a node whose new child captured none of its points (the
/// same set again next iteration: it would oscillate or sprout a brush of duplicates) both grow
/// straight toward their closest point instead, which is then captured for sure because d_k > D.
/// Stops when no point is left, when no point is in reach, or after maxIterations.
///
/// \throw InvalidInput for bad parameters, LimitExceeded past kMaxColonizationNodes,
/// Cancelled when \p progress asks to stop.
ColonizationResult colonize(const std::vector<glm::vec3>& attractors,
                            const ColonizationParams& params,
                            const skel::Skeleton* initial = nullptr,
                            NeighbourSearch search = NeighbourSearch::Accelerated,
                            Progress& progress = noProgress());

} // namespace sylva::growth
