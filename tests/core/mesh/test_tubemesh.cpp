#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include <omp.h>

#include "../common/testwords.h"
#include "engine/lsystem/turtle.h"
#include "engine/mesh/leafcards.h"
#include "engine/mesh/tubemesh.h"
#include "engine/util/error.h"
#include "engine/util/random.h"
#include "referencetubemesh.h"

using namespace sylva;
using sylva::testing::makeWord;

namespace {

skel::Skeleton tree(const std::string& text) {
    return lsys::interpret(makeWord(text), lsys::TurtleSettings{});
}

skel::Skeleton bigTree() {
    lsys::TurtleSettings t;
    t.angleDegrees = 30;
    t.step = 0.5;
    t.width = 0.3;
    return lsys::interpret(makeWord(sylva::testing::testTreeWord(4)), t);
}

// Oracle checks shared by several tests: finite unit normals, no degenerate triangles, and every
// triangle's winding agrees with its vertex normals (outward faces).
void checkWellFormed(const mesh::Mesh& m) {
    ASSERT_EQ(m.normals.size(), m.positions.size());
    ASSERT_EQ(m.uvs.size(), m.positions.size());
    for (const glm::vec3& n : m.normals) {
        ASSERT_TRUE(std::isfinite(n.x) && std::isfinite(n.y) && std::isfinite(n.z));
        ASSERT_NEAR(glm::length(n), 1.0f, 1e-3f);
    }
    for (std::size_t t = 0; t < m.indices.size(); t += 3) {
        const std::uint32_t a = m.indices[t], b = m.indices[t + 1], c = m.indices[t + 2];
        ASSERT_LT(std::max({a, b, c}), m.positions.size());
        const glm::vec3 cr =
            glm::cross(m.positions[b] - m.positions[a], m.positions[c] - m.positions[a]);
        const float area = 0.5f * glm::length(cr);
        ASSERT_GT(area, 1e-12f) << "degenerate triangle " << t / 3;
        const glm::vec3 ns = m.normals[a] + m.normals[b] + m.normals[c];
        ASSERT_GT(glm::dot(cr, ns), 0.0f) << "triangle " << t / 3 << " faces inwards";
    }
}

} // namespace

TEST(TubeMesh, CountsOfAStraightBranch) {
    const auto s = tree("FF");
    mesh::TubeSettings settings;
    settings.caps = false;
    const auto m = mesh::buildTubeMesh(s, settings);
    EXPECT_EQ(m.vertexCount(), 3u * 9u);
    EXPECT_EQ(m.triangleCount(), 2u * 8u * 2u);
    settings.caps = true;
    const auto c = mesh::buildTubeMesh(s, settings);
    EXPECT_EQ(c.vertexCount(), 3u * 9u + 2u * 10u);
    EXPECT_EQ(c.triangleCount(), 2u * 8u * 2u + 2u * 8u);
    ASSERT_EQ(c.submeshes.size(), 1u);
    EXPECT_EQ(c.submeshes[0].material, "bark");
    EXPECT_EQ(c.submeshes[0].indexCount, c.indices.size());
    checkWellFormed(c);
}

// The limit on tube mesh triangles (kMaxTubeTriangles, 100 million): checked from the counts
// before any memory is spent; FF without caps is 32 triangles.
TEST(TubeMesh, TriangleLimit) {
    EXPECT_EQ(mesh::TubeSettings{}.maxTriangles, mesh::kMaxTubeTriangles);
    EXPECT_EQ(mesh::kMaxTubeTriangles, 100'000'000u);
    const auto s = tree("FF");
    mesh::TubeSettings settings;
    settings.caps = false;
    settings.maxTriangles = 32;
    EXPECT_EQ(mesh::buildTubeMesh(s, settings).triangleCount(), 32u);
    settings.maxTriangles = 31;
    mesh::Mesh out;
    try {
        mesh::appendTubes(out, s, settings);
        FAIL() << "expected LimitExceeded";
    } catch (const LimitExceeded& e) {
        EXPECT_STREQ(e.what(), "tube mesh would have 32 triangles, more than the limit of 31; "
                               "lower the tube_mesh resolution or grow a smaller tree (fewer "
                               "generations, cycles or attractors)");
    }
    EXPECT_TRUE(out.positions.empty());
}

