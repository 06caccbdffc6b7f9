#include "engine/skeleton/skeleton.h"

#include "engine/util/error.h"

#include <string>

namespace sylva::skel {

void Skeleton::reserve(std::size_t n) {
    position.reserve(n);
    parent.reserve(n);
    radius.reserve(n);
    order.reserve(n);
    flags.reserve(n);
    orientation.reserve(n);
}

void Skeleton::clear() {
    position.clear();
    parent.clear();
    radius.clear();
    order.clear();
    flags.clear();
    orientation.clear();
    leaves.clear();
    light.clear();
    vigour.clear();
    age.clear();
    sourceLine.clear();
    shedThreshold = 0.0f;
}

std::int32_t Skeleton::addNode(const glm::vec3& pos, std::int32_t parentIndex, float r,
                               std::uint16_t branchOrder, const glm::quat& frame,
                               std::uint8_t nodeFlags) {
    const auto index = static_cast<std::int32_t>(position.size());
    position.push_back(pos);
    parent.push_back(parentIndex);
    radius.push_back(r);
    order.push_back(branchOrder);
    flags.push_back(nodeFlags);
    orientation.push_back(frame);
    // The optional records stay one entry per node once a generator has started them: a node
    // appended by a later stage (space colonization growing a crown on an L-system trunk traced
    // for the species editor) has no source line (0), no light, vigour or age of its own.
    if (!sourceLine.empty()) sourceLine.push_back(0);
    if (!light.empty()) light.push_back(0.0f);
    if (!vigour.empty()) vigour.push_back(0.0f);
    if (!age.empty()) age.push_back(0);
    return index;
}

std::size_t Skeleton::segmentCount() const {
    std::size_t n = 0;
    for (std::int32_t p : parent)
        n += p >= 0 ? 1 : 0;
    return n;
}

void Skeleton::finalize() {
    std::vector<std::uint32_t> children(size(), 0);
    for (std::size_t i = 0; i < size(); ++i)
        if (parent[i] >= 0) ++children[static_cast<std::size_t>(parent[i])];
    for (std::size_t i = 0; i < size(); ++i) {
        std::uint8_t f = flags[i] & static_cast<std::uint8_t>(~(kTip | kFork));
        if (children[i] == 0) f |= kTip;
        if (children[i] > 1) f |= kFork;
        flags[i] = f;
    }
}

void Skeleton::validate() const {
    const std::size_t n = position.size();
    if (parent.size() != n || radius.size() != n || order.size() != n || flags.size() != n ||
        orientation.size() != n)
        throw InvalidInput("skeleton arrays differ in size");
    if ((!light.empty() && light.size() != n) || (!vigour.empty() && vigour.size() != n) ||
        (!age.empty() && age.size() != n))
        throw InvalidInput("skeleton growth records (light, vigour, age) differ in size");
    if (!sourceLine.empty() && sourceLine.size() != n)
        throw InvalidInput("skeleton source lines differ in size from its nodes");
    for (std::size_t i = 0; i < n; ++i)
        if (parent[i] >= static_cast<std::int32_t>(i) || parent[i] < -1)
            throw InvalidInput("skeleton node " + std::to_string(i) +
                               " does not come after its parent");
}

void Skeleton::bounds(glm::vec3& lo, glm::vec3& hi) const {
    if (position.empty()) {
        lo = hi = glm::vec3(0.0f);
        return;
    }
    lo = hi = position[0];
    for (const glm::vec3& p : position) {
        lo = glm::min(lo, p);
        hi = glm::max(hi, p);
    }
}

} // namespace sylva::skel
