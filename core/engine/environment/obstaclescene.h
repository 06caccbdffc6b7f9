#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>
#include <span>
#include <vector>

#include <glm/glm.hpp>

#include "engine/environment/obstaclemesh.h"

namespace sylva::env {

/// A straight segment from a to b (a branch, a ray down to the ground), world space, metres.
struct Segment {
    glm::vec3 a{0.0f};
    glm::vec3 b{0.0f};
};

/// The first obstacle surface a segment meets, counted from its start.
struct SegmentHit {
    bool hit = false;
    float t = 0.0f;             ///< fraction of the segment, 0 at a, 1 at b
    glm::vec3 point{0.0f};      ///< a + t (b - a)
    glm::vec3 normal{0.0f};     ///< unit geometric normal of the triangle (either side)
    std::uint32_t mesh = 0;     ///< index into ObstacleScene::meshes()
    std::uint32_t triangle = 0; ///< index into that mesh's triangles
};

/// Which algorithm answers queries. Both give the same answers (up to floating-point ties on
/// triangle edges); BruteForce is the Möller–Trumbore oracle kept for tests and benchmarks.
enum class CollisionBackend { Embree, BruteForce };

/// Two-sided Möller–Trumbore ray/triangle test in double precision: true when the line
/// orig + t·dir crosses the triangle, with \p t and the barycentrics \p u, \p v (hit =
/// (1-u-v)·v0 + u·v1 + v·v2). The caller restricts t (0..1 for a segment with dir = b - a).
bool mollerTrumbore(const glm::dvec3& orig, const glm::dvec3& dir, const glm::dvec3& v0,
                    const glm::dvec3& v1, const glm::dvec3& v2, double& t, double& u, double& v);

/// Squared distance between the segment [p0, p1] and the triangle (v0, v1, v2), in double
/// precision: 0 when the segment crosses the triangle, otherwise the least of the endpoints'
/// distances to the triangle and the segment's distances to the triangle's edges. The closest
/// point on the triangle is written to \p onTriangle and the segment's parameter (0 at p0) to
/// \p t.
double segmentTriangleDistance2(const glm::dvec3& p0, const glm::dvec3& p1, const glm::dvec3& v0,
                                const glm::dvec3& v1, const glm::dvec3& v2, glm::dvec3& onTriangle,
                                double& t);

/// The static obstacles of a scene with an acceleration structure built once (an Embree BVH).
/// Immutable after construction; every query is const and safe to call from many threads.
class ObstacleScene {
public:
    /// An empty scene: every query misses.
    ObstacleScene();
    /// Builds the scene over \p meshes (empty meshes are allowed and ignored).
    explicit ObstacleScene(std::vector<ObstacleMesh> meshes,
                           CollisionBackend backend = CollisionBackend::Embree);
    ~ObstacleScene();
    ObstacleScene(ObstacleScene&&) noexcept;
    ObstacleScene& operator=(ObstacleScene&&) noexcept;
    ObstacleScene(const ObstacleScene&) = delete;
    ObstacleScene& operator=(const ObstacleScene&) = delete;

    CollisionBackend backend() const;
    const std::vector<ObstacleMesh>& meshes() const;
    std::size_t triangleCount() const;
    /// Sum of the meshes' dropped degenerate triangles.
    std::size_t degenerateCount() const;
    bool empty() const { return triangleCount() == 0; }
    /// Bounds of all triangles; lo > hi when empty.
    glm::vec3 lo() const;
    glm::vec3 hi() const;
    /// True when the box [lo, hi] overlaps the bounds of some mesh (a cheap early-out).
    bool overlapsBounds(const glm::vec3& lo, const glm::vec3& hi) const;

    /// The first hit along the segment (closest to a); hit == false when none. A zero-length
    /// segment never hits.
    SegmentHit intersect(const Segment& s) const;
    /// Whether the segment touches any triangle (cheaper than intersect()).
    bool occluded(const Segment& s) const;
    /// The obstacle point closest to the segment among the triangles within \p radius of it
    /// (metres, >= 0): whether a tube (a capsule) of that radius around the segment touches an
    /// obstacle. hit == false when none; otherwise point is on the triangle, t the segment's
    /// parameter of the closest approach and normal the triangle's. With radius 0 it answers
    /// like occluded() (up to floating-point ties on edges). Branch tubes and trunks use it so
    /// that bark, not only the branch axis, stays out of obstacles.
    SegmentHit nearest(const Segment& s, float radius) const;
    /// Whether a tube of \p radius around the segment touches any triangle: occluded(s) or
    /// nearest(s, radius).hit.
    bool touches(const Segment& s, float radius) const;
    /// touches() for many segments with one radius each; \p out[i] is 1 when segment i touches.
    void touches(std::span<const Segment> segments, std::span<const float> radii,
                 std::span<std::uint8_t> out) const;
    /// intersect() for many segments, in parallel (OpenMP) when called outside a parallel
    /// region; \p out must have segments.size() entries. Results do not depend on threads.
    void intersect(std::span<const Segment> segments, std::span<SegmentHit> out) const;
    /// occluded() for many segments; \p out[i] is 1 when segment i hits.
    void occluded(std::span<const Segment> segments, std::span<std::uint8_t> out) const;
    /// The three world-space corners of a triangle named by a hit.
    void triangle(std::uint32_t mesh, std::uint32_t triangle, glm::vec3& v0, glm::vec3& v1,
                  glm::vec3& v2) const;

private:
    struct Impl;
    std::unique_ptr<Impl> mImpl;
};

} // namespace sylva::env