TEST(TubeMesh, RingsLieAtTheRadius) {
    const auto s = tree("F!(0.06)F");
    mesh::TubeSettings settings;
    settings.caps = false;
    settings.resolution = 5;
    const auto m = mesh::buildTubeMesh(s, settings);
    ASSERT_EQ(m.vertexCount(), 18u);
    for (std::size_t k = 0; k < 3; ++k)
        for (std::size_t j = 0; j < 6; ++j) {
            const glm::vec3 d = m.positions[k * 6 + j] - s.position[k];
            EXPECT_NEAR(d.y, 0.0f, 1e-6f);
            EXPECT_NEAR(glm::length(d), s.radius[k], 1e-6f);
        }
    // u around (seam duplicated), v = length / circumference with the average radius.
    EXPECT_FLOAT_EQ(m.uvs[0].x, 0.0f);
    EXPECT_FLOAT_EQ(m.uvs[5].x, 1.0f);
    EXPECT_EQ(m.positions[0], m.positions[5]);
    const float v1 = 1.0f / (2.0f * std::numbers::pi_v<float> * 0.05f);
    const float v2 = v1 + 1.0f / (2.0f * std::numbers::pi_v<float> * 0.5f * (0.05f + 0.03f));
    EXPECT_NEAR(m.uvs[6].y, v1, 1e-4f);
    EXPECT_NEAR(m.uvs[12].y, v2, 1e-4f);
    checkWellFormed(m);
}

// bark_texture_width: an axis gets the texture round(circumference / width) times around and
// as often along, so its features keep their size in metres; an axis too thin for two widths,
// and width 0, keep the texture once around (the same bytes).
TEST(TubeMesh, BarkTextureWidthTilesThickAxes) {
    const auto s = tree("F!(0.06)F");
    mesh::TubeSettings settings;
    settings.caps = false;
    settings.resolution = 5;
    const auto once = mesh::buildTubeMesh(s, settings);
    settings.barkTextureWidth = 0.1; // the base's circumference 2π·0.05 = 0.314 m: 3 widths
    const auto tiled = mesh::buildTubeMesh(s, settings);
    ASSERT_EQ(tiled.vertexCount(), once.vertexCount());
    EXPECT_EQ(tiled.positions, once.positions);
    for (std::size_t v = 0; v < once.vertexCount(); ++v) {
        EXPECT_NEAR(tiled.uvs[v].x, 3.0f * once.uvs[v].x, 1e-6f) << v;
        EXPECT_NEAR(tiled.uvs[v].y, 3.0f * once.uvs[v].y, 1e-5f) << v;
    }
    EXPECT_FLOAT_EQ(tiled.uvs[5].x, 3.0f); // the seam: whole tiles, no jump in the texture
    settings.barkTextureWidth = 0.5;       // 0.63 widths: once around
    EXPECT_EQ(mesh::buildTubeMesh(s, settings).uvs, once.uvs);
    settings.barkTextureWidth = -0.1;
    try {
        mesh::buildTubeMesh(s, settings);
        FAIL() << "a negative width was accepted";
    } catch (const InvalidInput& e) {
        EXPECT_NE(std::string(e.what()).find("bark_texture_width"), std::string::npos) << e.what();
        EXPECT_NE(std::string(e.what()).find("[0, 10]"), std::string::npos) << e.what();
    }
}

TEST(TubeMesh, PlanarBendDoesNotTwist) {
    // Yaw turns keep the turtle's up (+Z); a rotation-minimizing frame started on +Z stays there.
    const auto s = tree("F+(30)F+(30)F-(50)F+(80)F");
    mesh::TubeSettings settings;
    settings.caps = false;
    const auto m = mesh::buildTubeMesh(s, settings);
    ASSERT_EQ(m.vertexCount(), s.size() * 9u);
    for (std::size_t k = 0; k < s.size(); ++k) {
        const glm::vec3 d = glm::normalize(m.positions[k * 9] - s.position[k]);
        EXPECT_NEAR(d.z, 1.0f, 1e-5f) << "ring " << k;
    }
    checkWellFormed(m);
}

