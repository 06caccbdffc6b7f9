#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <numbers>

#include <glm/gtc/quaternion.hpp>

#include "engine/mesh/leafplacement.h"
#include "engine/util/error.h"
#include "engine/util/random.h"

using namespace sylva;

namespace {

// A straight, thin vertical branch of \p segments one-metre segments.
skel::Skeleton twig(int segments, float radius = 0.01f) {
    skel::Skeleton s;
    s.addNode({0, 0, 0}, -1, radius, 0, glm::quat(1, 0, 0, 0));
    for (int i = 1; i <= segments; ++i)
        s.addNode({0, static_cast<float>(i), 0}, i - 1, radius, 0, glm::quat(1, 0, 0, 0));
    s.finalize();
    return s;
}

double azimuth(const skel::Leaf& l) {
    return std::atan2(l.position.x, l.position.z);
}

double angleDiff(double a, double b) {
    double d = std::fmod(a - b, 2.0 * std::numbers::pi);
    if (d < 0) d += 2.0 * std::numbers::pi;
    return d * 180.0 / std::numbers::pi;
}

mesh::LeafPlacement branchesOnly(mesh::Phyllotaxis ph) {
    mesh::LeafPlacement p;
    p.atTips = false;
    p.density = 10.0;
    p.phyllotaxis = ph;
    return p;
}

} // namespace

TEST(LeafPlacement, SpiralUsesTheGoldenAngle) {
    const auto leaves = mesh::placeLeaves(twig(2), branchesOnly(mesh::Phyllotaxis::Spiral));
    ASSERT_EQ(leaves.size(), 20u); // floor(10 * 1 + u) with u in [0, 1) per segment
    for (std::size_t i = 1; i < leaves.size(); ++i) {
        EXPECT_NEAR(angleDiff(azimuth(leaves[i]), azimuth(leaves[i - 1])), 137.5, 1e-3);
        EXPECT_GT(leaves[i].position.y, leaves[i - 1].position.y);
        EXPECT_NEAR(glm::length(glm::vec2(leaves[i].position.x, leaves[i].position.z)), 0.01f,
                    1e-6f);
    }
}

TEST(LeafPlacement, OppositeAndWhorled) {
    const auto opp = mesh::placeLeaves(twig(1), branchesOnly(mesh::Phyllotaxis::Opposite));
    ASSERT_EQ(opp.size(), 20u);
    EXPECT_NEAR(angleDiff(azimuth(opp[1]), azimuth(opp[0])), 180.0, 1e-3);
    EXPECT_NEAR(angleDiff(azimuth(opp[2]), azimuth(opp[0])), 90.0, 1e-3);
    auto p = branchesOnly(mesh::Phyllotaxis::Whorled);
    p.whorlCount = 4;
    const auto wh = mesh::placeLeaves(twig(1), p);
    ASSERT_EQ(wh.size(), 40u);
    EXPECT_NEAR(angleDiff(azimuth(wh[1]), azimuth(wh[0])), 90.0, 1e-3);
    EXPECT_NEAR(angleDiff(azimuth(wh[4]), azimuth(wh[0])), 45.0, 1e-3);
    const auto alt = mesh::placeLeaves(twig(1), branchesOnly(mesh::Phyllotaxis::Alternate));
    EXPECT_NEAR(angleDiff(azimuth(alt[1]), azimuth(alt[0])), 180.0, 1e-3);
}

TEST(LeafPlacement, ThickBranchesCarryNoLeavesTipsDo) {
    mesh::LeafPlacement p;
    p.tipCount = 5;
    const auto leaves = mesh::placeLeaves(twig(3, 0.2f), p);
    ASSERT_EQ(leaves.size(), 5u);
    for (const auto& l : leaves) {
        EXPECT_EQ(l.node, 3);
        EXPECT_EQ(l.position, glm::vec3(0, 3, 0));
    }
}

