#include <gtest/gtest.h>

#include <cstdint>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <utility>
#include <vector>

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

// Fuzz finding 24: Assimp 5.2.5 sizes its vertex arrays by the first vertex element and writes
// every item of a later vertex element at its index, past the arrays of a smaller first one
// (valgrind: invalid writes just after Assimp's vertex array; ASan, later: heap metadata
// overwritten). Faces likewise (face and tristrips elements share the face array). The check
// refuses a second element of either kind before Assimp reads the file.
TEST(MeshFileCheck, PlyHasOneVertexElementAndOneFaceElement) {
    const std::string start = "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\n"
                              "property float y\nproperty float z\nelement face 1\n"
                              "property list uchar int vertex_indices\n";
    const std::string triangle = "0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n";
    struct Case {
        const char* name;
        std::string elements, items, message;
    };
    const Case cases[] = {
        {"twovertex.ply",
         "element vertex 5\nproperty float x\nproperty float y\nproperty float z\n",
         "0 0 1\n1 0 1\n0 1 1\n1 1 1\n2 2 2\n",
         "twovertex.ply': cannot read it: PLY header line 9: a second vertex element"},
        {"twoface.ply", "element face 2\nproperty list uchar int vertex_indices\n",
         "3 0 1 2\n3 0 2 1\n", "PLY header line 9: a second face element ('face' came first)"},
        {"facestrips.ply", "element tristrips 1\nproperty list int int vertex_indices\n",
         "3 0 1 2\n", "PLY header line 9: a second face element ('face' came first)"},
    };
    for (const Case& c : cases) {
        const auto file =
            writeFile(c.name, start + c.elements + "end_header\n" + triangle + c.items);
        const std::string m = messageOf<InvalidInput>(file, kMaxObstacleTriangles);
        EXPECT_NE(m.find(c.message), std::string::npos) << m;
    }
    // Other elements may repeat (Assimp reads them into no mesh array).
    const auto other = writeFile("edges.ply", start +
                                                  "element edge 1\nproperty int vertex1\n"
                                                  "element edge 1\nproperty int vertex1\n"
                                                  "end_header\n" +
                                                  triangle + "0\n1\n");
    EXPECT_NO_THROW(checkMeshFile(other));
}

