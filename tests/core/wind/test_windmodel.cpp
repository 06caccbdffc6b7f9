#include <gtest/gtest.h>

#include <cstring>

#include "engine/util/error.h"
#include "engine/wind/windelements.h"
#include "engine/wind/windmodel.h"
#include "windtree.h"

using namespace sylva;
using namespace sylva::wind;

namespace {

float maxMotion(const mesh::WindVertex& v, const glm::vec3& p, const WindSettings& s) {
    float most = 0.0f;
    for (int f = 0; f < 120; ++f)
        most = std::max(most, glm::length(displace(v, p, nullptr, windFrame(s, f / 30.0)) - p));
    return most;
}

} // namespace

TEST(WindModel, ElementsFollowTheAxes) {
    const skel::Skeleton s = windtest::windTree();
    const WindElements e = buildWindElements(s);
    // One trunk, four limbs, eight branches; the level-3 twig has no element of its own.
    ASSERT_EQ(e.elements.size(), 13u);
    EXPECT_EQ(e.elements[0].level, 0);
    EXPECT_NEAR(e.elements[0].length, 10.0f, 1e-4f);
    EXPECT_NEAR(e.nodeU[5], 0.5f, 1e-6f);
    int levels[3] = {0, 0, 0};
    for (const WindElement& el : e.elements) {
        ++levels[el.level];
        EXPECT_GT(el.stiffness, 0.0f);
        EXPECT_GE(el.phase, 0.0f);
        EXPECT_LT(el.phase, 1.0f);
        if (el.parent >= 0) {
            EXPECT_LT(el.parent, &el - e.elements.data());
            EXPECT_EQ(el.level, e.elements[static_cast<std::size_t>(el.parent)].level + 1);
        }
    }
    EXPECT_EQ(levels[1], 4);
    EXPECT_EQ(levels[2], 8);
    // The twig (last node with order 3) moves with its branch at the branch's tip fraction.
    std::size_t twig = 0;
    for (std::size_t j = 0; j < s.size(); ++j)
        if (s.order[j] == 3) twig = j;
    ASSERT_GT(twig, 0u);
    EXPECT_EQ(e.nodeElement[twig], e.nodeElement[static_cast<std::size_t>(s.parent[twig])]);
    EXPECT_EQ(e.nodeU[twig], e.nodeU[static_cast<std::size_t>(s.parent[twig])]);
}

TEST(WindModel, IsDeterministic) {
    const skel::Skeleton s = windtest::windTree();
    mesh::Mesh a = windtest::windTreeMesh(s), b = windtest::windTreeMesh(s);
    addWindData(a, s);
    addWindData(b, s);
    ASSERT_EQ(a.wind.size(), a.positions.size());
    ASSERT_EQ(0, std::memcmp(a.wind.data(), b.wind.data(), a.wind.size() * sizeof(a.wind[0])));
    const WindFrame f = windFrame(WindSettings{}, 1.234);
    for (std::size_t i = 0; i < a.positions.size(); i += 7) {
        const glm::vec3 p = displace(a.wind[i], a.positions[i], nullptr, f);
        const glm::vec3 q = displace(b.wind[i], b.positions[i], nullptr, f);
        EXPECT_EQ(p, q);
    }
}

TEST(WindModel, TipMovesMoreThanBase) {
    const skel::Skeleton s = windtest::windTree();
    const WindElements e = buildWindElements(s);
    const WindSettings w;
    const float base = maxMotion(windVertexOf(e, 1), s.position[1], w);
    const float top = maxMotion(windVertexOf(e, 10), s.position[10], w);
    std::size_t tip = 0;
    for (std::size_t j = 0; j < s.size(); ++j)
        if (s.position[j].y > s.position[tip].y) tip = j;
    const float twig = maxMotion(windVertexOf(e, tip), s.position[tip], w);
    EXPECT_GT(base, 0.0f);
    EXPECT_GT(top, 5.0f * base);
    EXPECT_GT(twig, top);
    EXPECT_EQ(maxMotion(windVertexOf(e, 0), s.position[0], w), 0.0f); // the base stays put
}

