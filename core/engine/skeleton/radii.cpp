#include "engine/skeleton/radii.h"

#include <algorithm>
#include <limits>
#include <vector>

#include "engine/util/error.h"

namespace sylva::skel {

void validate(const RadiusShaping& shaping) {
    requireRange("taper", shaping.taper, 0.0, 1.0);
    requireRange("junction_slope", shaping.junctionSlope, 0.0, 10.0);
}

void shapeRadii(Skeleton& s, const RadiusShaping& shaping) {
    validate(shaping);
    s.validate();
    const std::size_t n = s.size();
    if (n == 0) return;
    auto visible = [&](std::size_t i) { return (s.flags[i] & kHidden) == 0; };

    // 1. The child that continues each node's axis: the first of its own order, else the
    // thickest.
    std::vector<std::int32_t> next(n, -1);
    for (std::size_t i = 0; i < n; ++i) {
        const std::int32_t p = s.parent[i];
        if (p < 0 || !visible(i)) continue;
        const auto pi = static_cast<std::size_t>(p);
        const std::int32_t cur = next[pi];
        if (cur < 0) {
            next[pi] = static_cast<std::int32_t>(i);
            continue;
        }
        const auto ci = static_cast<std::size_t>(cur);
        const bool curSame = s.order[ci] == s.order[pi], iSame = s.order[i] == s.order[pi];
        if (curSame) continue;
        if (iSame || s.radius[i] > s.radius[ci]) next[pi] = static_cast<std::int32_t>(i);
    }
    for (std::size_t i = 0; i < n; ++i) {
        const std::int32_t p = s.parent[i];
        if (p < 0 || !visible(i)) continue;
        const auto pi = static_cast<std::size_t>(p);
        const int o = s.order[pi] + (next[pi] == static_cast<std::int32_t>(i) ? 0 : 1);
        s.order[i] = static_cast<std::uint16_t>(std::min(o, 65535));
    }

    auto length = [&](std::size_t a, std::size_t b) {
        return glm::length(s.position[b] - s.position[a]);
    };
    // 2. The least taper, from the tips down.
    if (shaping.taper > 0.0f)
        for (std::size_t i = n; i-- > 0;) {
            const std::int32_t c = next[i];
            if (c < 0) continue;
            const auto ci = static_cast<std::size_t>(c);
            s.radius[i] =
                std::max(s.radius[i], s.radius[ci] * (1.0f + shaping.taper * length(i, ci)));
        }
    // 3. No child thicker than its parent; no steep fall above a fork.
    for (std::size_t i = 0; i < n; ++i) {
        const std::int32_t p = s.parent[i];
        if (p < 0 || !visible(i)) continue;
        const auto pi = static_cast<std::size_t>(p);
        float r = std::min(s.radius[i], s.radius[pi]);
        if (shaping.junctionSlope > 0.0f && next[pi] == static_cast<std::int32_t>(i))
            r = std::max(r, s.radius[pi] - shaping.junctionSlope * length(pi, i));
        s.radius[i] = r;
    }
}

} // namespace sylva::skel