// Assimp 5.2.5 also ends a PLY header line at \r, \0 and \f: "comment x\relement vertex 5" is a
// comment for a line-by-line check and a second vertex element for Assimp (the regression
// overflow-ply-second-vertex-element-in-comment wrote past the vertex array). Header lines are
// text: control characters other than a tab (and a \r before the \n) are refused.
TEST(MeshFileCheck, PlyHeaderControlCharactersAreRefused) {
    for (const char hidden : {'\r', '\0', '\f', '\v'}) {
        const auto file = writeFile("hidden.ply", "ply\nformat ascii 1.0\nelement vertex 3\n"
                                                  "property float x\nproperty float y\n"
                                                  "property float z\ncomment x" +
                                                      std::string(1, hidden) +
                                                      "element vertex 5\nend_header\n"
                                                      "0 0 0\n1 0 0\n0 1 0\n");
        const std::string m = messageOf<InvalidInput>(file, kMaxObstacleTriangles);
        EXPECT_NE(m.find("PLY header line 7: holds the control character 0x"), std::string::npos)
            << m;
    }
    // Windows line ends stay fine.
    std::string crlf;
    for (const char c : kQuadHeader + kQuadBody) {
        if (c == '\n') crlf += '\r';
        crlf += c;
    }
    EXPECT_EQ(loadObstacleMesh(writeFile("crlf.ply", crlf)).triangleCount(), 2u);
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

// Fuzz finding 25 (valgrind, then by hand): Assimp 5.2.5 reads an accessor's items from its data
// array unchecked. An offset mutated to 400000000 (SEGV), an accessor longer than its array (reads
// past it: the mesh then varies from run to run), and one naming a Name_array (its number array
// is empty: SEGV) are refused; so are skins and animations, the only users of name arrays, and
// attributes XML allows in forms the plain scan misses (single quotes, spaces around '='). An
// input's offset is read as a signed number (-1 read before the index list) and multiplies the
// list Assimp reserves (100000000: out of memory): a whole number below 64. A primitive without
// a VERTEX input made Assimp read before its index list (valgrind).
TEST(MeshFileCheck, ColladaAccessorsMustFitTheirArrays) {
    const std::string cube = colladaCube();
    const std::string accessor = "<accessor count=\"36\" source=\"#a\" stride=\"3\">";
    struct Case {
        std::string from, to, message;
    };
    const Case cases[] = {
        {accessor, "<accessor count=\"36\" offset=\"400000000\" source=\"#a\" stride=\"3\">",
         "Collada <accessor> at line 6: offset=\"400000000\" is not a whole number from 0 to "
         "90000000"},
        {accessor, "<accessor count=\"37\" source=\"#a\" stride=\"3\">",
         "Collada <accessor> at line 6 reads 111 values (offset 0, count 37, stride 3, 3 params) "
         "from 'a', which holds 108"},
        {accessor, "<accessor count=\"36\" offset = '1' source=\"#a\" stride=\"3\">",
         "reads 109 values (offset 1"},
        {accessor, "<accessor count='0' source=\"#a\" stride=\"3\">",
         "Collada <accessor> at line 6: count=\"0\" is not a whole number from 1"},
        {"<float_array id=\"a\" count=\"108\">", "<Name_array id=\"a\" count=\"108\">",
         "Collada <Name_array> at line 5: obstacles are static geometry"},
        {"<input offset=\"0\"", "<input offset=\"-1\"",
         "Collada <input> at line 8: offset=\"-1\" is not a whole number from 0 to 63"},
        {"semantic=\"VERTEX\"", "semantic=\"VE/TEX\"",
         "Collada <polylist> at line 8 has no input of semantic VERTEX"},
        {"<library_geometries>",
         "<library_controllers><controller id=\"c\"/></library_controllers>"
         "<library_geometries>",
         "Collada <controller> at line 4: obstacles are static geometry; export the obstacle "
         "without its skin and animations"},
    };
    for (const Case& c : cases) {
        std::string text = cube;
        text.replace(text.find(c.from), c.from.size(), c.to);
        const std::string m =
            messageOf<InvalidInput>(writeFile("accessor.dae", text), kMaxObstacleTriangles);
        EXPECT_NE(m.find(c.message), std::string::npos) << m;
    }
    // Comments hold no elements; the cube still loads.
    std::string text = cube;
    text.replace(text.find(accessor), 0, "<!-- <accessor count=\"99\" source=\"#a\"/> -->");
    EXPECT_EQ(loadObstacleMesh(writeFile("commented.dae", text)).triangleCount(), 12u);
}

// Fuzz finding 26: Assimp 5.2.5 assembles a primitive's index list <p> with what it has read of
// the primitive before it. A polylist whose <p> comes without a <vcount> before it read the
// polygon sizes from an empty array (SEGV at address 0); a VERTEX input after the list read before
// it (valgrind); and a comment in an index list hid a token that is not a number from the scan of
// its text (Assimp then asked for 3 GB). All three are refused; the cube's parts in Assimp's
// order, and a strip after its inputs, still load.
TEST(MeshFileCheck, ColladaIndexListsComeAfterWhatTheyNeed) {
    const std::string cube = colladaCube();
    const std::string vertex = "<input offset=\"0\" semantic=\"VERTEX\" source=\"#v\"/>";
    const std::size_t vcountAt = cube.find("<vcount>");
    const std::string vcount = cube.substr(vcountAt, cube.find("<p>") - vcountAt);
    struct Case {
        std::string from, to, message;
        bool moved = false; // `from` leaves its place: each case moves it after the list
    };
    const Case cases[] = {
        {vcount, "",
         "Collada <polylist> at line 8 has no <vcount> (the number of corners of each polygon) "
         "before its index list <p> at line 9"},
        {vcount, "</p>" + vcount, "has no <vcount> (the number of corners of each polygon) before",
         true},
        {"<vcount>", "<p/><vcount>", "has no <vcount> (the number of corners of each polygon)"},
        {vertex, "",
         "Collada <polylist> at line 8 has no input of semantic VERTEX before its "
         "index list <p> at line 10"},
        {vertex, "</p>" + vertex, "has no input of semantic VERTEX before its index list <p>",
         true},
        {"<p>0 ", "<p><!-- a comment -->0 x ",
         "Collada the index list <p> at line 10 holds markup (a comment, CDATA or an element) "
         "where only whole numbers belong"},
        {"<p>0 ", "<p><![CDATA[0 ]]>", "holds markup"},
        {"<vcount>3 ", "<vcount>3 <!-- -->", "the index list <vcount> at line 9 holds markup"},
    };
    for (const Case& c : cases) {
        std::string text = cube;
        if (c.moved) {
            text.erase(text.find(c.from), c.from.size());
            text.replace(text.find("</p>"), 4, c.to);
        } else {
            text.replace(text.find(c.from), c.from.size(), c.to);
        }
        const std::string m =
            messageOf<InvalidInput>(writeFile("order.dae", text), kMaxObstacleTriangles);
        EXPECT_NE(m.find(c.message), std::string::npos) << c.to << "\n" << m;
    }
    // Assimp reserves the index list a primitive declares before reading it (found beside
    // finding 26): triangles of count 89999999 asked for 2.2 GB, a polygon of 4294967295 corners
    // for 34 GB. A list shorter than declared is refused first (Assimp refuses it after).
    struct Short {
        std::string from, to, message;
    };
    const Short shorts[] = {
        {"<vcount>3 ", "<vcount>4294967295 ",
         "Collada <polylist> at line 8 declares 4294967328 corners of 1 value(s) each "
         "(4294967328 numbers), but its index list <p> at line 10 holds 36"},
        {"<input offset=\"0\" semantic=\"VERTEX\" source=\"#v\"/>",
         "<input offset=\"0\" semantic=\"VERTEX\" source=\"#v\"/>"
         "<input offset=\"1\" semantic=\"NORMAL\" source=\"#s\"/>",
         "declares 36 corners of 2 value(s) each (72 numbers), but its index list <p> at line 10 "
         "holds 36"},
    };
    for (const Short& c : shorts) {
        std::string text = cube;
        text.replace(text.find(c.from), c.from.size(), c.to);
        const std::string m =
            messageOf<InvalidInput>(writeFile("short.dae", text), kMaxObstacleTriangles);
        EXPECT_NE(m.find(c.message), std::string::npos) << m;
    }
    auto asPrimitive = [&](const std::string& primitive) {
        std::string text = cube;
        const std::size_t from = text.find("<polylist");
        const std::size_t to = text.find("</polylist>") + std::string("</polylist>").size();
        return text.replace(from, to - from, primitive);
    };
    const std::string triangles = messageOf<InvalidInput>(
        writeFile("short.dae", asPrimitive("<triangles count=\"89999999\">" + vertex +
                                           "<p>0 1 2 3 4 5</p></triangles>")),
        kMaxObstacleTriangles);
    EXPECT_NE(triangles.find("Collada <triangles> at line 8 declares 269999997 corners of 1 "
                             "value(s) each (269999997 numbers), but its index list <p> at line 8 "
                             "holds 6"),
              std::string::npos)
        << triangles;
    // Lines whose count is wrong (as SketchUp writes them) pass up to 2^20 numbers: Assimp
    // corrects the count. They hold no triangle, so Assimp refuses the file for that.
    const std::string fewer =
        messageOf<InvalidInput>(writeFile("lines.dae", asPrimitive("<lines count=\"7\">" + vertex +
                                                                   "<p>0 1 2 3</p></lines>")),
                                kMaxObstacleTriangles);
    EXPECT_NE(fewer.find("cannot read it: No meshes remaining"), std::string::npos) << fewer;
    const std::string many = messageOf<InvalidInput>(
        writeFile("lines.dae",
                  asPrimitive("<lines count=\"8000000\">" + vertex + "<p>0 1 2 3</p></lines>")),
        kMaxObstacleTriangles);
    EXPECT_NE(many.find("Collada <lines> at line 8 declares 16000000 corners of 1 value(s) each "
                        "(16000000 numbers), but its index list <p> at line 8 holds 4"),
              std::string::npos)
        << many;
    // A strip of 4 corners (2 triangles) after its input, its list ending "</p >", loads.
    std::string strip = cube;
    const std::size_t from = strip.find("<polylist");
    const std::size_t to = strip.find("</polylist>") + std::string("</polylist>").size();
    strip.replace(from, to - from,
                  "<tristrips count=\"1\">" + vertex + "<p>0 1 2 3</p ></tristrips>");
    EXPECT_EQ(loadObstacleMesh(writeFile("strip.dae", strip)).triangleCount(), 2u);
}

namespace {

void putLe32(std::string& bytes, std::size_t at, std::uint32_t v) {
    for (int k = 0; k < 4; ++k)
        bytes[at + std::size_t(k)] = static_cast<char>((v >> (8 * k)) & 0xffu);
}

/// A binary glTF 2.0 file of one triangle: header, JSON chunk, binary chunk (three positions);
/// \p mode is put into the primitive when given.
std::string glbTriangle(const std::string& mode = {}) {
    std::string json =
        R"({"asset":{"version":"2.0"},"scene":0,"scenes":[{"nodes":[0]}],"nodes":[{"mesh":0}],)"
        R"("meshes":[{"primitives":[{)" +
        (mode.empty() ? std::string() : R"("mode":)" + mode + ",") +
        R"("attributes":{"POSITION":0}}]}],"accessors":[{)"
        R"("bufferView":0,"componentType":5126,"count":3,"type":"VEC3","max":[1,1,0],)"
        R"("min":[0,0,0]}],"bufferViews":[{"buffer":0,"byteOffset":0,"byteLength":36}],)"
        R"("buffers":[{"byteLength":36}]})";
    json.resize((json.size() + 3) / 4 * 4, ' ');
    const float positions[9] = {0, 0, 0, 1, 0, 0, 0, 1, 0};
    std::string bin(reinterpret_cast<const char*>(positions), sizeof positions);
    std::string out(12, '\0');
    out.replace(0, 4, "glTF");
    putLe32(out, 4, 2);
    std::string chunk(8, '\0');
    putLe32(chunk, 0, std::uint32_t(json.size()));
    chunk.replace(4, 4, "JSON");
    out += chunk + json;
    putLe32(chunk, 0, std::uint32_t(bin.size()));
    chunk.replace(4, 4, std::string("BIN\0", 4));
    out += chunk + bin;
    putLe32(out, 8, std::uint32_t(out.size()));
    return out;
}

} // namespace

// Fuzz finding 19 (tests/fuzz/regressions/obstacle/oom-glb-json-chunk-4gb*): Debian's Assimp
// 5.2.5 allocates a binary glTF's declared JSON chunk length before comparing it with the file;
// a 2 KB file declaring 4 GB ran out of memory. The lengths must fit in the file.
TEST(MeshFileCheck, BinaryGltfLengthsMustFitTheFile) {
    const std::string good = glbTriangle();
    EXPECT_NO_THROW(checkMeshFile(writeFile("triangle.glb", good)));
    EXPECT_EQ(loadObstacleMesh(writeFile("triangle.glb", good)).triangleCount(), 1u);

    std::string json = good;
    putLe32(json, 12, 0xfffc0078u); // the fuzzer's JSON chunk length
    std::string m = messageOf<InvalidInput>(writeFile("hugejson.glb", json), kMaxObstacleTriangles);
    EXPECT_NE(m.find("cannot read it: binary glTF JSON chunk declares 4294705272 bytes, more than "
                     "the " +
                     std::to_string(good.size() - 20) + " the file holds after its header"),
              std::string::npos)
        << m;
    // By its magic whatever the extension, as Assimp sniffs it.
    EXPECT_THROW(checkMeshFile(writeFile("hugejson.obj", json)), InvalidInput);

    std::string bin = good;
    putLe32(bin, bin.size() - 36 - 8, 0x7fffffffu); // the binary chunk's length
    m = messageOf<InvalidInput>(writeFile("hugebin.glb", bin), kMaxObstacleTriangles);
    EXPECT_NE(m.find("binary chunk declares 2147483647 bytes, more than the 36"), std::string::npos)
        << m;

    std::string total = good;
    putLe32(total, 8, 0xffffffffu);
    m = messageOf<InvalidInput>(writeFile("hugetotal.glb", total), kMaxObstacleTriangles);
    EXPECT_NE(m.find("binary glTF declares 4294967295 bytes, the file has " +
                     std::to_string(good.size())),
              std::string::npos)
        << m;

    std::string version = good;
    putLe32(version, 4, 7);
    m = messageOf<InvalidInput>(writeFile("v7.glb", version), kMaxObstacleTriangles);
    EXPECT_NE(m.find("binary glTF version 7 is not 1 or 2"), std::string::npos) << m;
    EXPECT_THROW(checkMeshFile(writeFile("short.glb", good.substr(0, 16))), InvalidInput);
}

// Fuzz finding 20 (tests/fuzz/regressions/obstacle/crash-glb-line-loop): Debian's Assimp 5.2.5
// read through a null pointer on a binary glTF whose triangles were relabelled as a line loop
// (it closes the loop with the first face, empty when an index was out of range; triangle fans
// reuse earlier faces the same way). Obstacles need triangles: those modes are refused.
TEST(MeshFileCheck, GltfLineLoopsAndFansAreRefused) {
    EXPECT_EQ(loadObstacleMesh(writeFile("mode4.glb", glbTriangle("4"))).triangleCount(), 1u);
    for (const auto& [mode, what] :
         {std::pair{"2", "a line loop (mode 2)"}, std::pair{"3", "a line strip (mode 3)"},
          std::pair{"6", "a triangle fan (mode 6)"}}) {
        const std::string m = messageOf<InvalidInput>(writeFile("mode.glb", glbTriangle(mode)),
                                                      kMaxObstacleTriangles);
        EXPECT_NE(m.find(std::string("cannot read it: glTF meshes[0].primitives[0] is drawn as ") +
                         what + ", which the importer cannot read safely"),
                  std::string::npos)
            << m;
    }
    // A text glTF (by extension, or JSON content under another name) likewise.
    const std::string text = R"({"asset":{"version":"2.0"},"meshes":[{"primitives":[)"
                             R"({"mode":4,"attributes":{}},{"mode":2,"attributes":{}}]}]})";
    EXPECT_NE(messageOf<InvalidInput>(writeFile("loop.gltf", text), kMaxObstacleTriangles)
                  .find("meshes[0].primitives[1] is drawn as a line loop"),
              std::string::npos);
    EXPECT_THROW(checkMeshFile(writeFile("loop.mesh", "\n  " + text)), InvalidInput);
    // JSON that does not parse is refused with where it breaks.
    std::string broken = glbTriangle();
    broken[20] = '[';
    const std::string m =
        messageOf<InvalidInput>(writeFile("broken.glb", broken), kMaxObstacleTriangles);
    EXPECT_NE(m.find("cannot read it: glTF JSON is not valid"), std::string::npos) << m;
}

// Fuzz finding 21 (tests/fuzz/regressions/obstacle/overflow-glb-accessor-offset): an accessor's
// byteOffset mutated from 0 to 1 made Debian's Assimp 5.2.5 read one byte past a 720-byte
// buffer (ASan: heap-buffer-overflow). Accessors, buffer views and buffers must fit.
TEST(MeshFileCheck, GltfAccessorsViewsAndBuffersMustFit) {
    auto edited = [](const std::string& from, const std::string& to) {
        std::string glb = glbTriangle();
        const std::size_t at = glb.find(from);
        EXPECT_NE(at, std::string::npos) << from;
        glb.replace(at, from.size(), to); // same length: the chunk lengths stay right
        return glb;
    };
    auto refusal = [](const std::string& glb) {
        return messageOf<InvalidInput>(writeFile("bounds.glb", glb), kMaxObstacleTriangles);
    };
    std::string m = refusal(edited(R"("count":3,"type":"VEC3")", R"("count":4,"type":"VEC3")"));
    EXPECT_NE(m.find("glTF accessors[0] (4 × 12 bytes from byte 0) does not fit in "
                     "bufferViews[0] (36 bytes)"),
              std::string::npos)
        << m;
    m = refusal(edited(R"("byteOffset":0,"byteLength":36)", R"("byteOffset":1,"byteLength":36)"));
    EXPECT_NE(m.find("glTF bufferViews[0] does not fit in buffers[0]"), std::string::npos) << m;
    m = refusal(edited(R"("buffers":[{"byteLength":36}])", R"("buffers":[{"byteLength":99}])"));
    EXPECT_NE(m.find("glTF buffers[0] declares 99 bytes, more than its data holds (36)"),
              std::string::npos)
        << m;
    m = refusal(edited(R"("componentType":5126)", R"("componentType":5127)"));
    EXPECT_NE(m.find("accessors[0].componentType 5127 is not one of glTF's"), std::string::npos)
        << m;
    // An accessor without a buffer view is zeros, which Assimp allocates: limited.
    const std::string zeros = R"({"asset":{"version":"2.0"},"accessors":[{"componentType":5126,)"
                              R"("count":4000000000,"type":"VEC3"}]})";
    m = messageOf<LimitExceeded>(writeFile("zeros.gltf", zeros), kMaxObstacleTriangles);
    EXPECT_NE(m.find("accessors[0].count 4000000000 is more than the limit of 30000000"),
              std::string::npos)
        << m;
    m = refusal(edited(R"("type":"VEC3")", R"("type":"VEC9")"));
    EXPECT_NE(m.find("accessors[0].type 'VEC9' is not one of glTF's"), std::string::npos) << m;
}

// Fuzz finding 22 (tests/fuzz/regressions/obstacle/crash-gltf-skin-without-inverse-bind-matrices):
// a skin without inverseBindMatrices (valid glTF: identity) made Debian's Assimp 5.2.5 read
// through a null pointer. Obstacles need no skin: such files are refused, saying why.
TEST(MeshFileCheck, GltfSkinsNeedInverseBindMatrices) {
    const std::string head = R"({"asset":{"version":"2.0"},"nodes":[{"name":"joint"}],)";
    const std::string m = messageOf<InvalidInput>(
        writeFile("skin.gltf", head + R"("skins":[{"joints":[0]}]})"), kMaxObstacleTriangles);
    EXPECT_NE(m.find("cannot read it: glTF skins[0] names no accessor of inverse bind matrices"),
              std::string::npos)
        << m;
    EXPECT_THROW(checkMeshFile(writeFile(
                     "skin.gltf", head + R"("skins":[{"joints":[0],"inverseBindMatrices":3}]})")),
                 InvalidInput);
}

// Fuzz finding 23 (tests/fuzz/regressions/obstacle/oom-glb-strip-without-vertices): a line strip
// whose attributes were mutated away made Debian's Assimp 5.2.5 count count - 1 faces in
// unsigned arithmetic and ask for 64 GB; triangle strips (count - 2) likewise. Line strips are
// refused (above), triangle strips need at least one triangle.
TEST(MeshFileCheck, GltfTriangleStripsNeedThreeVertices) {
    EXPECT_EQ(loadObstacleMesh(writeFile("strip.glb", glbTriangle("5"))).triangleCount(), 1u);
    const std::string text = R"({"asset":{"version":"2.0"},"meshes":[{"primitives":[)"
                             R"({"mode":5,"attributes":{}}]}]})";
    const std::string m =
        messageOf<InvalidInput>(writeFile("strip.gltf", text), kMaxObstacleTriangles);
    EXPECT_NE(m.find("meshes[0].primitives[0] is a triangle strip of fewer than 3 vertices"),
              std::string::npos)
        << m;
}

// Finding 28 (by reading Assimp 5.2.5's Collada loader): it builds the scene by copying each
// <instance_node>'s node in, recursively. A node that instances itself or its parent recursed
// until the stack overflowed (ASan: stack-overflow); a chain of 30 nodes each instancing the next
// twice (2^30 copies) ran out of time and memory; 20,000 nested nodes overflowed the stack
// without instancing. Refused; 50 instances of one rock load as 50 rocks.
TEST(MeshFileCheck, ColladaSceneGraphsAreBounded) {
    const std::string cube = colladaCube();
    const std::string node = "<node id=\"n\"><instance_geometry url=\"#g\"/></node>";
    ASSERT_NE(cube.find(node), std::string::npos);
    auto scene = [&](const std::string& library, const std::string& nodes) {
        std::string text = cube;
        text.replace(text.find(node), node.size(), nodes);
        text.replace(text.find("<library_visual_scenes>"), 0, library);
        return writeFile("scene.dae", text);
    };
    const std::string self = messageOf<InvalidInput>(
        scene("",
              "<node id=\"n\"><instance_geometry url=\"#g\"/><instance_node url=\"#n\"/></node>"),
        kMaxObstacleTriangles);
    EXPECT_NE(self.find("Collada <node> at line 12 is its own ancestor (through <node> at line "
                        "12): the scene graph must not loop"),
              std::string::npos)
        << self;
    // Through the parent, and through the visual scene (a node to Assimp), by name.
    for (const std::string nodes :
         {"<node id=\"n\"><node id=\"m\"><instance_node url=\"#n\"/></node></node>",
          "<node id=\"n\"><instance_node url=\"#Scene\"/></node>"})
        EXPECT_NE(messageOf<InvalidInput>(scene("", nodes), kMaxObstacleTriangles)
                      .find("the scene graph must not loop"),
                  std::string::npos)
            << nodes;

    std::string chain = "<library_nodes>";
    for (int i = 0; i < 30; ++i)
        chain += "<node id=\"L" + std::to_string(i) + "\"><instance_node url=\"#L" +
                 std::to_string(i + 1) + "\"/><instance_node url=\"#L" + std::to_string(i + 1) +
                 "\"/></node>";
    chain += "<node id=\"L30\"><instance_geometry url=\"#g\"/></node></library_nodes>";
    const std::string doubling = messageOf<LimitExceeded>(
        scene(chain, "<node id=\"n\"><instance_node url=\"#L0\"/></node>"), kMaxObstacleTriangles);
    EXPECT_NE(doubling.find("holds more than 100000 nodes once its <instance_node>s are copied in"),
              std::string::npos)
        << doubling;

    std::string deep;
    for (int i = 0; i < 1000; ++i)
        deep += "<node>";
    deep += "<instance_geometry url=\"#g\"/>";
    for (int i = 0; i < 1000; ++i)
        deep += "</node>";
    const std::string tooDeep = messageOf<LimitExceeded>(scene("", deep), kMaxObstacleTriangles);
    EXPECT_NE(tooDeep.find("starts a hierarchy more than 1000 deep; flatten the obstacle's "
                           "hierarchy"),
              std::string::npos)
        << tooDeep;

    std::string rocks;
    for (int i = 0; i < 50; ++i)
        rocks += "<node id=\"r" + std::to_string(i) + "\"><translate>" + std::to_string(3 * i) +
                 " 0 0</translate><instance_node url=\"#rock\"/></node>";
    const ObstacleMesh fifty = loadObstacleMesh(
        scene("<library_nodes><node id=\"rock\"><instance_geometry url=\"#g\"/></node>"
              "</library_nodes>",
              rocks));
    EXPECT_EQ(fifty.triangleCount(), 50u * 12u);
    EXPECT_NEAR(fifty.hi.x - fifty.lo.x, 3.0f * 49 + 2.0f, 1e-3f);
}

namespace {

std::string readWhole(const std::filesystem::path& file) {
    std::ifstream in(file, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), {}};
}

/// A binary FBX 7.5 record (64-bit header words): name, properties (already encoded), children.
std::string fbxRecord(std::size_t at, const std::string& name, const std::string& properties,
                      std::size_t propertyCount, const std::vector<std::string>& children) {
    const auto word = [](std::uint64_t v) {
        std::string out;
        out.append(reinterpret_cast<const char*>(&v), 8);
        return out;
    };
    // Children are laid out after this header, name and properties; each needs its own offset.
    const std::size_t headerLength = 3 * 8 + 1 + name.size() + properties.size();
    std::string body;
    for (const std::string& child : children)
        body += child;
    if (!children.empty()) body += std::string(25, '\0'); // the null record closing the list
    const std::uint64_t end = at + headerLength + body.size();
    return word(end) + word(propertyCount) + word(properties.size()) +
           static_cast<char>(name.size()) + name + properties + body;
}

std::string fbxLong(std::int64_t v) {
    std::string out(1, 'L');
    out.append(reinterpret_cast<const char*>(&v), 8);
    return out;
}
std::string fbxString(const std::string& s) {
    const auto n = static_cast<std::uint32_t>(s.size());
    std::string out(1, 'S');
    out.append(reinterpret_cast<const char*>(&n), 4);
    out.append(s);
    return out;
}

} // namespace

