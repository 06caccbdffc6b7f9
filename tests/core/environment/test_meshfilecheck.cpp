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
// Fuzz findings 12 and 15: Assimp 5.2.5 sizes an OBJ mesh's vertices by its faces' index count
// (none for a line element of one vertex) but copies that vertex anyway, so a later line wrote
// past the array (valgrind: an invalid 8-byte write). Line and point elements never reach Assimp:
// every line Assimp would start with 'l' or 'p' becomes a comment, however the fuzzer dressed it.
TEST(MeshFileCheck, ObjLinesAndPointsNeverReachAssimp) {
    EXPECT_EQ(objGeometryOnly("l 1\nv 0 0 0\np 1\n"), "# 1\nv 0 0 0\n# 1\n");
    // Lines end at \r, \n, \0 and \f for Assimp; what follows is a new line.
    using namespace std::string_literals;
    EXPECT_EQ(objGeometryOnly("v 1 2 3\rl 1\0l\x16\x31 2\fp 1"s),
              "v 1 2 3\r# 1\0#\x16\x31 2\f# 1"s);
    // Material libraries too (finding 18: read from memory, Assimp parsed the OBJ's own text as
    // its MTL file and wrote past a buffer).
    EXPECT_EQ(objGeometryOnly("mtllib a.mtl\nmg 1\nusemtl a\n"), "#tllib a.mtl\n#g 1\nusemtl a\n");
    // After a byte order mark too; an 'l' inside a line is left alone.
    EXPECT_EQ(objGeometryOnly("\xEF\xBB\xBFl 1\nvl 1 # l\n"), "\xEF\xBB\xBF# 1\nvl 1 # l\n");
    // The file that made Assimp write past its vertex array now loads its one face.
    const std::string vertices = "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\n";
    const auto bad = writeFile("oneline.obj", vertices + "l 1\nl 1\nl 1 2 3 4\nf 1 2 3\n");
    EXPECT_EQ(loadObstacleMesh(bad, {}, kMaxObstacleTriangles).triangleCount(), 1u);
    const auto good = writeFile("lines.obj", vertices + "l 1 2\nl 1 2 3 4\nf 1 2 3\nf 1 3 4\n");
    EXPECT_EQ(loadObstacleMesh(good, {}, kMaxObstacleTriangles).triangleCount(), 2u);
    // Lines alone are still no obstacle.
    const auto lines = writeFile("onlylines.obj", vertices + "l 1 2 3\n");
    const std::string m = messageOf<InvalidInput>(lines, kMaxObstacleTriangles);
    EXPECT_NE(m.find("onlylines.obj"), std::string::npos) << m;
}

TEST(MeshFileCheck, LimitsObstacleTriangles) {
    const auto file = writeFile("quad.obj", "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nf 1 2 3\n"
                                            "f 1 3 4\nf 1 2 4\n");
    const std::string m = messageOf<LimitExceeded>(file, 2);
    EXPECT_NE(m.find("has 3 triangles, more than the limit of 2; decimate the mesh"),
              std::string::npos)
        << m;
    EXPECT_EQ(loadObstacleMesh(file, {}, 3).triangleCount(), 3u);
}

namespace {

/// A Collada cube (12 triangles) as Assimp exports it: a polylist with an index list <p>.
std::string colladaCube(const std::string& polylistCount = "12", const std::string& index = "25") {
    std::string p;
    for (int i = 0; i < 36; ++i)
        p += (i == 25 ? index : std::to_string(i)) + " ";
    std::string v, positions;
    for (int i = 0; i < 12; ++i)
        v += "3 ";
    const float c[8][3] = {{-1, 0, -1}, {1, 0, -1}, {1, 2, -1}, {-1, 2, -1},
                           {-1, 0, 1},  {1, 0, 1},  {1, 2, 1},  {-1, 2, 1}};
    const int tri[12][3] = {{0, 2, 1}, {0, 3, 2}, {4, 5, 6}, {4, 6, 7}, {0, 1, 5}, {0, 5, 4},
                            {3, 6, 2}, {3, 7, 6}, {0, 4, 7}, {0, 7, 3}, {1, 2, 6}, {1, 6, 5}};
    for (const auto& t : tri)
        for (int k : t)
            for (int a = 0; a < 3; ++a)
                positions += std::to_string(static_cast<int>(c[k][a])) + " ";
    return "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
           "<COLLADA xmlns=\"http://www.collada.org/2005/11/COLLADASchema\" version=\"1.4.1\">\n"
           "<asset><unit name=\"meter\" meter=\"1\"/><up_axis>Y_UP</up_axis></asset>\n"
           "<library_geometries><geometry id=\"g\"><mesh>\n"
           "<source id=\"s\"><float_array id=\"a\" count=\"108\">" +
           positions +
           "</float_array>\n"
           "<technique_common><accessor count=\"36\" source=\"#a\" stride=\"3\">"
           "<param name=\"X\" type=\"float\"/><param name=\"Y\" type=\"float\"/>"
           "<param name=\"Z\" type=\"float\"/></accessor></technique_common></source>\n"
           "<vertices id=\"v\"><input semantic=\"POSITION\" source=\"#s\"/></vertices>\n"
           "<polylist count=\"" +
           polylistCount + "\"><input offset=\"0\" semantic=\"VERTEX\" source=\"#v\"/>\n<vcount>" +
           v + "</vcount>\n<p>" + p +
           "</p>\n</polylist></mesh></geometry></library_geometries>\n"
           "<library_visual_scenes><visual_scene id=\"scene\"><node id=\"n\">"
           "<instance_geometry url=\"#g\"/></node></visual_scene></library_visual_scenes>\n"
           "<scene><instance_visual_scene url=\"#scene\"/></scene>\n</COLLADA>\n";
}

} // namespace

