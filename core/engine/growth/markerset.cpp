#include "engine/growth/markerset.h"

#include "engine/util/closestpoint.h"

#include <algorithm>
#include <cmath>

namespace sylva::growth {

MarkerSet::MarkerSet(std::vector<glm::vec3> positions, float cell)
    : mPositions(std::move(positions)), mAliveFlag(mPositions.size(), 1),
      mAlive(mPositions.size()) {
    mGrid = PointGrid(mPositions, cell);
}

void MarkerSet::compact() {
    if (4 * mAlive >= 3 * mGrid.order().size()) return;
    mGrid.keepOnly([this](std::uint32_t i) { return mAliveFlag[i] != 0; });
}

std::size_t MarkerSet::removeWithin(const glm::vec3& p, float radius) {
    std::size_t removed = 0;
    mGrid.forEachInRadius(p, radius, [&](std::uint32_t i, float) {
        if (!mAliveFlag[i]) return;
        mAliveFlag[i] = 0;
        ++removed;
    });
    mAlive -= removed;
    return removed;
}

glm::vec3 closestPointOnTriangle(const glm::vec3& p, const glm::vec3& a, const glm::vec3& b,
                                 const glm::vec3& c) {
    return sylva::closestPointOnTriangle(p, a, b, c);
}

std::size_t MarkerSet::removeNearTriangle(const glm::vec3& a, const glm::vec3& b,
                                          const glm::vec3& c, float radius) {
    // Only markers within the triangle's bounding sphere grown by radius can be near it: ask the
    // grid for those instead of testing every marker (a 10k-triangle obstacle against 100k+
    // markers took 20 s the brute-force way).
    const glm::vec3 centre = (a + b + c) / 3.0f;
    const float reach =
        std::sqrt(std::max({glm::dot(a - centre, a - centre), glm::dot(b - centre, b - centre),
                            glm::dot(c - centre, c - centre)})) +
        radius;
    std::size_t removed = 0;
    const float r2 = radius * radius;
    mGrid.forEachInRadius(centre, reach, [&](std::uint32_t i, float) {
        if (!mAliveFlag[i]) return;
        const glm::vec3 d = closestPointOnTriangle(mPositions[i], a, b, c) - mPositions[i];
        if (glm::dot(d, d) < r2) {
            mAliveFlag[i] = 0;
            ++removed;
        }
    });
    mAlive -= removed;
    return removed;
}

std::vector<std::uint32_t> MarkerSet::aliveIndices() const {
    std::vector<std::uint32_t> out;
    out.reserve(mAlive);
    for (std::size_t i = 0; i < mPositions.size(); ++i)
        if (mAliveFlag[i]) out.push_back(static_cast<std::uint32_t>(i));
    return out;
}

} // namespace sylva::growth
