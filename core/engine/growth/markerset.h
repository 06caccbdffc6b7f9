#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include <glm/glm.hpp>

#include "engine/growth/spatialgrid.h"

namespace sylva::growth {

/// The marker points of the space colonization environment: free space that buds perceive
/// and that growth consumes. Markers are removed inside the occupancy zone of every new
/// metamer (and near obstacles); removal never reorders them, so results are deterministic.
class MarkerSet {
public:
    MarkerSet() = default;
    /// \param cell grid cell edge (metres), typically twice the occupancy radius.
    MarkerSet(std::vector<glm::vec3> positions, float cell);

    std::size_t size() const { return mPositions.size(); }
    std::size_t aliveCount() const { return mAlive; }
    const std::vector<glm::vec3>& positions() const { return mPositions; }
    bool alive(std::size_t i) const { return mAliveFlag[i] != 0; }

    /// Removes every marker closer than \p radius to \p p; returns how many.
    std::size_t removeWithin(const glm::vec3& p, float radius);
    /// Removes every marker closer than \p radius to the triangle (a, b, c).
    std::size_t removeNearTriangle(const glm::vec3& a, const glm::vec3& b, const glm::vec3& c,
                                   float radius);
    /// Indices of the markers still alive, in increasing order.
    std::vector<std::uint32_t> aliveIndices() const;
    /// Drops the dead markers from the grid when they are a quarter of those it holds (so that
    /// removeWithin() skips fewer); what every query finds does not change.
    void compact();

private:
    std::vector<glm::vec3> mPositions;
    std::vector<std::uint8_t> mAliveFlag;
    std::size_t mAlive = 0;
    PointGrid mGrid;
};

/// Closest point of triangle (a, b, c) to p (Ericson, Real-Time Collision Detection §5.1.5).
glm::vec3 closestPointOnTriangle(const glm::vec3& p, const glm::vec3& a, const glm::vec3& b,
                                 const glm::vec3& c);

} // namespace sylva::growth