TEST(LeafPlacement, FramesSizesAndDeterminism) {
    mesh::LeafPlacement p;
    p.size = 0.2;
    p.sizeVariation = 0.5;
    p.normalWeight = 0.0;
    p.lightWeight = 0.0;
    p.upWeight = 1.0;
    p.seed = 9;
    skel::Skeleton s = twig(3);
    // Bend the twig so headings are not vertical.
    s.position[2] = {1, 1.5f, 0};
    s.position[3] = {2, 1.8f, 0.5f};
    const auto a = mesh::placeLeaves(s, p);
    const auto b = mesh::placeLeaves(s, p);
    ASSERT_FALSE(a.empty());
    bool differentSizes = false;
    for (std::size_t i = 0; i < a.size(); ++i) {
        EXPECT_EQ(a[i].position, b[i].position);
        EXPECT_EQ(a[i].size, b[i].size);
        EXPECT_GE(a[i].size, 0.1f - 1e-6f);
        EXPECT_LE(a[i].size, 0.3f + 1e-6f);
        differentSizes |= a[i].size != a[0].size;
        const glm::vec3 h = skel::headingOf(a[i].orientation), u = skel::upOf(a[i].orientation);
        EXPECT_NEAR(glm::dot(h, u), 0.0f, 1e-5f);
        EXPECT_GT(u.y, 0.0f); // facing up as asked
    }
    EXPECT_TRUE(differentSizes);
    p.seed = 10;
    const auto c = mesh::placeLeaves(s, p);
    bool changed = c.size() != a.size();
    for (std::size_t i = 0; !changed && i < a.size(); ++i)
        changed = a[i].size != c[i].size;
    EXPECT_TRUE(changed);
}

TEST(LeafPlacement, RangesAreChecked) {
    mesh::LeafPlacement p;
    p.whorlCount = 1;
    EXPECT_THROW(mesh::placeLeaves(twig(1), p), InvalidInput);
    p = {};
    p.sizeVariation = 2.0;
    EXPECT_THROW(mesh::placeLeaves(twig(1), p), InvalidInput);
}