TEST(WindModel, StrongerWindBendsMoreAndStaysBounded) {
    const skel::Skeleton s = windtest::windTree();
    const WindElements e = buildWindElements(s);
    float last = 0.0f;
    for (float strength : {0.25f, 0.5f, 1.0f, 2.0f}) {
        WindSettings w;
        w.strength = strength;
        w.gustiness = 0.0f;
        // The mean lean of the trunk's top, down-wind (+X), over one period.
        float lean = 0.0f;
        for (int f = 0; f < 120; ++f)
            lean +=
                displace(windVertexOf(e, 10), s.position[10], nullptr, windFrame(w, f / 30.0)).x;
        lean /= 120.0f;
        EXPECT_GT(lean, last) << strength;
        last = lean;
        // Bounded: no point moves farther than its distance from the base times the sum of the
        // three levels' saturation angles (0.3 + 0.6 + 0.6 rad), plus the flutter.
        for (std::size_t j = 0; j < s.size(); ++j)
            EXPECT_LE(maxMotion(windVertexOf(e, j), s.position[j], w),
                      1.5f * glm::length(s.position[j]) + 1e-4f);
    }
}

TEST(WindModel, NeverBelowTheGround) {
    const skel::Skeleton s = windtest::windTree();
    mesh::Mesh m = windtest::windTreeMesh(s);
    addWindData(m, s);
    for (glm::vec3 dir : {glm::vec3(1, 0, 0), glm::vec3(-1, 0, 0), glm::vec3(0, 0, 1)}) {
        WindSettings w;
        w.strength = 2.0f;
        w.gustiness = 1.0f;
        w.direction = dir;
        for (int f = 0; f < 120; f += 3) {
            const WindFrame frame = windFrame(w, f / 30.0);
            for (std::size_t i = 0; i < m.positions.size(); ++i) {
                const glm::vec3 p = displace(m.wind[i], m.positions[i], nullptr, frame);
                ASSERT_GE(p.y, std::min(m.positions[i].y, 0.0f)) << i;
            }
        }
    }
}

TEST(WindModel, LoopsOverItsPeriod) {
    const skel::Skeleton s = windtest::windTree();
    const WindElements e = buildWindElements(s);
    WindSettings w;
    w.period = 4.0f;
    for (std::size_t j = 0; j < s.size(); j += 3) {
        const glm::vec3 a = displaceNode(e, s, j, windFrame(w, 0.7));
        const glm::vec3 b = displaceNode(e, s, j, windFrame(w, 4.7));
        EXPECT_NEAR(glm::length(a - b), 0.0f, 1e-5f);
    }
}

TEST(WindModel, LeavesFlutterAboutTheirStem) {
    const skel::Skeleton s = windtest::windTree();
    mesh::Mesh m = windtest::windTreeMesh(s);
    addWindData(m, s);
    std::size_t leafVertices = 0;
    for (const mesh::Submesh& sm : m.submeshes)
        if (sm.material == "leaf")
            for (std::uint32_t k = sm.firstIndex; k < sm.firstIndex + sm.indexCount; ++k) {
                const std::uint32_t v = m.indices[k];
                ++leafVertices;
                // v = 0: the stem, no flutter; v = 1: the tip, the card's length (0.2 m).
                if (m.uvs[v].y == 0.0f) {
                    EXPECT_NEAR(m.wind[v].leaf.y, 0.0f, 1e-6f);
                } else {
                    EXPECT_NEAR(m.wind[v].leaf.y, 0.2f, 1e-5f);
                }
            }
    EXPECT_GT(leafVertices, 0u);
    // Bark never flutters.
    for (std::size_t i = 0; i < m.submeshes.front().indexCount; ++i)
        EXPECT_EQ(m.wind[m.indices[i]].leaf.y, 0.0f);
}

TEST(WindModel, RejectsSettingsOutOfRange) {
    WindSettings w;
    w.strength = 3.0f;
    EXPECT_THROW(validate(w), InvalidInput);
    w = {};
    w.period = 0.1f;
    EXPECT_THROW(validate(w), InvalidInput);
    mesh::Mesh noIds;
    noIds.positions.resize(3);
    EXPECT_THROW(addWindData(noIds, windtest::windTree()), InvalidInput);
}
