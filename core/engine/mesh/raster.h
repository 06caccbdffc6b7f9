#pragma once

#include <algorithm>
#include <cmath>

#include <glm/glm.hpp>

namespace sylva::mesh {

/// Sylva's CPU triangle rasteriser (the impostor baker's; tests keep their own oracle in
/// tests/core/forest/coverageraster.h). \p a, \p b, \p c are in pixels (x right, y down, z free
/// for the caller); fn(x, y, w0, w1, w2) is called for every pixel of the \p width × \p height
/// target whose centre lies inside the triangle (either winding), with the barycentric weights
/// of a, b and c at that centre. Pixel centres on a shared edge go to one triangle only (the
/// top-left rule), so a mesh without holes covers each pixel once. Affine interpolation: exact
/// for orthographic views, which is what it is used for.
template <typename Fn>
void rasterizeTriangle(const glm::vec3& a, const glm::vec3& b, const glm::vec3& c, int width,
                       int height, Fn&& fn) {
    const float area = (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x);
    if (!(std::abs(area) > 1e-12f)) return;
    const int x0 = std::max(0, static_cast<int>(std::ceil(std::min({a.x, b.x, c.x}) - 0.5f)));
    const int x1 =
        std::min(width - 1, static_cast<int>(std::floor(std::max({a.x, b.x, c.x}) - 0.5f)));
    const int y0 = std::max(0, static_cast<int>(std::ceil(std::min({a.y, b.y, c.y}) - 0.5f)));
    const int y1 =
        std::min(height - 1, static_cast<int>(std::floor(std::max({a.y, b.y, c.y}) - 0.5f)));
    if (x0 > x1 || y0 > y1) return;
    const float inv = 1.0f / area;
    // Edge functions normalised so that inside is >= 0 for either winding; an edge owns the
    // centres exactly on it when it is a top or left edge of the (normalised) triangle.
    const glm::vec2 v[3] = {{a.x, a.y}, {b.x, b.y}, {c.x, c.y}};
    float ex[3], ey[3], e0[3];
    bool owns[3];
    for (int k = 0; k < 3; ++k) {
        // Weight of vertex k: the edge opposite it.
        const glm::vec2 p = v[(k + 1) % 3], q = v[(k + 2) % 3];
        ex[k] = (p.y - q.y) * inv;
        ey[k] = (q.x - p.x) * inv;
        e0[k] = (p.x * q.y - q.x * p.y) * inv;
        owns[k] = ey[k] > 0.0f || (ey[k] == 0.0f && ex[k] > 0.0f);
    }
    for (int y = y0; y <= y1; ++y) {
        const float py = static_cast<float>(y) + 0.5f;
        for (int x = x0; x <= x1; ++x) {
            const float px = static_cast<float>(x) + 0.5f;
            float w[3];
            bool in = true;
            for (int k = 0; k < 3 && in; ++k) {
                w[k] = ex[k] * px + ey[k] * py + e0[k];
                in = w[k] > 0.0f || (w[k] == 0.0f && owns[k]);
            }
            if (in) fn(x, y, w[0], w[1], w[2]);
        }
    }
}

} // namespace sylva::mesh