namespace {

// placeLeaves written the straightforward way (each leaf's frame by glm::quat_cast when it is
// placed, the angles' cosines and sines of the same double angles, every leaf pushed back): the
// reference its tables, segment frames, raw inputs and SSE2 orientations must match bit for bit.
glm::vec3 referencePerpendicular(const glm::vec3& t, const glm::vec3& hint) {
    glm::vec3 p = hint - glm::dot(hint, t) * t;
    if (glm::dot(p, p) < 1e-8f) {
        const glm::vec3 a = std::abs(t.x) < 0.9f ? glm::vec3(1, 0, 0) : glm::vec3(0, 1, 0);
        p = glm::cross(t, a);
    }
    return glm::normalize(p);
}

std::vector<skel::Leaf> referencePlaceLeaves(const skel::Skeleton& s,
                                             const mesh::LeafPlacement& p) {
    constexpr double kDeg = std::numbers::pi / 180.0;
    const float ll = glm::length(p.lightDirection);
    const glm::vec3 light = ll > 0.0f ? p.lightDirection / ll : glm::vec3(0, 1, 0);
    const float sinPetiole = std::sin(static_cast<float>(p.petioleAngle * kDeg));
    const float cosPetiole = std::cos(static_cast<float>(p.petioleAngle * kDeg));
    std::vector<skel::Leaf> out;
    if (p.keepGrammarLeaves) out = s.leaves;
    auto place = [&](const glm::vec3& pos, const glm::vec3& t, const glm::vec3& radial,
                     float forward, Rng& rng, std::int32_t node) {
        skel::Leaf leaf;
        leaf.position = pos;
        const double v = p.sizeVariation * rng.uniform(-1.0, 1.0);
        leaf.size = static_cast<float>(p.size * (1.0 + v));
        leaf.node = node;
        const glm::vec3 h = glm::normalize(sinPetiole * radial + cosPetiole * t + forward * t);
        glm::vec3 n = static_cast<float>(p.normalWeight) * radial +
                      static_cast<float>(p.upWeight) * glm::vec3(0, 1, 0) +
                      static_cast<float>(p.lightWeight) * light;
        n -= glm::dot(n, h) * h;
        if (glm::dot(n, n) < 1e-8f) n = referencePerpendicular(h, glm::cross(h, t) + radial);
        n = glm::normalize(n);
        const glm::vec3 l = glm::cross(n, h);
        leaf.orientation = glm::normalize(glm::quat_cast(glm::mat3(-l, h, n)));
        out.push_back(leaf);
    };
    auto trig = [](double a) {
        return glm::vec2(static_cast<float>(std::cos(a)), static_cast<float>(std::sin(a)));
    };
    std::vector<glm::vec2> angles;
    auto anglesAt = [&](std::uint64_t k) {
        angles.clear();
        switch (p.phyllotaxis) {
        case mesh::Phyllotaxis::Spiral:
            angles.push_back(trig(137.5 * kDeg * static_cast<double>(k % 100000)));
            break;
        case mesh::Phyllotaxis::Alternate:
            angles.push_back(trig(std::numbers::pi * static_cast<double>(k % 2)));
            break;
        case mesh::Phyllotaxis::Opposite: {
            const double base = 0.5 * std::numbers::pi * static_cast<double>(k % 2);
            angles.push_back(trig(base));
            angles.push_back(trig(base + std::numbers::pi));
            break;
        }
        case mesh::Phyllotaxis::Whorled: {
            const double gap = 2.0 * std::numbers::pi / p.whorlCount;
            const double base = 0.5 * gap * static_cast<double>(k % 2);
            for (int i = 0; i < p.whorlCount; ++i)
                angles.push_back(trig(base + gap * i));
            break;
        }
        }
    };
    const std::size_t n = s.size();
    std::vector<std::uint32_t> children(n, 0);
    std::vector<std::uint8_t> hidden(n, 0);
    for (std::size_t i = 0; i < n; ++i) {
        const std::int32_t par = s.parent[i];
        hidden[i] =
            (s.flags[i] & skel::kHidden) || (par >= 0 && hidden[static_cast<std::size_t>(par)]);
        if (par >= 0 && !hidden[i]) ++children[static_cast<std::size_t>(par)];
    }
    std::vector<std::uint64_t> index(n, 0);
    for (std::size_t i = 0; i < n; ++i) {
        const std::int32_t par = s.parent[i];
        if (par < 0 || hidden[i]) continue;
        const auto pi = static_cast<std::size_t>(par);
        Rng rng(mixSeed(p.seed, i));
        const glm::vec3 a0 = s.position[pi], a1 = s.position[i];
        const float len = glm::length(a1 - a0);
        const glm::vec3 t = len > 1e-9f ? (a1 - a0) / len : skel::headingOf(s.orientation[i]);
        const glm::vec3 e1 = referencePerpendicular(t, skel::upOf(s.orientation[i]));
        const glm::vec3 e2 = glm::cross(t, e1);
        std::uint64_t k = s.order[i] == s.order[pi] ? index[pi] : 0;
        if (p.alongBranches && s.radius[i] <= p.maxBranchRadius && len > 0.0f) {
            const auto count = static_cast<std::uint64_t>(p.density * len + rng.uniform());
            for (std::uint64_t c = 0; c < count; ++c, ++k) {
                const float f = (static_cast<float>(c) + 0.5f) / static_cast<float>(count);
                const glm::vec3 axis = a0 + f * (a1 - a0);
                const float r = s.radius[pi] + f * (s.radius[i] - s.radius[pi]);
                anglesAt(k);
                for (const glm::vec2& cs : angles) {
                    const glm::vec3 radial = cs.x * e1 + cs.y * e2;
                    place(axis + r * radial, t, radial, 0.0f, rng, static_cast<std::int32_t>(i));
                }
            }
        }
        index[i] = k;
        if (p.atTips && children[i] == 0)
            for (int c = 0; c < p.tipCount; ++c) {
                const double ang = 2.0 * std::numbers::pi * c / p.tipCount + rng.uniform(0.0, 0.5);
                const glm::vec3 radial =
                    static_cast<float>(std::cos(ang)) * e1 + static_cast<float>(std::sin(ang)) * e2;
                place(a1, t, radial, 1.0f, rng, static_cast<std::int32_t>(i));
            }
    }
    return out;
}

// A random bushy skeleton: branches of several orders turning every way, some segments of zero
// length, some hidden, thick and thin.
skel::Skeleton bush(std::uint64_t seed, int nodes) {
    skel::Skeleton s;
    Rng rng(seed);
    s.addNode({0, 0, 0}, -1, 0.05f, 0, glm::quat(1, 0, 0, 0));
    for (int i = 1; i < nodes; ++i) {
        const auto par = static_cast<std::int32_t>(rng.below(static_cast<std::uint64_t>(i)));
        glm::vec3 step(rng.uniformf(-0.4f, 0.4f), rng.uniformf(-0.4f, 0.4f),
                       rng.uniformf(-0.4f, 0.4f));
        if (rng.below(15) == 0) step = glm::vec3(0.0f);
        if (rng.below(12) == 0) step = glm::vec3(0.0f, rng.uniformf(0.1f, 0.5f), 0.0f);
        const glm::quat frame = glm::normalize(glm::quat(rng.uniformf(-1, 1), rng.uniformf(-1, 1),
                                                         rng.uniformf(-1, 1), rng.uniformf(-1, 1)));
        const auto order = static_cast<std::uint16_t>(rng.below(3));
        s.addNode(s.position[static_cast<std::size_t>(par)] + step, par,
                  rng.uniformf(0.002f, 0.04f), order, frame,
                  static_cast<std::uint8_t>(rng.below(25) == 0 ? skel::kHidden : 0));
    }
    s.finalize();
    return s;
}

bool sameBits(const skel::Leaf& a, const skel::Leaf& b) {
    return std::memcmp(&a.position, &b.position, sizeof a.position) == 0 &&
           std::memcmp(&a.orientation, &b.orientation, sizeof a.orientation) == 0 &&
           std::memcmp(&a.size, &b.size, sizeof a.size) == 0 && a.node == b.node;
}

} // namespace

