#include <gtest/gtest.h>

#include "engine/mesh/leafcards.h"
#include "engine/mesh/tubemesh.h"
#include "engine/util/error.h"

using namespace sylva;

TEST(LeafCards, OneCardByHand) {
    skel::Leaf leaf;
    leaf.position = {1, 2, 3};
    leaf.size = 2.0f;
    mesh::Mesh m;
    mesh::appendLeafCards(m, {leaf}, mesh::LeafCardSettings{});
    ASSERT_EQ(m.vertexCount(), 4u);
    // Identity frame: heading +Y, left -X, normal +Z; width = 0.5 * 2.
    EXPECT_EQ(m.positions[0], glm::vec3(0.5f, 2, 3));
    EXPECT_EQ(m.positions[1], glm::vec3(1.5f, 2, 3));
    EXPECT_EQ(m.positions[2], glm::vec3(1.5f, 4, 3));
    EXPECT_EQ(m.positions[3], glm::vec3(0.5f, 4, 3));
    for (const glm::vec3& n : m.normals)
        EXPECT_EQ(n, glm::vec3(0, 0, 1));
    EXPECT_EQ(m.uvs[0], glm::vec2(0, 0));
    EXPECT_EQ(m.uvs[2], glm::vec2(1, 1));
    EXPECT_EQ(m.indices, (std::vector<std::uint32_t>{0, 1, 2, 0, 2, 3}));
    // Counter-clockwise seen from the normal.
    const glm::vec3 c =
        glm::cross(m.positions[1] - m.positions[0], m.positions[2] - m.positions[0]);
    EXPECT_GT(c.z, 0.0f);
    ASSERT_EQ(m.submeshes.size(), 1u);
    EXPECT_EQ(m.submeshes[0].material, "leaf");
}

TEST(LeafCards, FollowBarkAsSecondSubmesh) {
    skel::Skeleton s;
    s.addNode({0, 0, 0}, -1, 0.1f, 0, glm::quat(1, 0, 0, 0));
    s.addNode({0, 1, 0}, 0, 0.1f, 0, glm::quat(1, 0, 0, 0));
    mesh::Mesh m = mesh::buildTubeMesh(s, mesh::TubeSettings{});
    const std::size_t barkIndices = m.indices.size();
    skel::Leaf leaf;
    mesh::appendLeafCards(m, {leaf, leaf}, mesh::LeafCardSettings{});
    ASSERT_EQ(m.submeshes.size(), 2u);
    EXPECT_EQ(m.submeshes[0].material, "bark");
    EXPECT_EQ(m.submeshes[1].material, "leaf");
    EXPECT_EQ(m.submeshes[1].firstIndex, barkIndices);
    EXPECT_EQ(m.submeshes[1].indexCount, 12u);
    EXPECT_EQ(m.uvs.size(), m.positions.size());
}

TEST(LeafCards, RejectsBadAspect) {
    mesh::LeafCardSettings settings;
    settings.aspect = 0.0;
    mesh::Mesh m;
    EXPECT_THROW(mesh::appendLeafCards(m, {skel::Leaf{}}, settings), InvalidInput);
}
