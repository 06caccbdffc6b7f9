#include <gtest/gtest.h>

#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>

#include "engine/environment/meshfilecheck.h"
#include "engine/environment/obstaclemesh.h"
#include "engine/util/error.h"

using namespace sylva;
using namespace sylva::env;

namespace {

std::filesystem::path writeFile(const std::string& name, const std::string& bytes) {
    const auto file = std::filesystem::temp_directory_path() / ("sylva_test_" + name);
    std::ofstream(file, std::ios::binary) << bytes;
    return file;
}

template <typename E>
std::string messageOf(const std::filesystem::path& file, std::size_t maxTriangles) {
    try {
        loadObstacleMesh(file, {}, maxTriangles);
    } catch (const E& e) {
        return e.what();
    }
    ADD_FAILURE() << "no exception of the expected type for " << file;
    return {};
}

const std::string kQuadHeader = "ply\nformat ascii 1.0\nelement vertex 4\nproperty float x\n"
                                "property float y\nproperty float z\nelement face 2\n"
                                "property list uchar int vertex_indices\nend_header\n";
const std::string kQuadBody = "0 0 0\n1 0 0\n1 1 0\n0 1 0\n3 0 1 2\n3 0 2 3\n";

} // namespace

TEST(MeshFileCheck, AcceptsAWellFormedPly) {
    const auto file = writeFile("quad.ply", kQuadHeader + kQuadBody);
    EXPECT_NO_THROW(checkMeshFile(file));
    EXPECT_EQ(loadObstacleMesh(file).triangleCount(), 2u);
}

// Found by fuzz_obstacle (tests/fuzz/regressions/obstacle): Assimp 5.2.5 reads past a binary
// PLY header that never ends and crashes; the check refuses it first.
TEST(MeshFileCheck, RefusesAPlyHeaderWithoutEndHeader) {
    const auto file = writeFile("noend.ply", "ply\nformat binary_little_endian 1.0\n"
                                             "element vertex 4\nproperty float x\n");
    const std::string m = messageOf<InvalidInput>(file, kMaxObstacleTriangles);
    EXPECT_NE(m.find("PLY header has no end_header line"), std::string::npos) << m;
    EXPECT_NE(m.find("noend.ply"), std::string::npos) << m;
    // The fuzzer's own input: the header breaks off inside a property line.
    const auto cut = writeFile("cut.ply", "ply\nformat binary_little_endian 1.0\n"
                                          "element vertex 4\nproperty float x\nproperty flo");
    const std::string c = messageOf<InvalidInput>(cut, kMaxObstacleTriangles);
    EXPECT_NE(c.find("cannot read it: PLY header line 5"), std::string::npos) << c;
}

TEST(MeshFileCheck, RefusesTruncatedPlyData) {
    const auto ascii = writeFile("short.ply", kQuadHeader + "0 0 0\n1 0 0\n");
    std::string m = messageOf<InvalidInput>(ascii, kMaxObstacleTriangles);
    EXPECT_NE(m.find("declares 6 lines of items, the file has 2"), std::string::npos) << m;

    const auto binary = writeFile("short-bin.ply", "ply\nformat binary_little_endian 1.0\n"
                                                   "element vertex 3\nproperty float x\n"
                                                   "end_header\n0123");
    m = messageOf<InvalidInput>(binary, kMaxObstacleTriangles);
    EXPECT_NE(m.find("declares at least 12 bytes, the file has 4"), std::string::npos) << m;
}

TEST(MeshFileCheck, RefusesUnknownHeaderLines) {
    const auto file = writeFile("bad.ply", "ply\nformat ascii 1.0\nelement vertex 1\n"
                                           "property quaternion q\nend_header\n1\n");
    const std::string m = messageOf<InvalidInput>(file, kMaxObstacleTriangles);
    EXPECT_NE(m.find("header line 4: expected 'property <type> <name>'"), std::string::npos) << m;
}

// Found by fuzz_obstacle: Assimp's PLY importer passes face indices past the vertex array to
// the post-processing steps, which read out of bounds; loadObstacleMesh has Assimp validate the
// scene first, so the file is refused with a message.
TEST(MeshFileCheck, RefusesFaceIndicesPastTheVertices) {
    std::string body;
    auto f32 = [&](float v) { body.append(reinterpret_cast<const char*>(&v), 4); };
    auto i32 = [&](std::int32_t v) { body.append(reinterpret_cast<const char*>(&v), 4); };
    for (float v : {0.f, 0.f, 0.f, 1.f, 0.f, 0.f, 0.f, 1.f, 0.f})
        f32(v);
    body.push_back(3);
    for (std::int32_t i : {0, 1, 1000000})
        i32(i);
    const auto file = writeFile("badindex.ply", "ply\nformat binary_little_endian 1.0\n"
                                                "element vertex 3\nproperty float x\n"
                                                "property float y\nproperty float z\n"
                                                "element face 1\n"
                                                "property list uchar int vertex_indices\n"
                                                "end_header\n" +
                                                    body);
    const std::string m = messageOf<InvalidInput>(file, kMaxObstacleTriangles);
    EXPECT_NE(m.find("badindex.ply': cannot read it"), std::string::npos) << m;
}

// Found by fuzz_obstacle: a PLY face with no indices made Assimp's Triangulate step assert
// (abort the process); it is refused with a message instead.
TEST(MeshFileCheck, RefusesFacesWithoutVertices) {
    const auto file = writeFile("emptyface.ply", "ply\nformat ascii 1.0\nelement vertex 3\n"
                                                 "property float x\nproperty float y\n"
                                                 "property float z\nelement face 2\n"
                                                 "property list uchar int vertex_indices\n"
                                                 "end_header\n0 0 0\n1 0 0\n0 1 0\n"
                                                 "3 0 1 2\n0\n");
    const std::string m = messageOf<InvalidInput>(file, kMaxObstacleTriangles);
    EXPECT_NE(m.find("emptyface.ply': cannot read it"), std::string::npos) << m;
}

// The limit on what a PLY header may declare: Assimp reserves memory for it before reading.
TEST(MeshFileCheck, LimitsDeclaredPlyElementCounts) {
    const auto file = writeFile("huge.ply", "ply\nformat binary_little_endian 1.0\n"
                                            "element vertex 4000000000\nproperty float x\n"
                                            "end_header\n");
    const std::string m = messageOf<LimitExceeded>(file, kMaxObstacleTriangles);
    EXPECT_NE(m.find("element 'vertex' declares 4000000000 items, more than the limit of 10000000"),
              std::string::npos)
        << m;
}

// The limit on obstacle mesh triangles, whatever the format.
TEST(MeshFileCheck, LimitsObstacleTriangles) {
    const auto file = writeFile("quad.obj", "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nf 1 2 3\n"
                                            "f 1 3 4\nf 1 2 4\n");
    const std::string m = messageOf<LimitExceeded>(file, 2);
    EXPECT_NE(m.find("has 3 triangles, more than the limit of 2; decimate the mesh"),
              std::string::npos)
        << m;
    EXPECT_EQ(loadObstacleMesh(file, {}, 3).triangleCount(), 3u);
}