// Found by fuzz_obstacle (tests/fuzz/regressions/obstacle/oom-dae-index-list-not-a-number): a
// token that is not a number in a Collada index list made Assimp 5.2.5 ask for 2.4 GB; and a
// polylist declaring 2·10^9 polygons made it reserve 16 GB. Both are refused before Assimp reads
// the file; the well-formed cube loads.
TEST(MeshFileCheck, ColladaCountsAndIndexListsAreChecked) {
    EXPECT_EQ(loadObstacleMesh(writeFile("cube.dae", colladaCube())).triangleCount(), 12u);
    const std::string bad = messageOf<InvalidInput>(
        writeFile("badindex.dae", colladaCube("12", "x6")), kMaxObstacleTriangles);
    EXPECT_NE(bad.find("cannot read it: Collada the index list <p> at line 10 holds something that "
                       "is not a whole number"),
              std::string::npos)
        << bad;
    // By its content too, whatever the extension says.
    EXPECT_NE(messageOf<InvalidInput>(writeFile("badindex.xml", colladaCube("12", "\xc5\xca")),
                                      kMaxObstacleTriangles)
                  .find("not a whole number"),
              std::string::npos);
    const std::string huge = messageOf<LimitExceeded>(
        writeFile("huge.dae", colladaCube("2000000000")), kMaxObstacleTriangles);
    EXPECT_NE(huge.find("cannot read it: Collada count=\"2000000000\" at line 8 is more than the "
                        "limit of 90000000 items (9 per triangle of 10000000); decimate the mesh"),
              std::string::npos)
        << huge;
}

// Found by fuzz_obstacle (tests/fuzz/regressions/obstacle/crash-dae-count-not-a-number): a
// float_array whose count is not a whole number from 1 ("z192"; "0", "" and "-192" too) but
// holds values crashed Assimp 5.2.5 (SEGV). Refused before Assimp reads the file.
// Fuzz finding 14: a float_array whose count attribute was mutated away ("cmunt") made Assimp
// 5.2.5 read through a null pointer (SEGV). Every data array must declare its count; the accessor
// and the polylist without one are read safely (Assimp refuses or ignores them).
TEST(MeshFileCheck, ColladaDataArraysMustDeclareACount) {
    std::string text = colladaCube();
    text.replace(text.find("count=\"108\""), 5, "cmunt");
    const std::string m =
        messageOf<InvalidInput>(writeFile("nocount.dae", text), kMaxObstacleTriangles);
    EXPECT_NE(m.find("cannot read it: Collada <float_array> at line 5 has no count attribute"),
              std::string::npos)
        << m;
    // An attribute that merely ends in "count" is not one.
    text = colladaCube();
    text.replace(text.find("count=\"108\""), 11, "xcount=\"108\"");
    EXPECT_NE(messageOf<InvalidInput>(writeFile("xcount.dae", text), kMaxObstacleTriangles)
                  .find("has no count attribute"),
              std::string::npos);
}

TEST(MeshFileCheck, ColladaCountsAreWholeNumbersFromOne) {
    const std::string cube = colladaCube();
    for (const std::string bad : {"z108", "0", "", "-108", "1e3"}) {
        std::string text = cube;
        text.replace(text.find("count=\"108\""), 11, "count=\"" + bad + "\"");
        const std::string m =
            messageOf<InvalidInput>(writeFile("badcount.dae", text), kMaxObstacleTriangles);
        EXPECT_NE(m.find("cannot read it: Collada count=\"" + bad +
                         "\" at line 5 is not a whole number from 1"),
                  std::string::npos)
            << m;
    }
}
