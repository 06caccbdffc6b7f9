// Envelopes: uniform seeded sampling inside every shape, mesh inside tests and loading errors.
#include <gtest/gtest.h>

#include <cmath>

#include "engine/growth/envelope.h"
#include "engine/nodes/spacecolonizationnode.h"
#include "engine/util/error.h"

using namespace sylva;
using namespace sylva::growth;

namespace {
const std::string kData = std::string(SYLVA_TEST_DATA_DIR) + "/growth/";

// Every sample inside (by an independent analytic test), spread over the whole volume.
template <class Inside>
void expectSamplesInside(const Envelope& e, Inside inside, std::size_t n = 2000) {
    const auto points = e.sample(n, 3);
    ASSERT_EQ(points.size(), n);
    glm::vec3 lo(INFINITY), hi(-INFINITY);
    for (const glm::vec3& p : points) {
        ASSERT_TRUE(inside(p)) << p.x << " " << p.y << " " << p.z;
        lo = glm::min(lo, p);
        hi = glm::max(hi, p);
    }
    // Uniform: the samples reach close to the bounds on every axis.
    const glm::vec3 ext = e.boundsMax() - e.boundsMin();
    for (int a = 0; a < 3; ++a) {
        EXPECT_LT(lo[a] - e.boundsMin()[a], 0.25f * ext[a]);
        EXPECT_LT(e.boundsMax()[a] - hi[a], 0.25f * ext[a]);
    }
    EXPECT_EQ(e.sample(n, 3), points);
    EXPECT_NE(e.sample(n, 4), points);
}
} // namespace

TEST(Envelope, PrimitivesSampleInside) {
    expectSamplesInside(Envelope::sphere({1, 5, 2}, 3.0f), [](glm::vec3 p) {
        return glm::length(p - glm::vec3(1, 5, 2)) <= 3.0f + 1e-5f;
    });
    expectSamplesInside(Envelope::ellipsoid({0, 5, 0}, {4, 2, 3}), [](glm::vec3 p) {
        const glm::vec3 q = (p - glm::vec3(0, 5, 0)) / glm::vec3(4, 2, 3);
        return glm::dot(q, q) <= 1.0f + 1e-5f;
    });
    expectSamplesInside(Envelope::cone({0, 2, 0}, 2.0f, 6.0f), [](glm::vec3 p) {
        return p.y >= 2 && p.y <= 8 && std::hypot(p.x, p.z) <= 2.0f * (1 - (p.y - 2) / 6) + 1e-5f;
    });
    expectSamplesInside(Envelope::cone({0, 2, 0}, 2.0f, 6.0f, true), [](glm::vec3 p) {
        return p.y >= 2 && p.y <= 8 && std::hypot(p.x, p.z) <= 2.0f * (p.y - 2) / 6 + 1e-5f;
    });
    expectSamplesInside(Envelope::cylinder({0, 1, 0}, 1.0f, 5.0f), [](glm::vec3 p) {
        return p.y >= 1 && p.y <= 6 && std::hypot(p.x, p.z) <= 1.0f + 1e-5f;
    });
    expectSamplesInside(Envelope::hemisphere({0, 3, 0}, 4.0f), [](glm::vec3 p) {
        return p.y >= 3 && glm::length(p - glm::vec3(0, 3, 0)) <= 4.0f + 1e-5f;
    });
}

TEST(Envelope, ProfileFollowsTheCurve) {
    // Radius 2 at the base, 0.5 at the top: a truncated cone.
    const Envelope e = Envelope::profile({0, 1, 0}, 2.0f, 4.0f, {{0, 1}, {1, 0.25f}});
    expectSamplesInside(e, [](glm::vec3 p) {
        const float t = (p.y - 1) / 4;
        return t >= 0 && t <= 1 && std::hypot(p.x, p.z) <= 2.0f * (1 - 0.75f * t) + 1e-5f;
    });
    const auto flame = Envelope::weberPennProfile("flame");
    ASSERT_EQ(flame.size(), 33u);
    EXPECT_FLOAT_EQ(flame.front().y, 0.0f); // Weber–Penn flame: 0 at the base and at the top
    EXPECT_NEAR(flame.back().y, 0.0f, 1e-6f);
    EXPECT_NEAR(flame[10].y,
                (1 - 10 / 32.0f) <= 0.7f ? (1 - 10 / 32.0f) / 0.7f : (10 / 32.0f) / 0.3f, 1e-5f);
    EXPECT_THROW(Envelope::weberPennProfile("blob"), InvalidInput);
    EXPECT_THROW(Envelope::profile({0, 0, 0}, 1, 1, {{0, 1}}), InvalidInput);
    EXPECT_THROW(Envelope::profile({0, 0, 0}, 1, 1, {{0, 1}, {0.5f, 1.5f}, {1, 0}}), InvalidInput);
    EXPECT_THROW(Envelope::profile({0, 0, 0}, 1, 1, {{0, 0}, {1, 0}}).sample(10, 1), InvalidInput);
}

