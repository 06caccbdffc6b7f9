#pragma once

#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include <glm/glm.hpp>

namespace sylva::growth {

/// One space-colonization iteration's attraction (step 2 of colonize()): for every node that is
/// the closest node of at least one live point, the sum of the unit vectors from it to those
/// points (summed in point index order), their count and a hash of the set (mixSeed folded over
/// the point indices in order); the nodes so attracted in increasing index order. The arrays
/// are per node and grow with the skeleton; the caller zeroes count[j] of each attracted node
/// once it has used it (the other entries of sum and setHash are stale until a node is
/// attracted again). The closest of a node's points: nearestPoints().
struct Attraction {
    std::vector<glm::vec3> sum;
    std::vector<std::uint32_t> count;   ///< 0 outside attracted between iterations; one spare
    std::vector<std::uint64_t> setHash; ///< with hashSets only
    std::vector<float> nearest2;        ///< by nearestPoints, for the nodes it was given
    std::vector<std::uint32_t> nearest;
    std::vector<std::uint8_t> wanted;     ///< nearestPoints' scratch, all zero between calls
    std::vector<std::uint32_t> attracted; ///< increasing node index
    std::vector<std::uint64_t> marks;     ///< one bit a node, all zero between calls
    std::vector<std::uint32_t> firstMet;  ///< scratch: the nodes as first met (without the hash)

    /// A point, a node or a sum in one 16-byte register: lane 0 the count lane (1 for a point,
    /// 0 for a node, a sum's count), then x, y, z. The packed sums (without the hash).
    struct alignas(16) Lanes {
        Lanes() {} // left as it is by resize (its fill went through a stack temporary)
        Lanes(float c, float px, float py, float pz) : count(c), x(px), y(py), z(pz) {}
        float count, x, y, z;
    };
    /// A node's position and its packed sum (all zero between calls), side by side.
    struct NodeLanes {
        Lanes at, sum;
    };
    std::vector<Lanes> point4;           ///< the points, made on the first packed call for them
    std::vector<NodeLanes> node4;        ///< the nodes, grown as they come, and spares
    std::vector<std::uint8_t> met;       ///< a node met by a point, all zero between calls
    const glm::vec3* point4Of = nullptr; ///< the points point4 copies
    const glm::vec3* node4Of = nullptr;  ///< the nodes node4 copies
};

/// Fills \p a for \p nodeCount nodes at \p nodes from the live points \p live (increasing
/// index order) with their cached closest node (\p bestNode, −1 when none is in reach) and its
/// squared distance (\p best2). Each point adds (point − node) · (1 / √best2) to its node's sum.
/// The attracted nodes come from a bit per node marked as a node is first met, read word by word
/// (the same order as sorting them, without the sort). setHash only with \p hashSets (else it
/// is left as it was; without it the sums take no branch a point: sum and count hold one spare
/// entry past the nodes for the points out of reach): colonize() needs no hash to tell a node's set
/// from the last iteration's (see there), and keeps it for its naive search, the oracle.
/// Without the hash and with \p packed (on SSE2, below 2^24 points) each point, node and sum is
/// one register (Attraction::Lanes; the same floats): \p a copies the points on its first call
/// for them and the nodes as they come, so between calls with the same node array its nodes
/// below the last call's count must not move (colonize only appends); \p packed false runs the
/// scalar loop, which the tests hold it to.
void sumAttraction(Attraction& a, std::span<const std::uint32_t> live,
                   std::span<const glm::vec3> points, const float* best2,
                   const std::int32_t* bestNode, const glm::vec3* nodes, std::size_t nodeCount,
                   bool hashSets = true, bool packed = true);

/// For each node of \p nodes (attracted ones): the closest of its live points (the first in index
/// order of equally close ones) into a.nearest[node], its squared distance into a.nearest2[node],
/// by one pass over the live points. colonize() needs them only for the nodes whose vectors
/// cancel or whose set repeats (a few a tree), so the sums do not track them point by point (a
/// compare and a branch on every point); one pass an iteration whatever their number.
void nearestPoints(Attraction& a, std::span<const std::uint32_t> nodes,
                   std::span<const std::uint32_t> live, const float* best2,
                   const std::int32_t* bestNode);

} // namespace sylva::growth