// Finding 29 (by reading Assimp 5.2.5's FBX converter, after 28): it converts the models from
// the root down their parent links (`C: "OO", child, parent`) recursively. A model that is its
// own parent, or its parent's parent, recursed until the stack overflowed (ASan: stack-overflow);
// 100,000 nested ASCII scopes overflowed it in the tokenizer. Refused, in ASCII and binary
// files; the ASCII cube (and binary files Sylva writes, SceneExport) load as before.
TEST(MeshFileCheck, FbxModelLinksAndScopesAreBounded) {
    const std::filesystem::path data = std::filesystem::path(SYLVA_TEST_DATA_DIR) / "obstacles";
    const std::string cube = readWhole(data / "cube-ascii.fbx");
    ASSERT_EQ(loadObstacleMesh(data / "cube-ascii.fbx").triangleCount(), 12u);
    const std::string links = "\tC: \"OO\", 1000002, 1000003\n";
    ASSERT_NE(cube.find(links), std::string::npos);
    std::string self = cube;
    self.replace(self.find(links), links.size(), links + "\tC: \"OO\", 1000003, 1000003\n");
    const std::string m =
        messageOf<InvalidInput>(writeFile("self.fbx", self), kMaxObstacleTriangles);
    EXPECT_NE(m.find("cannot read it: FBX model 1000003 is its own ancestor (through FBX model "
                     "1000003): the scene graph must not loop"),
              std::string::npos)
        << m;
    // An object-property link ("OP") is not a parent link: the cube loads.
    std::string property = cube;
    property.replace(property.find(links), links.size(),
                     links + "\tC: \"OP\", 1000003, 1000003, \"Lcl Translation\"\n");
    EXPECT_EQ(loadObstacleMesh(writeFile("property.fbx", property)).triangleCount(), 12u);

    std::string deep = cube;
    std::string nest;
    for (int i = 0; i < 300; ++i)
        nest += "A: {";
    for (int i = 0; i < 300; ++i)
        nest += "}";
    deep += "\n" + nest + "\n";
    const std::string d =
        messageOf<LimitExceeded>(writeFile("deep.fbx", deep), kMaxObstacleTriangles);
    EXPECT_NE(d.find("FBX scopes nested more than 256 deep"), std::string::npos) << d;

    // Binary: two models, each the other's parent, under the root.
    const std::string magic = std::string("Kaydara FBX Binary  \0\x1a\0", 23);
    const std::uint32_t version = 7500;
    std::string binary = magic + std::string(reinterpret_cast<const char*>(&version), 4);
    auto model = [&](std::size_t at, std::int64_t id) {
        return fbxRecord(at, "Model", fbxLong(id) + fbxString("Model::m") + fbxString("Null"), 3,
                         {});
    };
    auto connection = [&](std::size_t at, std::int64_t child, std::int64_t parent) {
        return fbxRecord(at, "C", fbxString("OO") + fbxLong(child) + fbxLong(parent), 3, {});
    };
    // Offsets are absolute: lay the records out one after the other.
    std::size_t at = binary.size();
    const std::size_t objectsHeader = 3 * 8 + 1 + std::string("Objects").size();
    const std::string m1 = model(at + objectsHeader, 1);
    const std::string m2 = model(at + objectsHeader + m1.size(), 2);
    const std::string objects = fbxRecord(at, "Objects", "", 0, {m1, m2});
    binary += objects;
    at = binary.size();
    const std::size_t connectionsHeader = 3 * 8 + 1 + std::string("Connections").size();
    std::vector<std::string> cs;
    std::size_t c = at + connectionsHeader;
    for (const auto& [child, parent] : {std::pair{1, 0}, std::pair{2, 1}, std::pair{1, 2}}) {
        cs.push_back(connection(c, child, parent));
        c += cs.back().size();
    }
    binary += fbxRecord(at, "Connections", "", 0, cs);
    binary += std::string(25, '\0'); // the footer starts with a null record
    const std::string b =
        messageOf<InvalidInput>(writeFile("loop-binary.fbx", binary), kMaxObstacleTriangles);
    EXPECT_NE(b.find("FBX model 1 is its own ancestor (through FBX model 2)"), std::string::npos)
        << b;
    // A record that ends past the file: refused as Assimp's tokenizer refuses it.
    std::string cut = binary.substr(0, binary.size() - 60);
    const std::string t =
        messageOf<InvalidInput>(writeFile("cut-binary.fbx", cut), kMaxObstacleTriangles);
    EXPECT_NE(t.find("binary FBX record at byte"), std::string::npos) << t;
}

