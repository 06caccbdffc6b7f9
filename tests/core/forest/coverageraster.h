#pragma once
// A small CPU rasterizer for the LOD coverage test: which pixel centres a mesh covers when seen
// from a camera (no depth test for masks; an optional z-buffered colour image for pictures).

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <vector>

#include <glm/glm.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include "engine/mesh/mesh.h"

namespace sylva::test {

struct RasterCamera {
    glm::mat4 viewProj{1.0f};
    int width = 1920;
    int height = 1080;

    static RasterCamera lookAt(const glm::vec3& eye, const glm::vec3& target, double fovYDeg,
                               int width, int height) {
        RasterCamera c;
        c.width = width;
        c.height = height;
        const glm::mat4 proj =
            glm::perspective(static_cast<float>(glm::radians(fovYDeg)),
                             static_cast<float>(width) / static_cast<float>(height), 0.1f, 1e5f);
        c.viewProj = proj * glm::lookAt(eye, target, glm::vec3(0, 1, 0));
        return c;
    }

    /// The same camera and pixel size on a canvas \p guard pixels larger on every side (a guard
    /// band): a tree the frame cuts is drawn whole. Frame pixel (x, y) is (x + guard, y + guard).
    RasterCamera guarded(int guard) const {
        RasterCamera c = *this;
        c.width = width + 2 * guard;
        c.height = height + 2 * guard;
        // Normalised device coordinates shrink so the frame keeps its pixel size in the centre.
        c.viewProj =
            glm::scale(glm::mat4(1.0f),
                       glm::vec3(static_cast<float>(width) / static_cast<float>(c.width),
                                 static_cast<float>(height) / static_cast<float>(c.height), 1.0f)) *
            viewProj;
        return c;
    }
};

/// Calls fn(x, y, depth, triangle) for every pixel whose centre lies in a triangle of \p mesh
/// placed by \p model. Triangles crossing the near plane are skipped (trees stand in front).
template <typename Fn>
void rasterize(const mesh::Mesh& mesh, const glm::mat4& model, const RasterCamera& cam, Fn&& fn) {
    const glm::mat4 mvp = cam.viewProj * model;
    std::vector<glm::vec3> s(mesh.positions.size());
    std::vector<std::uint8_t> ok(mesh.positions.size());
    for (std::size_t i = 0; i < s.size(); ++i) {
        const glm::vec4 c = mvp * glm::vec4(mesh.positions[i], 1.0f);
        ok[i] = c.w > 0.1f;
        const float iw = 1.0f / c.w;
        s[i] = {(c.x * iw + 1.0f) * 0.5f * static_cast<float>(cam.width),
                (1.0f - c.y * iw) * 0.5f * static_cast<float>(cam.height), c.z * iw};
    }
    for (std::size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
        const std::uint32_t ia = mesh.indices[t], ib = mesh.indices[t + 1],
                            ic = mesh.indices[t + 2];
        if (!ok[ia] || !ok[ib] || !ok[ic]) continue;
        const glm::vec3 a = s[ia], b = s[ib], c = s[ic];
        const float area = (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x);
        if (area == 0.0f) continue;
        const int x0 = std::max(0, static_cast<int>(std::ceil(std::min({a.x, b.x, c.x}) - 0.5f)));
        const int x1 =
            std::min(cam.width - 1, static_cast<int>(std::floor(std::max({a.x, b.x, c.x}) - 0.5f)));
        const int y0 = std::max(0, static_cast<int>(std::ceil(std::min({a.y, b.y, c.y}) - 0.5f)));
        const int y1 = std::min(cam.height - 1,
                                static_cast<int>(std::floor(std::max({a.y, b.y, c.y}) - 0.5f)));
        const float inv = 1.0f / area;
        for (int y = y0; y <= y1; ++y) {
            const float py = static_cast<float>(y) + 0.5f;
            for (int x = x0; x <= x1; ++x) {
                const float px = static_cast<float>(x) + 0.5f;
                const float w0 = ((b.x - px) * (c.y - py) - (b.y - py) * (c.x - px)) * inv;
                const float w1 = ((c.x - px) * (a.y - py) - (c.y - py) * (a.x - px)) * inv;
                const float w2 = 1.0f - w0 - w1;
                if (w0 < 0.0f || w1 < 0.0f || w2 < 0.0f) continue;
                fn(x, y, w0 * a.z + w1 * b.z + w2 * c.z, t / 3);
            }
        }
    }
}

/// Calls fn(x, y) for every pixel whose square [x, x+1] x [y, y+1] a triangle of \p mesh
/// overlaps at all (outer conservative rasterization: the triangle's bounds, then each edge
/// against the pixel corner farthest inside it), so that sub-pixel geometry counts for the
/// pixels it touches instead of depending on where the pixel centres fall.
template <typename Fn>
void rasterizeConservative(const mesh::Mesh& mesh, const glm::mat4& model, const RasterCamera& cam,
                           Fn&& fn) {
    const glm::mat4 mvp = cam.viewProj * model;
    std::vector<glm::dvec2> s(mesh.positions.size());
    std::vector<std::uint8_t> ok(mesh.positions.size());
    for (std::size_t i = 0; i < s.size(); ++i) {
        const glm::vec4 c = mvp * glm::vec4(mesh.positions[i], 1.0f);
        ok[i] = c.w > 0.1f;
        const double iw = 1.0 / c.w;
        s[i] = {(c.x * iw + 1.0) * 0.5 * cam.width, (1.0 - c.y * iw) * 0.5 * cam.height};
    }
    for (std::size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
        const std::uint32_t ia = mesh.indices[t], ib = mesh.indices[t + 1],
                            ic = mesh.indices[t + 2];
        if (!ok[ia] || !ok[ib] || !ok[ic]) continue;
        const glm::dvec2 v[3] = {s[ia], s[ib], s[ic]};
        const double area =
            (v[1].x - v[0].x) * (v[2].y - v[0].y) - (v[1].y - v[0].y) * (v[2].x - v[0].x);
        const double sign = area >= 0.0 ? 1.0 : -1.0;
        const int x0 =
            std::max(0, static_cast<int>(std::floor(std::min({v[0].x, v[1].x, v[2].x}))));
        const int x1 = std::min(cam.width - 1,
                                static_cast<int>(std::floor(std::max({v[0].x, v[1].x, v[2].x}))));
        const int y0 =
            std::max(0, static_cast<int>(std::floor(std::min({v[0].y, v[1].y, v[2].y}))));
        const int y1 = std::min(cam.height - 1,
                                static_cast<int>(std::floor(std::max({v[0].y, v[1].y, v[2].y}))));
        // Edge k: sign · cross(b - a, p - a) >= 0 inside; its largest value over a pixel square
        // is the value at the centre plus half the L1 norm of the gradient.
        double ex[3], ey[3], e0[3];
        for (int k = 0; k < 3; ++k) {
            const glm::dvec2 a = v[k], b = v[(k + 1) % 3];
            ex[k] = -sign * (b.y - a.y);
            ey[k] = sign * (b.x - a.x);
            e0[k] = -(ex[k] * a.x + ey[k] * a.y) + 0.5 * (std::abs(ex[k]) + std::abs(ey[k]));
        }
        for (int y = y0; y <= y1; ++y) {
            const double py = y + 0.5;
            for (int x = x0; x <= x1; ++x) {
                const double px = x + 0.5;
                bool in = true;
                for (int k = 0; k < 3 && in; ++k)
                    in = ex[k] * px + ey[k] * py + e0[k] >= 0.0;
                if (in) fn(x, y);
            }
        }
    }
}

/// A coverage mask: the sorted indices (y · width + x) of the covered pixels.
using Mask = std::vector<std::uint32_t>;

/// Which pixels \p mesh covers: the pixels it touches (\p conservative) or the pixel centres
/// it contains. \p scratch is a zeroed screen-sized buffer, left zeroed.
inline Mask coverage(const mesh::Mesh& mesh, const glm::mat4& model, const RasterCamera& cam,
                     std::vector<std::uint8_t>& scratch, bool conservative = true) {
    scratch.resize(static_cast<std::size_t>(cam.width) * static_cast<std::size_t>(cam.height), 0);
    Mask m;
    const auto mark = [&](int x, int y) {
        const auto k = static_cast<std::uint32_t>(y * cam.width + x);
        if (scratch[k]) return;
        scratch[k] = 1;
        m.push_back(k);
    };
    if (conservative)
        rasterizeConservative(mesh, model, cam, mark);
    else
        rasterize(mesh, model, cam, [&](int x, int y, float, std::size_t) { mark(x, y); });
    for (std::uint32_t k : m)
        scratch[k] = 0;
    std::sort(m.begin(), m.end());
    return m;
}

/// Intersection over union of two masks; -1 when both are empty.
inline double iou(const Mask& a, const Mask& b) {
    std::size_t inter = 0, i = 0, j = 0;
    while (i < a.size() && j < b.size()) {
        if (a[i] == b[j]) {
            ++inter;
            ++i;
            ++j;
        } else if (a[i] < b[j]) {
            ++i;
        } else {
            ++j;
        }
    }
    const std::size_t uni = a.size() + b.size() - inter;
    return uni == 0 ? -1.0 : static_cast<double>(inter) / static_cast<double>(uni);
}

/// A z-buffered picture: bark brown, leaves green, shaded a little by depth.
struct Picture {
    int width = 0, height = 0;
    std::vector<glm::u8vec3> rgb;
    std::vector<float> depth;
    Picture(int w, int h)
        : width(w), height(h), rgb(static_cast<std::size_t>(w) * h, glm::u8vec3(235, 240, 245)),
          depth(static_cast<std::size_t>(w) * h, 2.0f) {}

    void draw(const mesh::Mesh& mesh, const glm::mat4& model, const RasterCamera& cam) {
        std::vector<std::uint8_t> leaf(mesh.indices.size() / 3, 0);
        for (const mesh::Submesh& s : mesh.submeshes)
            if (s.material == "leaf")
                for (std::uint32_t t = s.firstIndex / 3; t < (s.firstIndex + s.indexCount) / 3; ++t)
                    leaf[t] = 1;
        rasterize(mesh, model, cam, [&](int x, int y, float z, std::size_t t) {
            const std::size_t k = static_cast<std::size_t>(y) * width + x;
            if (z >= depth[k]) return;
            depth[k] = z;
            rgb[k] = leaf[t] ? glm::u8vec3(58, 120, 48) : glm::u8vec3(96, 70, 48);
        });
    }

    /// Binary PPM (convert it to PNG with ImageMagick's `convert`).
    void writePpm(const std::filesystem::path& file) const {
        std::ofstream out(file, std::ios::binary);
        out << "P6\n" << width << " " << height << "\n255\n";
        out.write(reinterpret_cast<const char*>(rgb.data()),
                  static_cast<std::streamsize>(rgb.size() * 3));
    }
};

} // namespace sylva::test
