#include "ui/viewport/picking.h"

#include <algorithm>
#include <cmath>

#include "engine/mesh/mesh.h"
#include "ui/viewport/viewtree.h"

namespace sylva::ui {

Bounds worldBounds(const mesh::Mesh& m, const glm::mat4& transform) {
    Bounds local, world;
    for (const glm::vec3& p : m.positions)
        local.add(p);
    if (local.empty()) return world;
    for (int corner = 0; corner < 8; ++corner) {
        const glm::vec3 c((corner & 1) ? local.hi.x : local.lo.x,
                          (corner & 2) ? local.hi.y : local.lo.y,
                          (corner & 4) ? local.hi.z : local.lo.z);
        world.add(glm::vec3(transform * glm::vec4(c, 1.0f)));
    }
    return world;
}

std::optional<float> intersect(const Ray& ray, const Bounds& box) {
    if (box.empty()) return std::nullopt;
    float t0 = 0.0f, t1 = std::numeric_limits<float>::max();
    for (int k = 0; k < 3; ++k) {
        const float d = ray.direction[k];
        if (std::abs(d) < 1e-12f) {
            if (ray.origin[k] < box.lo[k] || ray.origin[k] > box.hi[k]) return std::nullopt;
            continue;
        }
        float a = (box.lo[k] - ray.origin[k]) / d;
        float b = (box.hi[k] - ray.origin[k]) / d;
        if (a > b) std::swap(a, b);
        t0 = std::max(t0, a);
        t1 = std::min(t1, b);
        if (t0 > t1) return std::nullopt;
    }
    return t0;
}

std::optional<float> intersect(const Ray& ray, const glm::vec3& a, const glm::vec3& b,
                               const glm::vec3& c) {
    const glm::vec3 e1 = b - a, e2 = c - a;
    const glm::vec3 p = glm::cross(ray.direction, e2);
    const float det = glm::dot(e1, p);
    if (std::abs(det) < 1e-12f) return std::nullopt;
    const float inv = 1.0f / det;
    const glm::vec3 s = ray.origin - a;
    const float u = glm::dot(s, p) * inv;
    if (u < 0.0f || u > 1.0f) return std::nullopt;
    const glm::vec3 q = glm::cross(s, e1);
    const float v = glm::dot(ray.direction, q) * inv;
    if (v < 0.0f || u + v > 1.0f) return std::nullopt;
    const float t = glm::dot(e2, q) * inv;
    if (t < 0.0f) return std::nullopt;
    return t;
}

namespace {

/// The nearest hit of the ray with one tree's triangles, in the ray's own parameter: the ray is
/// taken into the tree's frame (an affine map keeps the parameter).
std::optional<float> hitTree(const Ray& ray, const ViewTree& tree) {
    if (!tree.mesh || tree.mesh->empty()) return std::nullopt;
    const glm::mat4 toLocal = glm::inverse(tree.transform);
    const Ray local{glm::vec3(toLocal * glm::vec4(ray.origin, 1.0f)),
                    glm::vec3(toLocal * glm::vec4(ray.direction, 0.0f))};
    const mesh::Mesh& m = *tree.mesh;
    std::optional<float> best;
    for (std::size_t i = 0; i + 2 < m.indices.size(); i += 3) {
        const auto t = intersect(local, m.positions[m.indices[i]], m.positions[m.indices[i + 1]],
                                 m.positions[m.indices[i + 2]]);
        if (t && (!best || *t < *best)) best = t;
    }
    return best;
}

bool isHidden(const std::vector<bool>& hidden, std::size_t i) {
    return i < hidden.size() && hidden[i];
}

} // namespace

TreeHit pickTree(const Ray& ray, const std::vector<ViewTree>& trees,
                 const std::vector<Bounds>& bounds, const std::vector<bool>& hidden,
                 const std::vector<bool>& byBounds) {
    // Boxes the ray enters, nearest first: a tree beyond the best hit so far is not tested.
    std::vector<std::pair<float, std::size_t>> candidates;
    for (std::size_t i = 0; i < trees.size() && i < bounds.size(); ++i) {
        if (isHidden(hidden, i)) continue;
        if (const auto t = intersect(ray, bounds[i])) candidates.emplace_back(*t, i);
    }
    std::sort(candidates.begin(), candidates.end());
    TreeHit best;
    for (const auto& [entry, i] : candidates) {
        if (entry > best.t) break;
        if (const auto t = hitTree(ray, trees[i]); t && *t < best.t) {
            best.t = *t;
            best.index = static_cast<int>(i);
        }
    }
    if (best.index >= 0) return best;
    // No triangle hit: a tree drawn coarse (a coarser level, an impostor card) covers pixels
    // its full mesh does not; the nearest such box the ray enters is what was clicked.
    for (const auto& [entry, i] : candidates)
        if (isHidden(byBounds, i)) return {static_cast<int>(i), entry};
    return best;
}

TreeHit pickTreeBruteForce(const Ray& ray, const std::vector<ViewTree>& trees,
                           const std::vector<bool>& hidden) {
    TreeHit best;
    for (std::size_t i = 0; i < trees.size(); ++i) {
        if (isHidden(hidden, i)) continue;
        if (const auto t = hitTree(ray, trees[i]); t && *t < best.t) {
            best.t = *t;
            best.index = static_cast<int>(i);
        }
    }
    return best;
}

std::optional<glm::vec3> hitPlane(const Ray& ray, float height) {
    if (std::abs(ray.direction.y) < 1e-9f) return std::nullopt;
    const float t = (height - ray.origin.y) / ray.direction.y;
    if (t <= 0.0f) return std::nullopt;
    return ray.origin + t * ray.direction;
}

} // namespace sylva::ui
