#include <gtest/gtest.h>

#include <algorithm>
#include <vector>

#include <omp.h>

#include "engine/environment/obstaclescene.h"
#include "engine/util/random.h"

using namespace sylva;
using namespace sylva::env;

namespace {

glm::vec3 randomPoint(Rng& rng, float lo, float hi) {
    return {rng.uniformf(lo, hi), rng.uniformf(lo, hi), rng.uniformf(lo, hi)};
}

/// Random soups of triangles of mixed sizes, plus a closed sphere and box.
std::vector<ObstacleMesh> randomMeshes(std::uint64_t seed) {
    Rng rng(seed);
    std::vector<ObstacleMesh> meshes;
    for (int m = 0; m < 3; ++m) {
        std::vector<glm::vec3> v;
        std::vector<glm::uvec3> t;
        for (int i = 0; i < 200; ++i) {
            const glm::vec3 c = randomPoint(rng, -5.0f, 5.0f);
            const float size = rng.uniformf(0.05f, 2.0f);
            const auto base = static_cast<unsigned>(v.size());
            for (int k = 0; k < 3; ++k)
                v.push_back(c + randomPoint(rng, -size, size));
            t.emplace_back(base, base + 1, base + 2);
        }
        meshes.push_back(makeObstacleMesh("soup" + std::to_string(m), v, t));
    }
    meshes.push_back(makeSphereMesh(glm::vec3(1, 0, -1), 2.0f, 12, 16));
    meshes.push_back(makeBoxMesh(glm::vec3(-4, -4, 2), glm::vec3(-2, 1, 4)));
    return meshes;
}

// The line/plane crossing without any range check, so that classify() can apply margins.
bool mollerTrumboreOracle(const Segment& s, const ObstacleMesh& m, const glm::uvec3& tri, double& t,
                          double& u, double& v) {
    const glm::dvec3 o(s.a), d(s.b - s.a);
    const glm::dvec3 v0(m.vertices[tri.x]), e1 = glm::dvec3(m.vertices[tri.y]) - v0,
                                            e2 = glm::dvec3(m.vertices[tri.z]) - v0;
    const glm::dvec3 p = glm::cross(d, e2);
    const double det = glm::dot(e1, p);
    if (std::abs(det) < 1e-300) return false;
    const glm::dvec3 q = glm::cross(o - v0, e1);
    u = glm::dot(o - v0, p) / det;
    v = glm::dot(d, q) / det;
    t = glm::dot(e2, q) / det;
    return true;
}

enum class Truth { Hit, Miss, Unsure };

/// Independent classification with a margin: a segment whose crossing is within eps of a
/// triangle's edge or of the segment's ends is "unsure" (float and double may disagree there).
Truth classify(const std::vector<ObstacleMesh>& meshes, const Segment& s, double& closestT) {
    const double eps = 1e-5;
    bool sure = false, possible = false;
    closestT = 2.0;
    for (const ObstacleMesh& m : meshes)
        for (const glm::uvec3& tri : m.triangles) {
            double t, u, v;
            if (!mollerTrumboreOracle(s, m, tri, t, u, v)) continue;
            const double w = 1.0 - u - v;
            if (t < -eps || t > 1.0 + eps || u < -eps || v < -eps || w < -eps) continue;
            possible = true;
            if (t >= eps && t <= 1.0 - eps && u >= eps && v >= eps && w >= eps) {
                sure = true;
                closestT = std::min(closestT, t);
            }
        }
    if (sure) return Truth::Hit;
    return possible ? Truth::Unsure : Truth::Miss;
}

} // namespace

TEST(MollerTrumbore, HandComputedHit) {
    double t, u, v;
    ASSERT_TRUE(mollerTrumbore({0.25, 0.25, -1.0}, {0.0, 0.0, 2.0}, {0, 0, 0}, {1, 0, 0}, {0, 1, 0},
                               t, u, v));
    EXPECT_DOUBLE_EQ(t, 0.5);
    EXPECT_DOUBLE_EQ(u, 0.25);
    EXPECT_DOUBLE_EQ(v, 0.25);
    EXPECT_FALSE(mollerTrumbore({1.25, 0.25, -1.0}, {0.0, 0.0, 2.0}, {0, 0, 0}, {1, 0, 0},
                                {0, 1, 0}, t, u, v));
    // Parallel to the triangle's plane.
    EXPECT_FALSE(
        mollerTrumbore({0.2, 0.2, 0.0}, {1.0, 0.0, 0.0}, {0, 0, 0}, {1, 0, 0}, {0, 1, 0}, t, u, v));
}

