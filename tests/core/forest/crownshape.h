#pragma once
// Crown silhouette measures (issue #33): a tree's side silhouette drawn orthographically by the
// CPU rasterizer of coverageraster.h, restricted to its crown rows (from the lowest to the
// highest row a leaf card covers), and the solidity of that silhouette: its area over the area
// of its convex hull. 1.0 is a blob whose outline has no bay and no hole; real crowns, with
// lumps, gaps and light between the limbs, measure about 0.75-0.85 (ez-tree's oak 0.79).

#include <algorithm>
#include <cstdint>
#include <vector>

#include <glm/glm.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include "coverageraster.h"
#include "engine/mesh/mesh.h"

namespace sylva::test {

/// A binary picture of one tree seen from the side: 1 where any triangle covers a pixel centre.
struct Silhouette {
    int width = 0, height = 0;
    std::vector<std::uint8_t> any;  ///< bark or leaves
    std::vector<std::uint8_t> leaf; ///< leaf cards only
    /// Pixel centres covered (not conservative): what the eye sees through the crown.
    std::vector<std::uint8_t> exact;
    double metresPerPixel = 0.0;
    bool at(int x, int y) const { return any[static_cast<std::size_t>(y) * width + x] != 0; }
};

/// The mesh seen along -Z rotated by \p yawDeg about +Y, scaled so the whole tree is
/// \p pixelsTall pixels high (one pixel of margin round it).
inline Silhouette sideSilhouette(const mesh::Mesh& mesh, int pixelsTall, float yawDeg = 0.0f) {
    const glm::mat4 rot = glm::rotate(glm::mat4(1.0f), glm::radians(yawDeg), glm::vec3(0, 1, 0));
    glm::vec3 lo(1e30f), hi(-1e30f);
    for (const glm::vec3& p : mesh.positions) {
        const glm::vec3 q = glm::vec3(rot * glm::vec4(p, 1.0f));
        lo = glm::min(lo, q);
        hi = glm::max(hi, q);
    }
    Silhouette s;
    const float tall = std::max(hi.y - lo.y, 1e-3f);
    const float mpp = tall / static_cast<float>(pixelsTall - 2);
    s.metresPerPixel = mpp;
    s.height = pixelsTall;
    s.width = static_cast<int>((hi.x - lo.x) / mpp) + 3;
    RasterCamera cam;
    cam.width = s.width;
    cam.height = s.height;
    const float w = static_cast<float>(s.width) * mpp, h = static_cast<float>(s.height) * mpp;
    const float cx = 0.5f * (lo.x + hi.x), cy = 0.5f * (lo.y + hi.y);
    cam.viewProj =
        glm::ortho(cx - 0.5f * w, cx + 0.5f * w, cy - 0.5f * h, cy + 0.5f * h, -1e4f, 1e4f) *
        glm::translate(glm::mat4(1.0f), glm::vec3(0, 0, 0)) * rot;
    const std::size_t n = static_cast<std::size_t>(s.width) * s.height;
    s.any.assign(n, 0);
    s.leaf.assign(n, 0);
    s.exact.assign(n, 0);
    // Conservative: a pixel any triangle touches is covered, so that leaves smaller than a
    // pixel close the outline instead of leaving pinholes that depend on where pixel centres fall.
    for (const mesh::Submesh& sm : mesh.submeshes) {
        mesh::Mesh part;
        part.positions = mesh.positions;
        part.indices.assign(mesh.indices.begin() + sm.firstIndex,
                            mesh.indices.begin() + sm.firstIndex + sm.indexCount);
        const bool leafRun = sm.material == "leaf";
        rasterizeConservative(part, glm::mat4(1.0f), cam, [&](int x, int y) {
            const std::size_t k = static_cast<std::size_t>(y) * s.width + x;
            s.any[k] = 1;
            if (leafRun) s.leaf[k] = 1;
        });
        rasterize(part, glm::mat4(1.0f), cam, [&](int x, int y, float, std::size_t) {
            s.exact[static_cast<std::size_t>(y) * s.width + x] = 1;
        });
    }
    return s;
}

struct CrownShape {
    double solidity = 1.0; ///< crown silhouette area / its convex hull's area
    double width = 0.0;    ///< widest crown row, metres
    double height = 0.0;   ///< crown rows, metres
    double treeHeight = 0.0;
    double crownBase = 0.0; ///< lowest leaf row above the ground, metres
    /// Height above the ground of the widest crown row, metres.
    double widestAt = 0.0;
    /// Covered fraction (pixel centres) of the crown's middle (an ellipse of 0.6 x the crown box's
    /// width and height about its centre): a crown of lit clusters alone is a thin shell that reads
    /// from the side as a ring round an empty middle; a real crown carries foliage in its depth.
    double middleCover = 1.0;
};

namespace detail {
inline double cross(const glm::dvec2& o, const glm::dvec2& a, const glm::dvec2& b) {
    return (a.x - o.x) * (b.y - o.y) - (a.y - o.y) * (b.x - o.x);
}
} // namespace detail

/// The crown's measures from a silhouette: solidity of the crown rows (bark included there),
/// the crown's extent.
inline CrownShape crownShape(const Silhouette& s) {
    CrownShape c;
    int top = -1, bottom = -1, treeTop = -1, ground = -1;
    for (int y = 0; y < s.height; ++y)
        for (int x = 0; x < s.width; ++x) {
            const std::size_t k = static_cast<std::size_t>(y) * s.width + x;
            if (s.any[k]) {
                if (treeTop < 0) treeTop = y;
                ground = y;
            }
            if (s.leaf[k]) {
                if (top < 0) top = y;
                bottom = y;
            }
        }
    if (top < 0) return c;
    std::vector<glm::dvec2> pts;
    double area = 0.0;
    int widest = 0, widestRow = bottom;
    for (int y = top; y <= bottom; ++y) {
        int x0 = -1, x1 = -1;
        for (int x = 0; x < s.width; ++x)
            if (s.at(x, y)) {
                if (x0 < 0) x0 = x;
                x1 = x;
                area += 1.0;
            }
        if (x0 < 0) continue;
        if (x1 - x0 + 1 > widest) {
            widest = x1 - x0 + 1;
            widestRow = y;
        }
        pts.push_back({x0, y});
        pts.push_back({x0, y + 1});
        pts.push_back({x1 + 1, y});
        pts.push_back({x1 + 1, y + 1});
    }
    // Andrew's monotone chain over the pixel corners of each row's ends.
    std::sort(pts.begin(), pts.end(), [](const glm::dvec2& a, const glm::dvec2& b) {
        return a.x < b.x || (a.x == b.x && a.y < b.y);
    });
    std::vector<glm::dvec2> hull(2 * pts.size());
    std::size_t k = 0;
    for (std::size_t i = 0; i < pts.size(); ++i) {
        while (k >= 2 && detail::cross(hull[k - 2], hull[k - 1], pts[i]) <= 0)
            --k;
        hull[k++] = pts[i];
    }
    for (std::size_t i = pts.size() - 1, t = k + 1; i > 0; --i) {
        while (k >= t && detail::cross(hull[k - 2], hull[k - 1], pts[i - 1]) <= 0)
            --k;
        hull[k++] = pts[i - 1];
    }
    hull.resize(k - 1);
    double hullArea = 0.0;
    for (std::size_t i = 0; i < hull.size(); ++i) {
        const glm::dvec2& a = hull[i];
        const glm::dvec2& b = hull[(i + 1) % hull.size()];
        hullArea += a.x * b.y - a.y * b.x;
    }
    hullArea = 0.5 * std::abs(hullArea);
    c.solidity = hullArea > 0.0 ? area / hullArea : 1.0;
    int left = s.width, right = -1;
    for (std::size_t i = 0; i < pts.size(); ++i) {
        left = std::min(left, static_cast<int>(pts[i].x));
        right = std::max(right, static_cast<int>(pts[i].x) - 1);
    }
    const double mx = 0.5 * (left + right + 1), my = 0.5 * (top + bottom + 1);
    const double ax = 0.3 * (right - left + 1), ay = 0.3 * (bottom - top + 1);
    int inMiddle = 0, covered = 0;
    for (int y = top; y <= bottom; ++y)
        for (int x = left; x <= right; ++x) {
            const double u = (x + 0.5 - mx) / ax, v = (y + 0.5 - my) / ay;
            if (u * u + v * v > 1.0) continue;
            ++inMiddle;
            const std::size_t at = static_cast<std::size_t>(y) * s.width + x;
            if (s.exact.empty() ? s.any[at] : s.exact[at]) ++covered;
        }
    c.middleCover = inMiddle > 0 ? static_cast<double>(covered) / inMiddle : 1.0;
    c.width = widest * s.metresPerPixel;
    c.height = (bottom - top + 1) * s.metresPerPixel;
    c.treeHeight = (ground - treeTop + 1) * s.metresPerPixel;
    c.crownBase = (ground - bottom) * s.metresPerPixel;
    c.widestAt = (ground - widestRow) * s.metresPerPixel;
    return c;
}

} // namespace sylva::test