TEST(Envelope, BadShapesAreRejected) {
    EXPECT_THROW(Envelope::sphere({0, 0, 0}, 0.0f), InvalidInput);
    EXPECT_THROW(Envelope::sphere({0, 0, 0}, NAN), InvalidInput);
    EXPECT_THROW(Envelope::ellipsoid({0, 0, 0}, {1, -1, 1}), InvalidInput);
    EXPECT_THROW(Envelope::cone({0, 0, 0}, 1.0f, 0.0f), InvalidInput);
    EXPECT_THROW(envelopeShapeFromName("torus"), InvalidInput);
    EXPECT_EQ(envelopeShapeFromName("hemisphere"), EnvelopeShape::Hemisphere);
}

TEST(Envelope, MeshFromFileMatchesAnalyticInside) {
    const Envelope cube = growth::loadEnvelopeMesh(kData + "cube.obj");
    expectSamplesInside(cube, [](glm::vec3 p) {
        return std::abs(p.x) <= 1 && p.y >= 0 && p.y <= 2 && std::abs(p.z) <= 1;
    });
    // The non-convex L prism, with scale and offset, tested on a lattice that hits edges and
    // vertices exactly (watertight parity) and on random points.
    const Envelope l = growth::loadEnvelopeMesh(kData + "l-prism.obj", 2.0f, {10, 0, 0});
    auto insideL = [](glm::vec3 p) {
        const float x = (p.x - 10) / 2, y = p.y / 2, z = p.z / 2;
        if (std::abs(z) > 1) return false;
        return (x >= 0 && x <= 3 && y >= 0 && y <= 1) || (x >= 0 && x <= 1 && y >= 0 && y <= 3);
    };
    int checked = 0;
    for (float x = 9.5f; x < 17; x += 0.37f)
        for (float y = -0.5f; y < 7; y += 0.41f)
            for (float z = -2.5f; z < 2.5f; z += 0.43f) {
                const glm::vec3 p(x, y, z);
                // skip points within 1e-3 of the surface, where float rounding decides
                const bool a = insideL(p);
                bool nearSurface = false;
                for (int k = 0; k < 6 && !nearSurface; ++k) {
                    glm::vec3 d(0.0f);
                    d[k / 2] = (k % 2 ? 1e-3f : -1e-3f);
                    nearSurface = insideL(p + d) != a;
                }
                if (nearSurface) continue;
                EXPECT_EQ(l.contains(p), a) << x << " " << y << " " << z;
                ++checked;
            }
    EXPECT_GT(checked, 4000);
    expectSamplesInside(
        l, [&](glm::vec3 p) { return insideL(p); }, 1000);
    // Rays that run exactly through the shared diagonal edges of the cap triangles (y = z
    // lattice values hitting mesh edges) still count one crossing.
    EXPECT_TRUE(l.contains({11.0f, 1.0f, 0.0f}));
    EXPECT_TRUE(l.contains({10.5f, 5.0f, 1.0f}));
    EXPECT_FALSE(l.contains({13.0f, 5.0f, 0.0f}));
}

TEST(Envelope, MeshLoadErrorsNameTheFile) {
    try {
        growth::loadEnvelopeMesh(kData + "missing.obj");
        FAIL();
    } catch (const IoError& e) {
        EXPECT_NE(std::string(e.what()).find("missing.obj"), std::string::npos);
    }
    try {
        growth::loadEnvelopeMesh(kData + "empty.obj");
        FAIL();
    } catch (const InvalidInput& e) { // read as obstacles are: "the file is empty"
        EXPECT_NE(std::string(e.what()).find("empty.obj"), std::string::npos);
    }
    // An open mesh (one triangle) has no inside to sample.
    EXPECT_THROW(Envelope::mesh({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}, {0, 1, 2}, "tri").sample(5, 1),
                 InvalidInput);
}