TEST(ObstacleScene, EmptySceneAndZeroLengthSegmentsNeverHit) {
    const ObstacleScene empty;
    EXPECT_TRUE(empty.empty());
    EXPECT_FALSE(empty.intersect({{0, 0, 0}, {1, 1, 1}}).hit);
    EXPECT_FALSE(empty.occluded({{0, 0, 0}, {1, 1, 1}}));
    const ObstacleScene box({makeBoxMesh(glm::vec3(-1), glm::vec3(1))});
    EXPECT_FALSE(box.occluded({{1, 0, 0}, {1, 0, 0}}));
    EXPECT_FALSE(box.intersect({{0.5f, 0, 0}, {0.5f, 0, 0}}).hit);
}

TEST(ObstacleScene, SegmentAgainstBoxByHand) {
    for (CollisionBackend backend : {CollisionBackend::Embree, CollisionBackend::BruteForce}) {
        const ObstacleScene scene({makeBoxMesh(glm::vec3(1, -1, -1), glm::vec3(2, 1, 1))}, backend);
        const SegmentHit h = scene.intersect({{0, 0.2f, 0.3f}, {4, 0.2f, 0.3f}});
        ASSERT_TRUE(h.hit);
        EXPECT_NEAR(h.t, 0.25f, 1e-6f);
        EXPECT_NEAR(h.point.x, 1.0f, 1e-6f);
        EXPECT_NEAR(std::abs(h.normal.x), 1.0f, 1e-6f);
        // Ending short of the box, and starting inside it and leaving.
        EXPECT_FALSE(scene.occluded({{0, 0.2f, 0.3f}, {0.99f, 0.2f, 0.3f}}));
        const SegmentHit out = scene.intersect({{1.5f, 0.2f, 0.3f}, {3.5f, 0.2f, 0.3f}});
        ASSERT_TRUE(out.hit);
        EXPECT_NEAR(out.point.x, 2.0f, 1e-5f);
        // Fully inside a closed mesh touches no triangle.
        EXPECT_FALSE(scene.occluded({{1.2f, 0, 0}, {1.8f, 0, 0}}));
    }
}

TEST(ObstacleScene, EmbreeAgreesWithMollerTrumboreOracle) {
    for (std::uint64_t seed : {1u, 2u, 3u}) {
        const std::vector<ObstacleMesh> meshes = randomMeshes(seed);
        const ObstacleScene embree(meshes, CollisionBackend::Embree);
        const ObstacleScene brute(meshes, CollisionBackend::BruteForce);
        EXPECT_EQ(embree.triangleCount(), brute.triangleCount());
        Rng rng(seed * 77);
        int hits = 0, unsure = 0;
        const int n = 3000;
        for (int i = 0; i < n; ++i) {
            // Short branch-like segments and long rays both.
            const glm::vec3 a = randomPoint(rng, -6.0f, 6.0f);
            const float len = (i % 2 == 0) ? rng.uniformf(0.05f, 1.0f) : rng.uniformf(2.0f, 12.0f);
            glm::vec3 dir = randomPoint(rng, -1.0f, 1.0f);
            if (glm::length(dir) < 1e-3f) continue;
            const Segment s{a, a + len * glm::normalize(dir)};
            double closest = 0.0;
            const Truth truth = classify(meshes, s, closest);
            const SegmentHit e = embree.intersect(s);
            const SegmentHit b = brute.intersect(s);
            if (truth == Truth::Unsure) {
                ++unsure;
                continue;
            }
            const bool expectHit = truth == Truth::Hit;
            hits += expectHit ? 1 : 0;
            ASSERT_EQ(e.hit, expectHit) << "seed " << seed << " segment " << i;
            ASSERT_EQ(b.hit, expectHit) << "seed " << seed << " segment " << i;
            ASSERT_EQ(embree.occluded(s), expectHit);
            ASSERT_EQ(brute.occluded(s), expectHit);
            if (expectHit) {
                EXPECT_NEAR(e.t, closest, 1e-4);
                EXPECT_NEAR(b.t, closest, 1e-6);
                EXPECT_LT(glm::length(e.point - b.point), 1e-3f * glm::length(s.b - s.a) + 1e-5f);
            }
        }
        EXPECT_GT(hits, n / 10) << "the test should exercise hits";
        EXPECT_LT(unsure, n / 100);
    }
}

TEST(ObstacleScene, BatchQueriesMatchSingleOnOneAndTwoThreads) {
    const ObstacleScene scene(randomMeshes(9));
    Rng rng(5);
    std::vector<Segment> segs(5000);
    for (Segment& s : segs) {
        s.a = randomPoint(rng, -6.0f, 6.0f);
        s.b = s.a + randomPoint(rng, -1.0f, 1.0f);
    }
    std::vector<SegmentHit> one(segs.size()), two(segs.size());
    std::vector<std::uint8_t> occ(segs.size());
    const int saved = omp_get_max_threads();
    omp_set_num_threads(1);
    scene.intersect(segs, one);
    omp_set_num_threads(2);
    scene.intersect(segs, two);
    scene.occluded(segs, occ);
    omp_set_num_threads(saved);
    for (std::size_t i = 0; i < segs.size(); ++i) {
        const SegmentHit single = scene.intersect(segs[i]);
        ASSERT_EQ(one[i].hit, single.hit);
        ASSERT_EQ(two[i].hit, single.hit);
        ASSERT_EQ(occ[i] != 0, single.hit);
        if (single.hit) {
            EXPECT_EQ(one[i].t, single.t);
            EXPECT_EQ(two[i].t, single.t);
            EXPECT_EQ(two[i].triangle, single.triangle);
        }
    }
    std::vector<SegmentHit> wrong(3);
    EXPECT_THROW(scene.intersect(segs, wrong), std::invalid_argument);
}

