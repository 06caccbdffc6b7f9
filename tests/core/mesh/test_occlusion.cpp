#include <gtest/gtest.h>

#include "engine/mesh/occlusion.h"

using namespace sylva;

namespace {

// A crown of leaf vertices filling the box [-1, 1]³ around (0, 5, 0) plus a bark trunk below.
mesh::Mesh crown() {
    mesh::Mesh m;
    m.positions = {{0, 0, 0}, {0, 3, 0}, {0.1f, 1.5f, 0}}; // trunk, bark
    m.indices = {0, 1, 2};
    for (int x = -1; x <= 1; ++x)
        for (int y = 4; y <= 6; ++y)
            for (int z = -1; z <= 1; ++z)
                m.positions.push_back(glm::vec3(x, y, z));
    for (std::uint32_t i = 3; i + 2 < m.positions.size(); i += 3)
        m.indices.insert(m.indices.end(), {i, i + 1, i + 2});
    m.submeshes = {{"bark", 0, 3}, {"leaf", 3, static_cast<std::uint32_t>(m.indices.size() - 3)}};
    return m;
}

std::size_t find(const mesh::Mesh& m, glm::vec3 p) {
    for (std::size_t i = 0; i < m.positions.size(); ++i)
        if (m.positions[i] == p) return i;
    return m.positions.size();
}

} // namespace

TEST(CrownOcclusion, DarkInsideTheCrownOpenOutside) {
    const mesh::Mesh m = crown();
    const std::vector<float> ao = mesh::crownOcclusion(m, 0.4f);
    ASSERT_EQ(ao.size(), m.positions.size());
    for (float a : ao) {
        EXPECT_GE(a, 0.4f);
        EXPECT_LE(a, 1.0f);
    }
    const float centre = ao[find(m, {0, 5, 0})];
    const float top = ao[find(m, {0, 6, 0})];
    const float side = ao[find(m, {1, 5, 0})];
    const float bottom = ao[find(m, {0, 4, 0})];
    EXPECT_NEAR(centre, 0.4f, 0.1f);
    EXPECT_NEAR(top, 1.0f, 1e-5f);
    EXPECT_GT(side, centre + 0.3f);
    // Sky light comes from above: the crown's underside is darker than its top.
    EXPECT_LT(bottom, top);
    // The trunk below the crown stays lit.
    EXPECT_GT(ao[0], 0.8f);
}

TEST(CrownOcclusion, WithoutLeavesEverythingIsOpen) {
    mesh::Mesh m = crown();
    m.submeshes = {{"bark", 0, static_cast<std::uint32_t>(m.indices.size())}};
    for (float a : mesh::crownOcclusion(m))
        EXPECT_EQ(a, 1.0f);
    EXPECT_TRUE(mesh::crownOcclusion(mesh::Mesh{}).empty());
}
