// Lit attraction points (issue #33): sunlit clusters and shedding of the shaded inside.
#include <gtest/gtest.h>

#include <algorithm>

#include "engine/growth/envelope.h"
#include "engine/growth/litattractors.h"
#include "engine/util/error.h"

using namespace sylva;
using namespace sylva::growth;

namespace {
std::vector<glm::vec3> crown() {
    return Envelope::ellipsoid(glm::vec3(0, 6, 0), glm::vec3(4, 3, 4)).sample(4000, 5);
}
} // namespace

TEST(LitAttractors, WithoutLightEveryPointIsKept) {
    const std::vector<glm::vec3> pts = crown();
    EXPECT_EQ(litAttractors(pts, LightParams{}, 1), pts);
}

TEST(LitAttractors, ShedsTheMostShadedFractionFromBelow) {
    const std::vector<glm::vec3> pts = crown();
    LightParams p;
    p.shadedFraction = 0.3f;
    const std::vector<glm::vec3> kept = litAttractors(pts, p, 1);
    EXPECT_LE(kept.size(), pts.size() * 71 / 100);
    EXPECT_GE(kept.size(), pts.size() * 55 / 100); // ties at the quantile are few
    // The highest point is lit; the shed ones are lower on average (shadow falls downward).
    const auto higher = [](const glm::vec3& a, const glm::vec3& b) { return a.y < b.y; };
    EXPECT_EQ(*std::max_element(kept.begin(), kept.end(), higher),
              *std::max_element(pts.begin(), pts.end(), higher));
    double keptY = 0.0, allY = 0.0;
    for (const glm::vec3& q : kept)
        keptY += q.y / kept.size();
    for (const glm::vec3& q : pts)
        allY += q.y / pts.size();
    EXPECT_GT(keptY, allY + 0.2);
}

TEST(LitAttractors, ClustersLeaveGapsAndAreDeterministic) {
    const std::vector<glm::vec3> pts = crown();
    LightParams p;
    p.clusters = 12;
    p.clusterRadius = 0.3f;
    const std::vector<glm::vec3> a = litAttractors(pts, p, 1), b = litAttractors(pts, p, 1),
                                 c = litAttractors(pts, p, 2);
    EXPECT_EQ(a, b);
    EXPECT_NE(a, c);
    EXPECT_GT(a.size(), pts.size() / 10);
    EXPECT_LT(a.size(), pts.size() * 8 / 10); // gaps between the clusters
    // Kept points keep their input order (a subsequence).
    std::size_t j = 0;
    for (const glm::vec3& q : pts)
        if (j < a.size() && q == a[j]) ++j;
    EXPECT_EQ(j, a.size());
    // No cluster sits in the shaded lower inside: the lowest central points are gone.
    for (const glm::vec3& q : a)
        EXPECT_FALSE(q.y < 4.0f && q.x * q.x + q.z * q.z < 0.25f)
            << q.x << " " << q.y << " " << q.z;
}

TEST(LitAttractors, BadParametersSayTheRange) {
    LightParams p;
    p.clusters = -1;
    EXPECT_THROW(validate(p), InvalidInput);
    p = {};
    p.shadedFraction = 1.0f;
    try {
        validate(p);
        FAIL();
    } catch (const InvalidInput& e) {
        EXPECT_NE(std::string(e.what()).find("shaded_fraction"), std::string::npos);
    }
    p = {};
    p.clusterRadius = 0.0f;
    EXPECT_THROW(validate(p), InvalidInput);
}

// Lit clusters alone are a shell; inner clusters put points back in its depth (foliage on the
// main limbs) without touching the shed most-shaded points.
TEST(LitAttractors, InnerClustersFillTheDepthOfTheShell) {
    const std::vector<glm::vec3> pts = crown();
    LightParams p;
    p.clusters = 12;
    p.clusterRadius = 0.3f;
    p.shadedFraction = 0.1f;
    const auto deep = [](const std::vector<glm::vec3>& v) {
        std::size_t n = 0;
        for (const glm::vec3& q : v) {
            const glm::vec3 d = (q - glm::vec3(0, 6, 0)) / glm::vec3(4, 3, 4);
            if (glm::dot(d, d) < 0.6f * 0.6f) ++n;
        }
        return n;
    };
    const std::vector<glm::vec3> shell = litAttractors(pts, p, 1);
    p.innerClusters = 8;
    const std::vector<glm::vec3> filled = litAttractors(pts, p, 1);
    EXPECT_GT(deep(filled), 2 * deep(shell) + 40) << deep(shell) << " " << deep(filled);
    EXPECT_GT(filled.size(), shell.size());
    // Every lit point is still there: the inner clusters only add.
    std::size_t j = 0;
    for (const glm::vec3& q : filled)
        if (j < shell.size() && q == shell[j]) ++j;
    EXPECT_EQ(j, shell.size());
    // Without lit clusters there is no shell to fill: inner clusters do nothing.
    LightParams only;
    only.innerClusters = 8;
    EXPECT_EQ(litAttractors(pts, only, 1), pts);
    only.innerRadius = 0.0f;
    EXPECT_THROW(validate(only), InvalidInput);
}
