#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include <glm/gtc/constants.hpp>

#include "engine/environment/obstaclemesh.h"
#include "engine/util/error.h"

using namespace sylva;
using namespace sylva::env;

namespace {

std::filesystem::path data(const std::string& name) {
    return std::filesystem::path(SYLVA_TEST_DATA_DIR) / "obstacles" / name;
}

template <typename E>
std::string messageOf(const std::filesystem::path& file, const MeshTransform& t = {}) {
    try {
        loadObstacleMesh(file, t);
    } catch (const E& e) {
        return e.what();
    }
    ADD_FAILURE() << "no exception of the expected type for " << file;
    return {};
}

void expectNear(const glm::vec3& a, const glm::vec3& b, float eps = 1e-5f) {
    EXPECT_NEAR(a.x, b.x, eps);
    EXPECT_NEAR(a.y, b.y, eps);
    EXPECT_NEAR(a.z, b.z, eps);
}

} // namespace

TEST(MeshTransform, AppliesScaleThenRotationsXYZThenTranslation) {
    MeshTransform t;
    t.scale = glm::vec3(2.0f);
    t.rotateDeg = glm::vec3(90.0f, 90.0f, 0.0f);
    t.translate = glm::vec3(10.0f, 0.0f, 0.0f);
    // (0,1,0) -> scale (0,2,0) -> about x by 90°: (0,0,2) -> about y by 90°: (2,0,0) -> +10 x.
    expectNear(glm::vec3(t.matrix() * glm::vec4(0, 1, 0, 1)), glm::vec3(12, 0, 0));
    // Rotating about z last: (1,0,0) about z by 90° is (0,1,0).
    MeshTransform z;
    z.rotateDeg = glm::vec3(0, 0, 90);
    expectNear(glm::vec3(z.matrix() * glm::vec4(1, 0, 0, 1)), glm::vec3(0, 1, 0));
}

TEST(LoadObstacleMesh, ReadsObjWithTransform) {
    const ObstacleMesh wall = loadObstacleMesh(data("wall.obj"));
    EXPECT_EQ(wall.triangleCount(), 12u);
    EXPECT_EQ(wall.degenerateCount, 0u);
    expectNear(wall.lo, glm::vec3(-0.1f, 0.0f, -3.0f));
    expectNear(wall.hi, glm::vec3(0.1f, 3.0f, 3.0f));
    EXPECT_NE(wall.name.find("wall.obj"), std::string::npos);

    MeshTransform t;
    t.translate = glm::vec3(5, 0, 0);
    t.rotateDeg = glm::vec3(0, 90, 0); // the wall's long side (z) turns onto x
    t.scale = glm::vec3(1, 2, 1);
    const ObstacleMesh moved = loadObstacleMesh(data("wall.obj"), t);
    expectNear(moved.lo, glm::vec3(2.0f, 0.0f, -0.1f));
    expectNear(moved.hi, glm::vec3(8.0f, 6.0f, 0.1f));
}

TEST(LoadObstacleMesh, TriangulatesQuads) {
    const ObstacleMesh sphere = loadObstacleMesh(data("sphere_quads.obj"));
    EXPECT_EQ(sphere.triangleCount(), 2u * 12u + 2u * 12u * 6u);
    expectNear(sphere.lo, glm::vec3(-1.0f, -1.0f, -1.0f), 0.02f);
}

TEST(LoadObstacleMesh, ReadsStlAndCountsDegenerateTriangles) {
    const ObstacleMesh tri = loadObstacleMesh(data("triangle.stl"));
    EXPECT_EQ(tri.triangleCount(), 1u);
    EXPECT_EQ(tri.degenerateCount, 1u);
}

TEST(LoadObstacleMesh, ErrorsNameTheFile) {
    const std::string missing = messageOf<IoError>(data("no_such_mesh.obj"));
    EXPECT_NE(missing.find("no_such_mesh.obj"), std::string::npos) << missing;
    EXPECT_NE(missing.find("not found"), std::string::npos) << missing;

    const std::string folder = messageOf<IoError>(data(""));
    EXPECT_NE(folder.find("obstacles"), std::string::npos) << folder;

    const std::string empty = messageOf<InvalidInput>(data("empty.obj"));
    EXPECT_NE(empty.find("empty.obj"), std::string::npos) << empty;
    EXPECT_NE(empty.find("empty"), std::string::npos) << empty;

    const std::string garbage = messageOf<InvalidInput>(data("garbage.ply"));
    EXPECT_NE(garbage.find("garbage.ply"), std::string::npos) << garbage;
    EXPECT_NE(garbage.find("cannot read"), std::string::npos) << garbage;

    const std::string degenerate = messageOf<InvalidInput>(data("degenerate.obj"));
    EXPECT_NE(degenerate.find("degenerate.obj"), std::string::npos) << degenerate;
    EXPECT_NE(degenerate.find("degenerate"), std::string::npos) << degenerate;

    const std::string lines = messageOf<InvalidInput>(data("lines_only.obj"));
    EXPECT_NE(lines.find("lines_only.obj"), std::string::npos) << lines;

    MeshTransform flat;
    flat.scale = glm::vec3(1, 0, 0); // squashed onto a line: no triangle has area left
    const std::string squashed = messageOf<InvalidInput>(data("wall.obj"), flat);
    EXPECT_NE(squashed.find("degenerate"), std::string::npos) << squashed;
}

TEST(MakeObstacleMesh, RejectsBadIndicesAndDropsDegenerates) {
    EXPECT_THROW(makeObstacleMesh("bad", {{0, 0, 0}, {1, 0, 0}}, {{0, 1, 2}}), InvalidInput);
    const float nan = std::numeric_limits<float>::quiet_NaN();
    const ObstacleMesh m =
        makeObstacleMesh("m", {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {2, 0, 0}, {nan, 0, 0}},
                         {{0, 1, 2}, {0, 0, 2}, {0, 1, 3}, {0, 2, 4}});
    EXPECT_EQ(m.triangleCount(), 1u);
    EXPECT_EQ(m.degenerateCount, 3u);
}

TEST(MakeObstacleMesh, WritesObjThatLoadsBack) {
    const ObstacleMesh sphere = makeSphereMesh(glm::vec3(1, 2, 3), 0.5f, 6, 8);
    EXPECT_EQ(sphere.triangleCount(), 2u * 8u + 2u * 8u * 4u);
    const auto file = std::filesystem::temp_directory_path() / "sylva_test_sphere.obj";
    writeObstacleObj(sphere, file);
    const ObstacleMesh back = loadObstacleMesh(file);
    std::filesystem::remove(file);
    EXPECT_EQ(back.triangleCount(), sphere.triangleCount());
    expectNear(back.lo, sphere.lo);
    expectNear(back.hi, sphere.hi);
}