TEST(TubeMesh, FramesAreRotationMinimizingIn3D) {
    // A gently spiralling branch: consecutive ring frames differ only by the rotation taking one
    // tangent to the next (the oracle), up to the discretisation error of double reflection.
    std::string text = "F";
    for (int i = 0; i < 40; ++i)
        text += "+(7)&(5)/(11)F";
    const auto s = tree(text);
    mesh::TubeSettings settings;
    settings.caps = false;
    const auto m = mesh::buildTubeMesh(s, settings);
    const std::size_t rv = 9;
    ASSERT_EQ(m.vertexCount(), s.size() * rv);
    auto tangent = [&](std::size_t k) {
        return glm::normalize(glm::cross(m.positions[k * rv] - s.position[k],
                                         m.positions[k * rv + 2] - s.position[k]));
    };
    for (std::size_t k = 1; k < s.size(); ++k) {
        const glm::vec3 t0 = tangent(k - 1), t1 = tangent(k);
        const glm::vec3 n0 = glm::normalize(m.positions[(k - 1) * rv] - s.position[k - 1]);
        const glm::vec3 n1 = glm::normalize(m.positions[k * rv] - s.position[k]);
        const glm::vec3 axis = glm::cross(t0, t1);
        glm::vec3 expected = n0;
        if (glm::length(axis) > 1e-7f) {
            const float angle = std::atan2(glm::length(axis), glm::dot(t0, t1));
            expected = glm::angleAxis(angle, glm::normalize(axis)) * n0;
        }
        EXPECT_GT(glm::dot(expected, n1), std::cos(0.01f)) << "ring " << k;
    }
    checkWellFormed(m);
}

TEST(TubeMesh, LateralBaseRingSitsInsideParent) {
    const auto s = bigTree();
    mesh::TubeSettings settings;
    settings.windAttributes = true;
    settings.resolution = 6;
    const auto m = mesh::buildTubeMesh(s, settings);
    checkWellFormed(m);
    ASSERT_EQ(m.branchOrder.size(), m.vertexCount());
    std::size_t forks = 0;
    for (std::size_t j = 0; j < s.size(); ++j) {
        const std::int32_t p = s.parent[j];
        if (p < 0 || s.order[j] == s.order[static_cast<std::size_t>(p)]) continue;
        ++forks;
        const glm::vec3 fork = s.position[static_cast<std::size_t>(p)];
        const float rp = s.radius[static_cast<std::size_t>(p)];
        // The res+1 vertices of the child's order nearest to the fork form its base ring.
        std::vector<float> dist;
        for (std::size_t v = 0; v < m.vertexCount(); ++v)
            if (m.branchOrder[v] == s.order[j]) dist.push_back(glm::length(m.positions[v] - fork));
        std::partial_sort(dist.begin(), dist.begin() + 7, dist.end());
        for (int i = 0; i < 7; ++i)
            EXPECT_LE(dist[static_cast<std::size_t>(i)], rp * 1.0001f) << "fork at node " << p;
    }
    EXPECT_GT(forks, 10u);
}

TEST(TubeMesh, BranchingThickness) {
    const auto s = tree("F[+F]F");
    mesh::TubeSettings settings;
    settings.thickness = mesh::ThicknessMode::Branching;
    settings.initialThickness = 0.4;
    settings.thicknessMultiplier = 0.5;
    const auto r = mesh::tubeRadii(s, settings);
    ASSERT_EQ(r.size(), 4u);
    EXPECT_FLOAT_EQ(r[0], 0.2f);
    EXPECT_FLOAT_EQ(r[1], 0.2f);
    EXPECT_FLOAT_EQ(r[2], 0.1f); // one branching point below
    EXPECT_FLOAT_EQ(r[3], 0.1f);
}

TEST(TubeMesh, MinBranchRadiusDropsThinLaterals) {
    const auto s = tree("F[+!(0.02)F[-F]]F");
    mesh::TubeSettings settings;
    settings.caps = false;
    const auto all = mesh::buildTubeMesh(s, settings);
    settings.minBranchRadius = 0.02;
    const auto trunk = mesh::buildTubeMesh(s, settings);
    EXPECT_EQ(all.vertexCount(), (3u + 2u + 2u) * 9u);
    EXPECT_EQ(trunk.vertexCount(), 3u * 9u);
}

TEST(TubeMesh, HiddenNodesAreSkipped) {
    auto s = tree("F[+F]F");
    s.flags[2] |= skel::kHidden;
    mesh::TubeSettings settings;
    settings.caps = false;
    EXPECT_EQ(mesh::buildTubeMesh(s, settings).vertexCount(), 3u * 9u);
}

TEST(TubeMesh, SameOnOneAndTwoThreads) {
    const auto s = bigTree();
    mesh::TubeSettings settings;
    settings.windAttributes = true;
    const int saved = omp_get_max_threads();
    omp_set_num_threads(1);
    const auto a = mesh::buildTubeMesh(s, settings);
    omp_set_num_threads(2);
    const auto b = mesh::buildTubeMesh(s, settings);
    omp_set_num_threads(saved);
    EXPECT_EQ(a.positions, b.positions);
    EXPECT_EQ(a.normals, b.normals);
    EXPECT_EQ(a.uvs, b.uvs);
    EXPECT_EQ(a.indices, b.indices);
    EXPECT_EQ(a.flexibility, b.flexibility);
}