// Finding 30 (by reading Assimp 5.2.5's glTF importer, after 28 and 29): a node listed as a
// child by several nodes is copied under each, so 30 nodes each listing the next twice asked
// for 2^30 nodes (out of memory). Refused with the scene-graph limits; a loop (which Assimp
// refuses itself) is refused by the same walk, and the binary triangle still loads.
TEST(MeshFileCheck, GltfNodeHierarchiesAreBounded) {
    std::string nodes;
    for (int i = 0; i < 30; ++i)
        nodes += R"({"children":[)" + std::to_string(i + 1) + "," + std::to_string(i + 1) + "]},";
    nodes += R"({"name":"leaf"})";
    const std::string doubling = R"({"asset":{"version":"2.0"},"scene":0,"scenes":[{"nodes":[0]}],)"
                                 R"("nodes":[)" +
                                 nodes + "]}";
    const std::string m =
        messageOf<LimitExceeded>(writeFile("doubling.gltf", doubling), kMaxObstacleTriangles);
    EXPECT_NE(m.find("cannot read it: glTF nodes[14] holds more than 100000 nodes once the nodes "
                     "listed as children more than once are copied under each"),
              std::string::npos)
        << m;
    const std::string loop = R"({"asset":{"version":"2.0"},"nodes":[{"children":[1]},)"
                             R"({"children":[0]}]})";
    const std::string l =
        messageOf<InvalidInput>(writeFile("loop.gltf", loop), kMaxObstacleTriangles);
    EXPECT_NE(l.find("glTF nodes[0] is its own ancestor (through nodes[1]): the scene graph "
                     "must not loop"),
              std::string::npos)
        << l;
    EXPECT_EQ(loadObstacleMesh(writeFile("tri.glb", glbTriangle())).triangleCount(), 1u);
}

