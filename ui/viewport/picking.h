#pragma once

#include <cstdint>
#include <limits>
#include <memory>
#include <optional>
#include <vector>

#include <glm/glm.hpp>

namespace sylva::mesh {
struct Mesh;
}

namespace sylva::ui {

struct ViewTree;

/// A ray in world space; direction need not be unit (hit distances are in its units).
struct Ray {
    glm::vec3 origin{0.0f};
    glm::vec3 direction{0.0f, 0.0f, -1.0f};
};

/// Axis-aligned box; empty when lo > hi.
struct Bounds {
    glm::vec3 lo{std::numeric_limits<float>::max()};
    glm::vec3 hi{std::numeric_limits<float>::lowest()};
    bool empty() const { return lo.x > hi.x; }
    void add(const glm::vec3& p) {
        lo = glm::min(lo, p);
        hi = glm::max(hi, p);
    }
};

/// The world-space box of a mesh placed by \p transform (its local box's corners transformed).
Bounds worldBounds(const mesh::Mesh& mesh, const glm::mat4& transform);

/// The ray parameter where it enters \p box (0 when it starts inside), or none.
std::optional<float> intersect(const Ray& ray, const Bounds& box);

/// Möller–Trumbore: the ray parameter of the hit with triangle (a, b, c), either side, or none.
std::optional<float> intersect(const Ray& ray, const glm::vec3& a, const glm::vec3& b,
                               const glm::vec3& c);

struct TreeHit {
    int index = -1; ///< into the trees; -1 when the ray hits none
    float t = std::numeric_limits<float>::max();
};

/// The tree whose own triangles the ray hits first. Trees whose world box (\p bounds, one per
/// tree) the ray misses, or enters beyond the best hit so far, are skipped, so a click through a
/// gap in a crown picks what is behind it and a forest of 1,000 trees tests only the few boxes
/// the ray crosses. Hidden trees (\p hidden, by index; may be empty) are never picked.
/// Trees drawn coarser than their mesh (\p byBounds, by index; may be empty: a coarse level or
/// an impostor card, whose pixels are not the full mesh's): when the ray hits no tree's
/// triangles, the nearest of their world boxes it enters is the hit, so a click on a distant
/// tree's drawn crown selects it (a hit on triangles still wins, as before).
TreeHit pickTree(const Ray& ray, const std::vector<ViewTree>& trees,
                 const std::vector<Bounds>& bounds, const std::vector<bool>& hidden = {},
                 const std::vector<bool>& byBounds = {});

/// The same without the boxes: every triangle of every tree (the oracle for tests).
TreeHit pickTreeBruteForce(const Ray& ray, const std::vector<ViewTree>& trees,
                           const std::vector<bool>& hidden = {});

/// Where the ray meets the horizontal plane y = \p height, or none (parallel or behind).
std::optional<glm::vec3> hitPlane(const Ray& ray, float height);

} // namespace sylva::ui