// Room reserved past the bark (for a tree's leaf cards) changes no output, and is there.
TEST(TubeMesh, RoomReservedForTheCardsChangesNothing) {
    const auto s = bigTree();
    mesh::TubeSettings settings;
    settings.windAttributes = true;
    settings.nodeIds = true;
    settings.barkColorBottom = 0.0;
    settings.barkColorTop = 2.0;
    const auto plain = mesh::buildTubeMesh(s, settings);
    settings.reserveVertices = 1000;
    settings.reserveIndices = 1500;
    const auto roomy = mesh::buildTubeMesh(s, settings);
    EXPECT_EQ(roomy.positions, plain.positions);
    EXPECT_EQ(roomy.normals, plain.normals);
    EXPECT_EQ(roomy.uvs, plain.uvs);
    EXPECT_EQ(roomy.indices, plain.indices);
    EXPECT_EQ(roomy.branchOrder, plain.branchOrder);
    EXPECT_EQ(roomy.flexibility, plain.flexibility);
    EXPECT_EQ(roomy.node, plain.node);
    EXPECT_EQ(roomy.colors, plain.colors);
    ASSERT_FALSE(roomy.colors.empty());
    const std::size_t v = roomy.positions.size() + 1000;
    for (std::size_t capacity :
         {roomy.positions.capacity(), roomy.normals.capacity(), roomy.uvs.capacity(),
          roomy.branchOrder.capacity(), roomy.flexibility.capacity(), roomy.node.capacity(),
          roomy.colors.capacity()})
        EXPECT_GE(capacity, v);
    EXPECT_GE(roomy.indices.capacity(), roomy.indices.size() + 1500);
}

TEST(TubeMesh, ZeroLengthAndZeroWidthSegmentsStayWellFormed) {
    const auto s = tree("FF(0)F!(0)F[+F(0)]");
    const auto m = mesh::buildTubeMesh(s, mesh::TubeSettings{});
    checkWellFormed(m);
}

TEST(TubeMesh, RejectsBadResolution) {
    const auto s = tree("F");
    mesh::TubeSettings settings;
    settings.resolution = 2;
    try {
        mesh::buildTubeMesh(s, settings);
        FAIL();
    } catch (const InvalidInput& e) {
        EXPECT_NE(std::string(e.what()).find("[3, 64]"), std::string::npos) << e.what();
    }
}

// Oracle: the first, straightforward mesher (resize + write at offsets) gives the same bytes as
// the optimized one (scratch blocks appended in order; round rings' vertices three lanes at once
// with SSE2, Writer::ring), on one and two threads, with and
// without caps, wind attributes, twig dropping, and when appending to a mesh that has vertices
// but no normals yet.
TEST(TubeMesh, SameBytesAsStraightforwardMesher) {
    lsys::TurtleSettings t;
    t.angleDegrees = 30;
    t.step = 0.5;
    t.width = 0.3;
    const auto s = lsys::interpret(makeWord(sylva::testing::testTreeWord(6)), t);
    const int saved = omp_get_max_threads();
    for (int threads : {1, 2})
        for (int variant = 0; variant < 4; ++variant) {
            omp_set_num_threads(threads);
            mesh::TubeSettings settings;
            settings.resolution = variant == 3 ? 5 : 8;
            settings.caps = variant != 1;
            settings.windAttributes = variant == 2;
            settings.minBranchRadius = variant == 3 ? 0.02 : 0.0;
            mesh::Mesh a, b;
            if (variant == 1) {
                a.positions.push_back({1, 2, 3});
                a.indices = {0, 0, 0};
                b = a;
            }
            mesh::appendTubes(a, s, settings);
            mesh::reference::appendTubesReference(b, s, settings);
            const std::string what =
                "threads " + std::to_string(threads) + " variant " + std::to_string(variant);
            ASSERT_GT(a.vertexCount(), 2u * 4096u) << what; // several scratch runs
            EXPECT_EQ(a.positions, b.positions) << what;
            EXPECT_EQ(a.normals, b.normals) << what;
            EXPECT_EQ(a.uvs, b.uvs) << what;
            EXPECT_EQ(a.indices, b.indices) << what;
            EXPECT_EQ(a.branchOrder, b.branchOrder) << what;
            EXPECT_EQ(a.flexibility, b.flexibility) << what;
            ASSERT_EQ(a.submeshes.size(), b.submeshes.size()) << what;
            for (std::size_t k = 0; k < a.submeshes.size(); ++k) {
                EXPECT_EQ(a.submeshes[k].material, b.submeshes[k].material) << what;
                EXPECT_EQ(a.submeshes[k].firstIndex, b.submeshes[k].firstIndex) << what;
                EXPECT_EQ(a.submeshes[k].indexCount, b.submeshes[k].indexCount) << what;
            }
        }
    omp_set_num_threads(saved);
}

