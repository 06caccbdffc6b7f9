#pragma once

#include <glm/glm.hpp>

namespace sylva {

/// \p v scaled to unit length, or \p fallback when v is not longer than \p minLength (a
/// direction that summed to ~0 keeps the caller's).
inline glm::vec3 safeNormalize(const glm::vec3& v, const glm::vec3& fallback,
                               float minLength = 1e-6f) {
    const float l = glm::length(v);
    return l > minLength ? v / l : fallback;
}

} // namespace sylva
