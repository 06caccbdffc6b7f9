#pragma once

#include <cstdint>
#include <vector>

#include <glm/glm.hpp>
#include <glm/gtc/quaternion.hpp>

namespace sylva::skel {

/// Bits of Skeleton::flags.
enum NodeFlag : std::uint8_t {
    kHidden = 1 << 0, ///< pruned by adaptation; kept so re-adapting and undo can restore it
    kTip = 1 << 1,    ///< no child continues this axis (set by finalize())
    kFork = 1 << 2,   ///< more than one child (set by finalize())
    /// Self-organizing growth: in a lateral branch whose light per internode is below its
    /// tree's shedding threshold (Skeleton::shedThreshold), so the next cycle would shed it.
    kStarved = 1 << 3,
};

/// The turtle frame convention, used everywhere a rest orientation is stored: the quaternion
/// maps the local axes to world space with heading = q·(0,1,0), left = q·(-1,0,0) and
/// up = q·(0,0,1). The identity is a turtle at the origin heading +Y (up), left -X, up +Z.
inline glm::vec3 headingOf(const glm::quat& q) {
    return q * glm::vec3(0, 1, 0);
}
inline glm::vec3 leftOf(const glm::quat& q) {
    return q * glm::vec3(-1, 0, 0);
}
inline glm::vec3 upOf(const glm::quat& q) {
    return q * glm::vec3(0, 0, 1);
}

/// A leaf (from the grammar's J or a later leaves node): a card anchored at position.
struct Leaf {
    glm::vec3 position{0.0f};
    glm::quat orientation{1, 0, 0, 0}; ///< same frame convention as the nodes
    float size = 1.0f;                 ///< metres (card length)
    std::int32_t node = -1;            ///< skeleton node it hangs on, -1 if none
};

/// The one currency between stages: a forest of node trees in struct-of-arrays form.
/// Invariant: parent[i] < i (parents before children), parent[i] == -1 for roots.
/// A node with a parent is the end of the segment parent -> node. Units are metres, Y is up.
struct Skeleton {
    std::vector<glm::vec3> position;
    std::vector<std::int32_t> parent;
    std::vector<float> radius;          ///< metres, at the node
    std::vector<std::uint16_t> order;   ///< branch order, 0 for the trunk
    std::vector<std::uint8_t> flags;    ///< NodeFlag bits
    std::vector<glm::quat> orientation; ///< rest orientation (turtle frame) at the node
    std::vector<Leaf> leaves;
    /// Optional per-node growth records (empty when the generator does not produce them; else
    /// one entry per node): light gathered by the node's subtree (units of full exposure),
    /// vigour flowing through it (metamer units) and its age in growth cycles. The editor
    /// colours trees by them, so a user can see why a branch was shed.
    std::vector<float> light;
    std::vector<float> vigour;
    std::vector<std::uint16_t> age;
    /// Optional provenance (empty unless the generator was asked to trace it; else one entry per
    /// node): the 1-based line of the generator's source text that made the node; for an
    /// L-system, the rule that wrote its F (or the axiom's line). The species editor highlights it.
    std::vector<std::int32_t> sourceLine;
    /// Light per internode below which a lateral branch is shed (self-organizing trees; 0 when
    /// the generator sheds nothing). Nodes below it now carry kStarved.
    float shedThreshold = 0.0f;

    std::size_t size() const { return position.size(); }
    bool empty() const { return position.empty(); }
    void reserve(std::size_t n);
    void clear();

    /// Appends a node and returns its index. \p parentIndex must be -1 or < size().
    std::int32_t addNode(const glm::vec3& pos, std::int32_t parentIndex, float r,
                         std::uint16_t branchOrder, const glm::quat& frame,
                         std::uint8_t nodeFlags = 0);

    /// Number of segments (nodes that have a parent).
    std::size_t segmentCount() const;
    /// Recomputes kTip and kFork from the topology.
    void finalize();
    /// Throws InvalidInput if the arrays disagree in size or parent[i] >= i.
    void validate() const;
    /// Axis-aligned bounds of all node positions; {0,0} for an empty skeleton.
    void bounds(glm::vec3& lo, glm::vec3& hi) const;
};

} // namespace sylva::skel