// A random bush: many short axes (a node's first child of its order continues the axis, the
// others start laterals), some segments of zero length, some hidden nodes.
skel::Skeleton shortAxes(std::uint64_t seed, int nodes) {
    skel::Skeleton s;
    Rng rng(seed);
    s.addNode({0, 0, 0}, -1, 0.05f, 0, glm::quat(1, 0, 0, 0));
    for (int i = 1; i < nodes; ++i) {
        const auto par = static_cast<std::int32_t>(rng.below(static_cast<std::uint64_t>(i)));
        glm::vec3 step(rng.uniformf(-0.4f, 0.4f), rng.uniformf(-0.4f, 0.4f),
                       rng.uniformf(-0.4f, 0.4f));
        if (rng.below(15) == 0) step = glm::vec3(0.0f);
        const glm::quat frame = glm::normalize(glm::quat(rng.uniformf(-1, 1), rng.uniformf(-1, 1),
                                                         rng.uniformf(-1, 1), rng.uniformf(-1, 1)));
        s.addNode(s.position[static_cast<std::size_t>(par)] + step, par,
                  rng.uniformf(0.002f, 0.04f), static_cast<std::uint16_t>(rng.below(3)), frame,
                  static_cast<std::uint8_t>(rng.below(25) == 0 ? skel::kHidden : 0));
    }
    s.finalize();
    return s;
}

// The meshing of a run's chains in two passes (every chain's ring frames, then the rings) on
// axes of one to a few segments, where each chain's frames start at its own place.
TEST(TubeMesh, SameBytesAsStraightforwardMesherOnShortAxes) {
    for (std::uint64_t seed = 1; seed <= 3; ++seed) {
        const skel::Skeleton s = shortAxes(seed, 2500);
        mesh::TubeSettings settings;
        settings.resolution = seed == 2 ? 5 : 8;
        settings.caps = seed != 3;
        mesh::Mesh a, b;
        mesh::appendTubes(a, s, settings);
        mesh::reference::appendTubesReference(b, s, settings);
        ASSERT_GT(a.vertexCount(), 2u * 4096u) << "seed " << seed; // several scratch runs
        EXPECT_EQ(a.positions, b.positions) << "seed " << seed;
        EXPECT_EQ(a.normals, b.normals) << "seed " << seed;
        EXPECT_EQ(a.uvs, b.uvs) << "seed " << seed;
        EXPECT_EQ(a.indices, b.indices) << "seed " << seed;
    }
}