TEST(LeafPlacement, SameAsTheStraightforwardVersion) {
    const mesh::Phyllotaxis kinds[] = {mesh::Phyllotaxis::Spiral, mesh::Phyllotaxis::Alternate,
                                       mesh::Phyllotaxis::Opposite, mesh::Phyllotaxis::Whorled};
    int compared = 0;
    for (std::uint64_t seed = 1; seed <= 8; ++seed) {
        skel::Skeleton s = bush(seed, 300);
        mesh::LeafPlacement p;
        p.seed = seed;
        // Seed 5: the grammar's own leaves kept, the placed ones after them.
        if (seed == 5) {
            s.leaves = {{{1, 2, 3}, glm::quat(0, 1, 0, 0), 0.5f, 7}, {{4, 5, 6}, {}, 0.25f, 9}};
            p.keepGrammarLeaves = true;
        }
        p.phyllotaxis = kinds[seed % 4];
        p.whorlCount = 3 + static_cast<int>(seed % 4);
        p.density = 10.0 + 7.0 * static_cast<double>(seed);
        p.maxBranchRadius = 0.03;
        p.tipCount = static_cast<int>(seed % 5);
        p.petioleAngle = 10.0 * static_cast<double>(seed);
        // Seed 3: only the up weight and no petiole angle, so the leaves of vertical segments
        // have their normal along their heading (frame()'s other branch, SSE2's scalar lanes).
        if (seed == 3) {
            p.normalWeight = p.lightWeight = 0.0;
            p.petioleAngle = 0.0;
        }
        const std::vector<skel::Leaf> got = mesh::placeLeaves(s, p);
        const std::vector<skel::Leaf> want = referencePlaceLeaves(s, p);
        ASSERT_EQ(got.size(), want.size()) << "seed " << seed;
        for (std::size_t i = 0; i < got.size(); ++i)
            ASSERT_TRUE(sameBits(got[i], want[i])) << "seed " << seed << " leaf " << i;
        compared += static_cast<int>(got.size());
    }
    EXPECT_GT(compared, 4000);
}
