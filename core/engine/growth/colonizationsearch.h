#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>
#include <vector>

#include <glm/glm.hpp>

namespace sylva::growth {

/// Closest node within d_i of every live point, and the kill test.
struct PointState {
    const std::vector<glm::vec3>& points;
    std::vector<float> best2;           ///< squared distance to bestNode, d_i² when none
    std::vector<std::int32_t> bestNode; ///< -1 when no node is within d_i
    std::vector<std::uint8_t> killed;
    std::vector<std::uint32_t> live; ///< live points in increasing index order
};

/// Drops the points killed by the last update (\p s.killed) from \p s.live, keeping its order:
/// sixteen at a time with AVX-512 (their flags gathered, the kept ones compressed), else by
/// erase_if.
void dropKilled(PointState& s);

/// The oracle: every live point against every node, every iteration.
void updateNaive(PointState& s, const std::vector<glm::vec3>& nodes, float di2, float dk2);

/// Cached closest node per point. Nodes never move and points only die, so the closest node
/// can change only to a node added since the last update; nodes are visited in increasing index
/// order with a strict '<', which reproduces the oracle's lowest-index tie-breaking exactly.
/// Points are kept cell by cell (a uniform grid sized as PointGrid's) in struct-of-arrays form,
/// live points first, so both inner loops are branch-free and vectorize. A cell is skipped for
/// a new node when the node is no closer to the cell's bounds than the worst cached distance of
/// its live points (no point of it could improve); the bound holds in float arithmetic, so
/// skipping never changes a result (nor does which cell a point is in).
class AcceleratedSearch {
public:
    AcceleratedSearch(const std::vector<glm::vec3>& points, float di);
    ~AcceleratedSearch();
    AcceleratedSearch(const AcceleratedSearch&) = delete;
    AcceleratedSearch& operator=(const AcceleratedSearch&) = delete;

    /// Offers the nodes from \p firstNew on to the live points (their closest node and
    /// distance in \p s), and marks those within \p dk2 of it killed, their closest node −1
    /// (so that sums over a live list that still holds them pass them by). Returns how many
    /// it killed.
    std::size_t update(PointState& s, const std::vector<glm::vec3>& nodes, std::size_t firstNew,
                       float dk2);

private:
    struct Impl;
    std::unique_ptr<Impl> mImpl;
};

} // namespace sylva::growth