TEST(TubeMesh, NodeIdsNameTheNodeOfEveryVertex) {
    // F F [ + F F ]: trunk nodes 0, 1, 2; the lateral's nodes 3, 4 start at node 2.
    const auto s = tree("FF[+FF]");
    ASSERT_EQ(s.size(), 5u);
    ASSERT_EQ(s.parent[3], 2);
    mesh::TubeSettings settings;
    settings.resolution = 5;
    const auto plain = mesh::buildTubeMesh(s, settings);
    EXPECT_TRUE(plain.node.empty()) << "node ids only on request";
    settings.nodeIds = true;
    const auto m = mesh::buildTubeMesh(s, settings);
    ASSERT_EQ(m.node.size(), m.positions.size());
    EXPECT_EQ(m.positions, plain.positions) << "asking for node ids changes no geometry";
    EXPECT_EQ(m.indices, plain.indices);
    const auto r = mesh::tubeRadii(s, settings);
    std::vector<int> perNode(s.size(), 0);
    for (std::size_t v = 0; v < m.node.size(); ++v) {
        const std::uint32_t n = m.node[v];
        ASSERT_LT(n, s.size()) << "vertex " << v;
        ++perNode[n];
        // Ring vertices lie at their node's radius from it, cap centres on it; the lateral's
        // base ring lies around its parent node 2 (radius clamped to the parent's) but belongs
        // to the lateral's first node 3.
        const float d = glm::distance(m.positions[v], s.position[n]);
        const float dParent = glm::distance(m.positions[v], s.position[2]);
        const bool onOwn = d < 1e-5f || std::abs(d - r[n]) < 1e-4f;
        const bool baseRing = n == 3 && std::abs(dParent - std::min(r[2], r[3])) < 1e-4f;
        EXPECT_TRUE(onOwn || baseRing)
            << "vertex " << v << " of node " << n << " lies " << d << " from it";
    }
    // A ring of 6 vertices per node, plus the lateral's base ring on node 3 and the caps
    // (6 + centre) of the root 0 and the chain ends 2 and 4.
    EXPECT_EQ(perNode[0], 6 + 7);
    EXPECT_EQ(perNode[1], 6);
    EXPECT_EQ(perNode[2], 6 + 7);
    EXPECT_EQ(perNode[3], 6 + 6);
    EXPECT_EQ(perNode[4], 6 + 7);

    // Leaf cards take their leaf's node when the mesh carries node ids.
    std::vector<skel::Leaf> leaves(2);
    leaves[0].node = 4;
    leaves[0].size = 0.1f;
    leaves[1].node = -1;
    leaves[1].size = 0.1f;
    mesh::Mesh withLeaves = m;
    mesh::appendLeafCards(withLeaves, leaves, {});
    ASSERT_EQ(withLeaves.node.size(), withLeaves.positions.size());
    for (std::size_t c = 0; c < 4; ++c) {
        EXPECT_EQ(withLeaves.node[m.node.size() + c], 4u);
        EXPECT_EQ(withLeaves.node[m.node.size() + 4 + c], mesh::Mesh::kNoNode);
    }
}

namespace {

/// Distance from \p p to the polyline \p line.
float distanceToPolyline(const glm::vec3& p, const std::vector<glm::vec3>& line) {
    float best = 1e30f;
    for (std::size_t k = 0; k + 1 < line.size(); ++k) {
        const glm::vec3 a = line[k], d = line[k + 1] - a;
        const float t = std::clamp(glm::dot(p - a, d) / glm::dot(d, d), 0.0f, 1.0f);
        best = std::min(best, glm::length(a + t * d - p));
    }
    return best;
}

} // namespace

TEST(TubeMesh, SimplifiedAxesStayWithinTheTolerance) {
    // A quarter circle of 60 nodes (radius 3 m) and a straight run of 20.
    skel::Skeleton s;
    const glm::quat up(1, 0, 0, 0);
    s.addNode({0, 0, 0}, -1, 0.05f, 0, up);
    for (int i = 1; i <= 20; ++i)
        s.addNode({0, 0.1f * static_cast<float>(i), 0}, i - 1, 0.05f, 0, up);
    for (int i = 1; i <= 60; ++i) {
        const float a = static_cast<float>(i) / 60.0f * std::numbers::pi_v<float> / 2.0f;
        s.addNode({3.0f - 3.0f * std::cos(a), 2.0f + 3.0f * std::sin(a), 0}, 19 + i, 0.05f, 0, up);
    }
    s.finalize();
    mesh::TubeSettings settings;
    settings.caps = false;
    const std::size_t ringVerts = static_cast<std::size_t>(settings.resolution) + 1;
    EXPECT_EQ(mesh::buildTubeMesh(s, settings).vertexCount(), s.size() * ringVerts);
    for (double tol : {0.001, 0.01, 0.05}) {
        settings.simplifyTolerance = tol;
        const mesh::Mesh m = mesh::buildTubeMesh(s, settings);
        ASSERT_EQ(m.vertexCount() % ringVerts, 0u);
        std::vector<glm::vec3> centres;
        for (std::size_t r = 0; r < m.vertexCount() / ringVerts; ++r) {
            glm::vec3 c(0.0f);
            for (std::size_t j = 0; j < ringVerts - 1; ++j)
                c += m.positions[r * ringVerts + j];
            centres.push_back(c / static_cast<float>(ringVerts - 1));
        }
        EXPECT_LT(centres.size(), tol >= 0.01 ? s.size() / 4 : s.size()) << tol;
        EXPECT_LT(glm::length(centres.front() - s.position.front()), 1e-5f);
        EXPECT_LT(glm::length(centres.back() - s.position.back()), 1e-5f);
        for (const glm::vec3& p : s.position)
            EXPECT_LE(distanceToPolyline(p, centres), static_cast<float>(tol) + 1e-5f) << tol;
    }
}