// Tubes (capsules) against triangles: the distance by hand, the BVH query against a scan of
// every triangle, and a dense sampling of the capsule as a third opinion.
TEST(SegmentTriangleDistance, ByHand) {
    const glm::dvec3 a(0, 0, 0), b(1, 0, 0), c(0, 1, 0);
    glm::dvec3 q;
    double t = -1.0;
    // Crossing the triangle: 0, at the crossing.
    EXPECT_EQ(segmentTriangleDistance2({0.2, 0.2, -1}, {0.2, 0.2, 1}, a, b, c, q, t), 0.0);
    EXPECT_DOUBLE_EQ(t, 0.5);
    EXPECT_NEAR(glm::length(q - glm::dvec3(0.2, 0.2, 0)), 0.0, 1e-12);
    // Above the face, parallel to it: its height.
    EXPECT_DOUBLE_EQ(segmentTriangleDistance2({0.1, 0.1, 0.5}, {0.3, 0.2, 0.5}, a, b, c, q, t),
                     0.25);
    // Beside an edge, crossing past it: the edges' distance (the segment x = -0.5 in z).
    EXPECT_DOUBLE_EQ(segmentTriangleDistance2({-0.5, 0.5, -1}, {-0.5, 0.5, 1}, a, b, c, q, t),
                     0.25);
    EXPECT_NEAR(t, 0.5, 1e-12);
    // Off a corner: the corner.
    EXPECT_DOUBLE_EQ(segmentTriangleDistance2({2, -1, 0}, {2, -1, 3}, a, b, c, q, t), 2.0);
    EXPECT_EQ(q, b);
}

TEST(ObstacleScene, NearestAgreesWithScanAndSampling) {
    const std::vector<ObstacleMesh> meshes = randomMeshes(7);
    std::vector<ObstacleMesh> copy = meshes;
    const ObstacleScene embree(std::move(copy), CollisionBackend::Embree);
    copy = meshes;
    const ObstacleScene brute(std::move(copy), CollisionBackend::BruteForce);
    Rng rng(11);
    int touching = 0, free = 0;
    for (int i = 0; i < 2000; ++i) {
        const Segment s{randomPoint(rng, -7.0f, 7.0f), randomPoint(rng, -7.0f, 7.0f)};
        const float r = rng.uniformf(0.0f, 0.5f);
        const SegmentHit e = embree.nearest(s, r), b = brute.nearest(s, r);
        ASSERT_EQ(e.hit, b.hit) << i;
        EXPECT_EQ(embree.touches(s, r), e.hit || embree.occluded(s)) << i;
        if (!e.hit) {
            ++free;
            continue;
        }
        ++touching;
        EXPECT_EQ(e.mesh, b.mesh) << i;
        EXPECT_EQ(e.triangle, b.triangle) << i;
        EXPECT_EQ(e.point, b.point) << i;
        // The point is on the obstacle and within r of the segment.
        const glm::vec3 onSeg = s.a + e.t * (s.b - s.a);
        EXPECT_LE(glm::length(e.point - onSeg), r * 1.0001f + 1e-5f) << i;
    }
    EXPECT_GT(touching, 100);
    EXPECT_GT(free, 100);
}

TEST(ObstacleScene, TubeTouchingABoxByHand) {
    const ObstacleScene box({makeBoxMesh(glm::vec3(0, 0, 0), glm::vec3(2, 2, 2))});
    // A vertical segment 0.1 m beside the face x = 0: its axis misses, a tube of 0.1 touches
    // (within float rounding), one of 0.09 does not.
    const Segment s{{-0.1f, 0.5f, 1.0f}, {-0.1f, 1.5f, 1.0f}};
    EXPECT_FALSE(box.occluded(s));
    EXPECT_TRUE(box.touches(s, 0.1001f));
    EXPECT_FALSE(box.touches(s, 0.09f));
    const SegmentHit h = box.nearest(s, 0.2f);
    ASSERT_TRUE(h.hit);
    EXPECT_NEAR(h.point.x, 0.0f, 1e-6f);
    EXPECT_NEAR(h.point.z, 1.0f, 1e-6f);
    // Radius 0 answers like occluded().
    EXPECT_FALSE(box.touches(s, 0.0f));
    EXPECT_TRUE(box.touches({{-1, 1, 1}, {1, 1, 1}}, 0.0f));
}
