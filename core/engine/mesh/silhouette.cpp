#include "engine/mesh/silhouette.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <numbers>

namespace sylva::mesh {

void coverageMask(const Mesh& mesh, const glm::vec3& centre, const glm::vec3& right,
                  const glm::vec3& up, double scale, int pixels,
                  std::vector<std::uint8_t>& covered) {
    covered.assign(static_cast<std::size_t>(pixels) * static_cast<std::size_t>(pixels), 0);
    std::vector<glm::dvec2> screen(mesh.positions.size());
    for (std::size_t i = 0; i < screen.size(); ++i) {
        const glm::vec3 d = mesh.positions[i] - centre;
        screen[i] = {glm::dot(d, right) * scale + 0.5 * pixels,
                     0.5 * pixels - glm::dot(d, up) * scale};
    }
    for (std::size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
        const glm::dvec2 v[3] = {screen[mesh.indices[t]], screen[mesh.indices[t + 1]],
                                 screen[mesh.indices[t + 2]]};
        const double area =
            (v[1].x - v[0].x) * (v[2].y - v[0].y) - (v[1].y - v[0].y) * (v[2].x - v[0].x);
        const double sign = area >= 0.0 ? 1.0 : -1.0;
        const int x0 =
            std::max(0, static_cast<int>(std::floor(std::min({v[0].x, v[1].x, v[2].x}))));
        const int x1 =
            std::min(pixels - 1, static_cast<int>(std::floor(std::max({v[0].x, v[1].x, v[2].x}))));
        const int y0 =
            std::max(0, static_cast<int>(std::floor(std::min({v[0].y, v[1].y, v[2].y}))));
        const int y1 =
            std::min(pixels - 1, static_cast<int>(std::floor(std::max({v[0].y, v[1].y, v[2].y}))));
        // Each edge's half-plane pushed out by half a pixel along its normal's L1 extent: the
        // pixel square overlaps it. Within the bounding box this is the usual overestimating
        // conservative rasteriser.
        double ex[3], ey[3], e0[3];
        for (int k = 0; k < 3; ++k) {
            const glm::dvec2 p = v[k], q = v[(k + 1) % 3];
            ex[k] = -sign * (q.y - p.y);
            ey[k] = sign * (q.x - p.x);
            e0[k] = -(ex[k] * p.x + ey[k] * p.y) + 0.5 * (std::abs(ex[k]) + std::abs(ey[k]));
        }
        for (int y = y0; y <= y1; ++y)
            for (int x = x0; x <= x1; ++x) {
                const double px = x + 0.5, py = y + 0.5;
                if (ex[0] * px + ey[0] * py + e0[0] >= 0.0 &&
                    ex[1] * px + ey[1] * py + e0[1] >= 0.0 &&
                    ex[2] * px + ey[2] * py + e0[2] >= 0.0)
                    covered[static_cast<std::size_t>(y) * static_cast<std::size_t>(pixels) +
                            static_cast<std::size_t>(x)] = 1;
            }
    }
}

std::vector<std::uint8_t> closeMask(const std::vector<std::uint8_t>& mask, int width, int height,
                                    int radius) {
    const auto at = [width](int x, int y) {
        return static_cast<std::size_t>(y) * static_cast<std::size_t>(width) +
               static_cast<std::size_t>(x);
    };
    const auto disc = [&](const std::vector<std::uint8_t>& in, bool dilate) {
        std::vector<std::uint8_t> out(in.size());
        for (int y = 0; y < height; ++y)
            for (int x = 0; x < width; ++x) {
                bool v = !dilate;
                for (int dy = -radius; dy <= radius; ++dy)
                    for (int dx = -radius; dx <= radius; ++dx) {
                        if (dx * dx + dy * dy > radius * radius) continue;
                        const int xx = x + dx, yy = y + dy;
                        const bool inside =
                            xx >= 0 && yy >= 0 && xx < width && yy < height && in[at(xx, yy)];
                        v = dilate ? (v || inside) : (v && inside);
                    }
                out[at(x, y)] = v ? 1 : 0;
            }
        return out;
    };
    std::vector<std::uint8_t> closed = disc(disc(mask, true), false);
    for (std::size_t k = 0; k < closed.size(); ++k)
        closed[k] = closed[k] || mask[k];
    return closed;
}

glm::vec3 silhouetteView(int k, int views) {
    const double az = 2.0 * std::numbers::pi * k / std::max(views, 1), el = (k % 2) ? 0.35 : 0.0;
    return {static_cast<float>(std::cos(el) * std::sin(az)), static_cast<float>(std::sin(el)),
            static_cast<float>(std::cos(el) * std::cos(az))};
}

double maskIoU(const std::vector<std::uint8_t>& a, const std::vector<std::uint8_t>& b) {
    std::size_t both = 0, either = 0;
    for (std::size_t i = 0; i < a.size() && i < b.size(); ++i) {
        both += a[i] && b[i];
        either += a[i] || b[i];
    }
    return either ? static_cast<double>(both) / static_cast<double>(either) : 1.0;
}

} // namespace sylva::mesh