TEST(TubeMesh, ThinAxesBecomeRibbonsFacingTheCamera) {
    skel::Skeleton s;
    const glm::quat up(1, 0, 0, 0);
    s.addNode({0, 0, 0}, -1, 0.2f, 0, up);
    s.addNode({0, 2, 0}, 0, 0.15f, 0, up);
    s.addNode({0, 4, 0}, 1, 0.1f, 0, up);
    s.addNode({1, 2.5f, 0}, 1, 0.01f, 1, up);
    s.addNode({2, 3, 0}, 3, 0.008f, 1, up);
    s.finalize();
    mesh::TubeSettings settings;
    settings.caps = false;
    settings.ribbonBelowRadius = 0.05;
    settings.ribbonCamera = {0.5f, 3, 20};
    settings.ribbonWidthScale = 0.9;
    settings.nodeIds = true;
    // The ribbon faces one camera only: the mesh says so, so that viewers keep it two-sided
    // (the viewport culls the back faces of closed tubes alone).
    settings.ribbonBelowRadius = 0.005;
    EXPECT_FALSE(mesh::buildTubeMesh(s, settings).cameraRibbons);
    settings.ribbonBelowRadius = 0.05;
    const mesh::Mesh m = mesh::buildTubeMesh(s, settings);
    EXPECT_TRUE(m.cameraRibbons);
    // The trunk: three rings of 9; the lateral: its base at the fork and two nodes, 2 each.
    ASSERT_EQ(m.vertexCount(), 3u * 9u + 3u * 2u);
    EXPECT_EQ(m.triangleCount(), 2u * 16u + 2u * 2u);
    for (std::size_t v = 27; v < m.vertexCount(); v += 2) {
        const glm::vec3 mid = 0.5f * (m.positions[v] + m.positions[v + 1]);
        const std::uint32_t node = m.node[v];
        EXPECT_GT(glm::dot(m.normals[v], settings.ribbonCamera - mid), 0.0f);
        // As wide as 2 r · scale, at right angles to the view.
        const float r = std::min(s.radius[node], v == 27 ? s.radius[1] : s.radius[node]);
        EXPECT_NEAR(glm::length(m.positions[v + 1] - m.positions[v]), 2.0f * r * 0.9f, 1e-5f);
        EXPECT_NEAR(glm::dot(m.positions[v + 1] - m.positions[v], settings.ribbonCamera - mid),
                    0.0f, 1e-4f);
    }
}

// Twigs get fewer sides (issue #33: the spruce's bark): an axis whose own base radius is below
// twigBelowRadius is meshed with twigResolution sides, the rest with resolution, and the mesh
// stays closed and well formed with caps (a cap has as many sides as its ring).
TEST(TubeMesh, ThinAxesGetTwigResolution) {
    const auto s = tree("F[+!(0.02)F[-F]]F");
    mesh::TubeSettings settings;
    settings.caps = false;
    settings.twigBelowRadius = 0.015;
    settings.twigResolution = 4;
    const auto m = mesh::buildTubeMesh(s, settings);
    // The trunk: three rings of 9; the two laterals (base ring at the fork and one node): 5.
    EXPECT_EQ(m.vertexCount(), 3u * 9u + (2u + 2u) * 5u);
    EXPECT_EQ(m.triangleCount(), 2u * 16u + 2u * 8u);
    settings.caps = true;
    const auto c = mesh::buildTubeMesh(s, settings);
    EXPECT_EQ(c.triangleCount(), 2u * 16u + 2u * 8u + 2u * 8u + 2u * 4u);
    checkWellFormed(c);
    // Off (radius 0), or every axis thicker than it: as before.
    settings.caps = false;
    settings.twigBelowRadius = 0.0;
    EXPECT_EQ(mesh::buildTubeMesh(s, settings).vertexCount(), (3u + 2u + 2u) * 9u);
    settings.twigBelowRadius = 0.015;
    settings.twigResolution = 2;
    EXPECT_THROW(mesh::buildTubeMesh(s, settings), InvalidInput);
}

