// Shadow propagation's optimal growth direction: cases by hand, and the vectorized kernel
// against a plain per-neighbour loop.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "engine/growth/optimaldirection.h"
#include "engine/growth/shadowgrid.h"
#include "engine/util/random.h"
#include "engine/util/randomvector.h"

using namespace sylva::growth;

namespace {

constexpr std::int32_t kOpaque = ShadowGrid::kOpaque;

std::int32_t& at(std::int32_t (&s)[27], int x, int y, int z) {
    return s[(y + 1) * 9 + (x + 1) * 3 + (z + 1)];
}

/// The definition, neighbour by neighbour: among the neighbours inside the cone and not opaque,
/// those with the least shadow; their integer offsets summed per distance class (faces, edges,
/// corners), each class scaled by 1/|offset|, normalized; dir when none qualifies.
glm::vec3 plainDirection(std::int32_t (&s)[27], const glm::vec3& dir, float cosHalf) {
    auto inside = [&](int x, int y, int z) {
        const glm::vec3 n = glm::normalize(glm::vec3(x, y, z));
        return n.x * dir.x + n.y * dir.y + n.z * dir.z >= cosHalf && at(s, x, y, z) != kOpaque;
    };
    std::int32_t best = kOpaque;
    bool any = false;
    for (int y = -1; y <= 1; ++y)
        for (int x = -1; x <= 1; ++x)
            for (int z = -1; z <= 1; ++z)
                if ((x || y || z) && inside(x, y, z)) {
                    best = any ? std::min(best, at(s, x, y, z)) : at(s, x, y, z);
                    any = true;
                }
    if (!any) return dir;
    glm::ivec3 perClass[3] = {glm::ivec3(0), glm::ivec3(0), glm::ivec3(0)};
    for (int y = -1; y <= 1; ++y)
        for (int x = -1; x <= 1; ++x)
            for (int z = -1; z <= 1; ++z)
                if ((x || y || z) && inside(x, y, z) && at(s, x, y, z) == best)
                    perClass[x * x + y * y + z * z - 1] += glm::ivec3(x, y, z);
    const glm::vec3 sum = glm::vec3(perClass[0]) + glm::vec3(perClass[1]) * 0.70710678f +
                          glm::vec3(perClass[2]) * 0.57735027f;
    const float l = glm::length(sum);
    return l > 1e-6f ? sum / l : dir;
}

void fill(std::int32_t (&s)[27], std::int32_t v) {
    for (std::int32_t& x : s)
        x = v;
}

} // namespace

TEST(SelfOrgDirection, TowardsTheOneLeastShadowedNeighbour) {
    std::int32_t s[27];
    fill(s, 100);
    at(s, 1, 0, 0) = 10;
    const glm::vec3 d = leastShadowedDirection(s, glm::vec3(0, 1, 0), -1.0f); // full sphere
    EXPECT_FLOAT_EQ(d.x, 1.0f);
    EXPECT_FLOAT_EQ(d.y, 0.0f);
    EXPECT_FLOAT_EQ(d.z, 0.0f);
}

TEST(SelfOrgDirection, TiesAreSummedAsUnitVectors) {
    std::int32_t s[27];
    fill(s, 100);
    // A face (+Y) and an edge (+X, +Z) tie: (0, 1, 0) + (1, 0, 1)/√2, normalized.
    at(s, 0, 1, 0) = 5;
    at(s, 1, 0, 1) = 5;
    const glm::vec3 d = leastShadowedDirection(s, glm::vec3(0, 1, 0), -1.0f);
    const glm::vec3 expect = glm::normalize(glm::vec3(0.70710678f, 1.0f, 0.70710678f));
    EXPECT_NEAR(d.x, expect.x, 1e-6f);
    EXPECT_NEAR(d.y, expect.y, 1e-6f);
    EXPECT_NEAR(d.z, expect.z, 1e-6f);
    // Two opposite faces cancel: the sum is ~0 and the bud keeps its own direction.
    fill(s, 100);
    at(s, 1, 0, 0) = 5;
    at(s, -1, 0, 0) = 5;
    const glm::vec3 keep = leastShadowedDirection(s, glm::vec3(0, 0, 1), -1.0f);
    EXPECT_EQ(keep, glm::vec3(0, 0, 1));
}

TEST(SelfOrgDirection, OnlyNeighboursInsideTheConeCount) {
    std::int32_t s[27];
    fill(s, 100);
    at(s, 0, -1, 0) = 0; // least shadow, but straight behind a bud heading +Y
    at(s, 1, 1, 1) = 50; // a corner at 54.7° from +Y
    at(s, 0, 1, 0) = 60; // straight ahead
    // 90° cone (half-angle 45°): the corner is outside, straight ahead wins.
    glm::vec3 d = leastShadowedDirection(s, glm::vec3(0, 1, 0), std::cos(glm::radians(45.0f)));
    EXPECT_EQ(d, glm::vec3(0, 1, 0));
    // 120° cone (half-angle 60°): the corner is inside and less shadowed.
    d = leastShadowedDirection(s, glm::vec3(0, 1, 0), std::cos(glm::radians(60.0f)));
    EXPECT_NEAR(d.x, 0.57735027f, 1e-6f);
    EXPECT_NEAR(d.y, 0.57735027f, 1e-6f);
    EXPECT_NEAR(d.z, 0.57735027f, 1e-6f);
    // Opaque neighbours never win, and with nothing inside the cone the bud keeps its direction.
    fill(s, kOpaque);
    at(s, 0, -1, 0) = 0;
    const glm::vec3 up = glm::normalize(glm::vec3(0.3f, 1.0f, 0.1f));
    EXPECT_EQ(leastShadowedDirection(s, up, 0.5f), up);
}

TEST(SelfOrgDirection, TheCentreIsIgnored) {
    std::int32_t s[27];
    fill(s, 100);
    at(s, 0, 0, 0) = 0;
    at(s, 0, 0, -1) = 7;
    const glm::vec3 d = leastShadowedDirection(s, glm::vec3(0, 1, 0), -1.0f);
    EXPECT_EQ(d, glm::vec3(0, 0, -1));
}

TEST(SelfOrgDirection, EqualsThePlainLoopBitForBit) {
    // Random neighbourhoods drawn from a few values (so that ties are common), some opaque,
    // random unit directions and cone angles from 1° to the whole sphere.
    sylva::Rng rng(42);
    for (int trial = 0; trial < 200'000; ++trial) {
        std::int32_t s[27];
        const int levels = 1 + static_cast<int>(rng.next() % 4);
        for (std::int32_t& v : s) {
            const std::uint64_t r = rng.next();
            v = r % 11 == 0 ? kOpaque : static_cast<std::int32_t>((r >> 8) % levels) * 1000;
        }
        const glm::vec3 dir = sylva::randomUnitVector(rng);
        const float angle = 1.0f + static_cast<float>(rng.next() % 360);
        const float cosHalf = std::cos(glm::radians(0.5f * angle));
        const glm::vec3 fast = leastShadowedDirection(s, dir, cosHalf);
        const glm::vec3 plain = plainDirection(s, dir, cosHalf);
        ASSERT_EQ(fast, plain) << "trial " << trial;
    }
}