// Fuzz finding 31 (ASan and valgrind, the final run, after 1,003,132 executions): when every
// importer of a file's extension refuses it, Assimp 5.2.5 tries all of its importers on the
// content. A `.glb` whose magic was pushed back by "indexarray" was read by the OpenGEX importer
// (which looks for "IndexArray" in any case), and that read past its buffer. Only the importers
// of the file's extension are kept; a file whose extension no importer claims is refused.
TEST(MeshFileCheck, OnlyTheImportersOfTheExtensionReadTheFile) {
    const std::string moved =
        std::string("indexarrayglTF\x02\0\0\0\0\0\0\x01\0\0\0e\x01\0\0\0\0\0\0\0%a\0p ", 40);
    const std::string m =
        messageOf<InvalidInput>(writeFile("moved.glb", moved), kMaxObstacleTriangles);
    EXPECT_NE(m.find("cannot read it: No suitable reader found"), std::string::npos) << m;
    const std::string none =
        messageOf<InvalidInput>(writeFile("cube.abc", "v 0 0 0\n"), kMaxObstacleTriangles);
    EXPECT_NE(none.find("cannot read it: no importer reads '.abc' files; use OBJ, PLY, STL, glTF "
                        "(.gltf, .glb), FBX or Collada (.dae)"),
              std::string::npos)
        << none;
    // The extension in any case.
    EXPECT_EQ(loadObstacleMesh(writeFile("tri.OBJ", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n"))
                  .triangleCount(),
              1u);
}