// Issue #44: a root's tube flares at the ground and goes on a little below it; the flare's
// rings belong to real nodes; without the settings the mesh is the old one.
TEST(TubeMesh, RootFlareWidensTheBaseAndSinksIntoTheGround) {
    lsys::TurtleSettings t;
    t.width = 0.2; // radius 0.1
    t.step = 2.0;
    const skel::Skeleton s = lsys::interpret(makeWord("FF"), t);
    mesh::TubeSettings plain;
    const mesh::Mesh before = mesh::buildTubeMesh(s, plain);
    mesh::TubeSettings flared = plain;
    flared.rootFlare = 1.4;
    flared.flareHeight = 0.6;
    flared.groundDepth = 0.1;
    flared.nodeIds = true;
    const mesh::Mesh m = mesh::buildTubeMesh(s, flared);
    checkWellFormed(m);
    EXPECT_GT(m.positions.size(), before.positions.size());
    // Widest ring radius at a height: the ring vertices lie there (within a millimetre).
    auto radiusAt = [&](float y) {
        float r = 0.0f;
        for (const glm::vec3& p : m.positions)
            if (std::abs(p.y - y) < 1e-3f) r = std::max(r, std::hypot(p.x, p.z));
        return r;
    };
    float lowest = 0.0f;
    for (const glm::vec3& p : m.positions)
        lowest = std::min(lowest, p.y);
    EXPECT_NEAR(lowest, -0.1f, 1e-4f);
    EXPECT_NEAR(radiusAt(0.0f), 0.14f, 1e-4f);
    EXPECT_NEAR(radiusAt(-0.1f), 0.14f, 1e-4f);
    EXPECT_NEAR(radiusAt(2.0f), 0.1f, 1e-4f); // above the flare: the skeleton's radius
    // Smoothly narrower upwards through the flare.
    float previous = radiusAt(0.0f);
    for (float y : {0.036f, 0.084f, 0.15f, 0.24f, 0.36f, 0.48f}) {
        const float r = radiusAt(y);
        EXPECT_GT(r, 0.1f) << y;
        EXPECT_LT(r, previous) << y;
        previous = r;
    }
    for (std::uint32_t id : m.node)
        EXPECT_LT(id, s.size());
    // The flare rises at most kMaxFlareRadii root radii, whatever flareHeight says.
    flared.flareHeight = 100.0;
    const mesh::Mesh tall = mesh::buildTubeMesh(s, flared);
    float highestWide = 0.0f;
    for (const glm::vec3& p : tall.positions)
        if (std::hypot(p.x, p.z) > 0.1001f) highestWide = std::max(highestWide, p.y);
    EXPECT_LT(highestWide, static_cast<float>(mesh::kMaxFlareRadii) * 0.1f + 1e-3f);
    flared.flareHeight = 0.6;
    flared.rootFlare = 4.5;
    EXPECT_THROW(mesh::buildTubeMesh(s, flared), InvalidInput);
}

// Buttresses (issue #44, oak and beech): a lobed section at the ground, round again above the
// flare, about the round section's mean radius; a well-formed mesh with outward normals.
TEST(TubeMesh, ButtressLobesFadeOverTheFlare) {
    lsys::TurtleSettings t;
    t.width = 0.2; // radius 0.1
    t.step = 2.0;
    const skel::Skeleton s = lsys::interpret(makeWord("FF"), t);
    mesh::TubeSettings settings;
    settings.rootFlare = 1.4;
    settings.flareHeight = 0.6;
    settings.groundDepth = 0.1;
    const mesh::Mesh round = mesh::buildTubeMesh(s, settings);
    settings.buttressLobes = 5;
    settings.buttressDepth = 0.4;
    const mesh::Mesh lobed = mesh::buildTubeMesh(s, settings);
    checkWellFormed(lobed);
    EXPECT_GT(lobed.positions.size(), round.positions.size()); // 15 sides instead of 8
    auto ringAt = [&](float y) {
        std::vector<float> r;
        for (const glm::vec3& p : lobed.positions)
            if (std::abs(p.y - y) < 1e-4f && std::hypot(p.x, p.z) > 1e-3f)
                r.push_back(std::hypot(p.x, p.z));
        return r;
    };
    const std::vector<float> ground = ringAt(0.0f);
    ASSERT_FALSE(ground.empty());
    const auto [lo, hi] = std::minmax_element(ground.begin(), ground.end());
    EXPECT_GT(*hi / *lo, 1.3f);
    double mean = 0.0;
    for (float r : ground)
        mean += r;
    mean /= static_cast<double>(ground.size());
    EXPECT_NEAR(mean, 0.14, 0.14 * 0.1);
    const std::vector<float> above = ringAt(2.0f);
    ASSERT_FALSE(above.empty());
    for (float r : above)
        EXPECT_NEAR(r, 0.1f, 1e-4f);
    settings.buttressLobes = 13;
    EXPECT_THROW(mesh::buildTubeMesh(s, settings), InvalidInput);
}
