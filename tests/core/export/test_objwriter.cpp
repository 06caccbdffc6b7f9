#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>

#include <omp.h>

#include <assimp/Importer.hpp>
#include <assimp/scene.h>

#include "../common/testwords.h"
#include "engine/export/obj/objwriter.h"
#include "engine/lsystem/turtle.h"
#include "engine/mesh/treemesh.h"
#include "engine/util/error.h"
#include "engine/util/random.h"

using namespace sylva;
using exporter::formatFixed;

namespace {

std::string fixedOracle(double v, int decimals) {
    char buf[128];
    std::snprintf(buf, sizeof buf, "%.*f", decimals, v);
    std::string s = buf;
    if (s.find('.') != std::string::npos) {
        while (s.back() == '0')
            s.pop_back();
        if (s.back() == '.') s.pop_back();
    }
    if (s == "-0") s = "0";
    return s;
}

mesh::Mesh triangleMesh() {
    mesh::Mesh m;
    m.positions = {{0, 0, 0}, {1.5f, 0, 0}, {0, 2, -0.25f}};
    m.normals = {{0, 0, 1}, {0, 0, 1}, {0, 0, 1}};
    m.uvs = {{0, 0}, {1, 0}, {0, 1}};
    m.indices = {0, 1, 2};
    return m;
}

mesh::Mesh treeMesh() {
    lsys::TurtleSettings t;
    t.angleDegrees = 30;
    t.width = 0.3;
    const auto s = lsys::interpret(sylva::testing::makeWord(sylva::testing::testTreeWord(7)), t);
    return mesh::buildTreeMesh(s, mesh::TreeMeshSettings{});
}

std::filesystem::path tempDir(const std::string& name) {
    auto dir = std::filesystem::temp_directory_path() / ("sylva_geometry_" + name);
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir);
    return dir;
}

} // namespace

TEST(ObjWriter, FixedFormattingMatchesPrintf) {
    Rng rng(7);
    char buf[64];
    for (int i = 0; i < 20000; ++i) {
        const int decimals = 1 + static_cast<int>(rng.below(9));
        double v = rng.uniform(-1.0, 1.0) * std::pow(10.0, rng.uniform(-7.0, 6.0));
        if (i % 10 == 0) v = std::round(v * 1000.0) / 1000.0; // values with trailing zeros
        // Stay away from exact .5 ties at the last decimal where printf and nearbyint may
        // legitimately round from different binary expansions.
        const double scaled = v * std::pow(10.0, decimals);
        if (std::abs(scaled - std::trunc(scaled) - 0.5) < 1e-6 ||
            std::abs(scaled - std::trunc(scaled) + 0.5) < 1e-6)
            continue;
        char* e = formatFixed(buf, v, decimals);
        ASSERT_EQ(std::string(buf, e), fixedOracle(v, decimals)) << v << " " << decimals;
    }
    char* e = formatFixed(buf, 0.0, 6);
    EXPECT_EQ(std::string(buf, e), "0");
    e = formatFixed(buf, -1e-9, 6);
    EXPECT_EQ(std::string(buf, e), "0");
    e = formatFixed(buf, 1e30, 6);
    EXPECT_EQ(std::string(buf, e), "1e+30");
}

TEST(ObjWriter, OneTriangleByHand) {
    const mesh::Mesh m = triangleMesh();
    std::string out;
    exporter::ObjOffsets offsets;
    exporter::appendObj(out, {"my tree", &m}, offsets);
    EXPECT_EQ(out, "o my_tree\n"
                   "v 0 0 0\nv 1.5 0 0\nv 0 2 -0.25\n"
                   "vt 0 0\nvt 1 0\nvt 0 1\n"
                   "vn 0 0 1\nvn 0 0 1\nvn 0 0 1\n"
                   "usemtl bark\n"
                   "f 1/1/1 2/2/2 3/3/3\n");
    EXPECT_EQ(offsets.v, 4u);
    // A second object continues the numbering; a transform moves positions.
    std::string second;
    exporter::ObjObject moved{"b", &m, glm::translate(glm::mat4(1.0f), glm::vec3(10, 0, 0))};
    exporter::ObjOptions noExtras;
    noExtras.uvs = false;
    noExtras.materials = false;
    exporter::appendObj(second, moved, offsets, noExtras);
    EXPECT_EQ(second, "o b\nv 10 0 0\nv 11.5 0 0\nv 10 2 -0.25\n"
                      "vn 0 0 1\nvn 0 0 1\nvn 0 0 1\n"
                      "f 4//4 5//5 6//6\n");
}

TEST(ObjWriter, ChunkedParallelOutputEqualsSequential) {
    const mesh::Mesh m = treeMesh();
    ASSERT_GT(m.vertexCount(), 40000u); // more than one chunk
    std::vector<exporter::ObjObject> objects{{"a", &m}, {"b", &m}};
    objects[1].transform = glm::rotate(glm::mat4(1.0f), 0.5f, glm::vec3(0, 1, 0));
    exporter::ObjOptions options;
    options.mtllib = "forest.mtl";
    std::string sequential = "mtllib forest.mtl\n";
    exporter::ObjOffsets offsets;
    for (const auto& o : objects)
        exporter::appendObj(sequential, o, offsets, options);
    const int saved = omp_get_max_threads();
    omp_set_num_threads(1);
    const std::string one = exporter::formatObj(objects, options);
    omp_set_num_threads(2);
    const std::string two = exporter::formatObj(objects, options);
    omp_set_num_threads(saved);
    EXPECT_EQ(one, sequential);
    EXPECT_EQ(two, sequential);
}

TEST(ObjWriter, FileIsWrittenAtomically) {
    const auto dir = tempDir("obj");
    const mesh::Mesh m = triangleMesh();
    exporter::writeObjFile(dir / "t.obj", {{"t", &m}});
    std::ifstream in(dir / "t.obj");
    std::stringstream ss;
    ss << in.rdbuf();
    EXPECT_EQ(ss.str().substr(0, 4), "o t\n");
    // A missing folder is an IoError and leaves nothing behind.
    EXPECT_THROW(exporter::writeObjFile(dir / "missing" / "t.obj", {{"t", &m}}), IoError);
    EXPECT_FALSE(std::filesystem::exists(dir / "missing"));
    // Cancelling midway leaves no partial file.
    struct Cancel : Progress {
        bool isCancelled() const override { return true; }
    } cancel;
    EXPECT_THROW(exporter::writeObjFile(dir / "c.obj", {{"t", &m}}, {}, cancel), Cancelled);
    EXPECT_FALSE(std::filesystem::exists(dir / "c.obj"));
    std::size_t files = 0;
    for (const auto& e : std::filesystem::directory_iterator(dir))
        files += e.is_regular_file();
    EXPECT_EQ(files, 1u); // no temporaries left
    std::filesystem::remove_all(dir);
}

TEST(ObjWriter, RelativeIndicesByHand) {
    const mesh::Mesh m = triangleMesh();
    std::string out;
    exporter::ObjOffsets offsets{5, 5, 5}; // relative indices do not depend on earlier objects
    exporter::ObjOptions options;
    options.relativeIndices = true;
    options.materials = false;
    exporter::appendObj(out, {"t", &m}, offsets, options);
    EXPECT_EQ(out, "o t\n"
                   "v 0 0 0\nv 1.5 0 0\nv 0 2 -0.25\n"
                   "vt 0 0\nvt 1 0\nvt 0 1\n"
                   "vn 0 0 1\nvn 0 0 1\nvn 0 0 1\n"
                   "f -3/-3/-3 -2/-2/-2 -1/-1/-1\n");
    options.uvs = false;
    out.clear();
    exporter::appendObj(out, {"t", &m}, offsets, options);
    EXPECT_NE(out.find("f -3//-3 -2//-2 -1//-1\n"), std::string::npos) << out;
}

// Oracle: Assimp reads the compact file (relative indices, fewer decimals) as the same
// geometry as the default one, to the documented precision.
TEST(ObjWriter, CompactOptionsReadBackLikeDefault) {
    const auto dir = tempDir("compact");
    const mesh::Mesh m = treeMesh();
    std::vector<exporter::ObjObject> objects{{"a", &m}, {"b", &m}};
    objects[1].transform = glm::translate(glm::mat4(1.0f), glm::vec3(3, 0, 1));
    exporter::writeObjFile(dir / "full.obj", objects);
    exporter::writeObjFile(dir / "compact.obj", objects, exporter::ObjOptions::compact());
    // Fewer decimals alone shrink the file (relative indices pay off only once absolute ones
    // grow longer than an object's vertex count, i.e. in forests: see docs/perf/geometry.md).
    exporter::ObjOptions decimalsOnly = exporter::ObjOptions::compact();
    decimalsOnly.relativeIndices = false;
    exporter::writeObjFile(dir / "decimals.obj", objects, decimalsOnly);
    EXPECT_LT(std::filesystem::file_size(dir / "decimals.obj"),
              std::filesystem::file_size(dir / "full.obj"));
    Assimp::Importer ia, ib;
    const aiScene* a = ia.ReadFile((dir / "full.obj").string(), 0);
    const aiScene* b = ib.ReadFile((dir / "compact.obj").string(), 0);
    ASSERT_TRUE(a && b) << ia.GetErrorString() << ib.GetErrorString();
    ASSERT_EQ(a->mNumMeshes, b->mNumMeshes);
    ASSERT_GE(a->mNumMeshes, 2u);
    for (unsigned k = 0; k < a->mNumMeshes; ++k) {
        const aiMesh* ma = a->mMeshes[k];
        const aiMesh* mb = b->mMeshes[k];
        ASSERT_EQ(ma->mNumFaces, mb->mNumFaces);
        ASSERT_EQ(ma->mNumVertices, mb->mNumVertices);
        for (unsigned f = 0; f < ma->mNumFaces; ++f) {
            ASSERT_EQ(ma->mFaces[f].mNumIndices, 3u);
            for (unsigned c = 0; c < 3; ++c) {
                const unsigned ia3 = ma->mFaces[f].mIndices[c], ib3 = mb->mFaces[f].mIndices[c];
                const aiVector3D d = ma->mVertices[ia3] - mb->mVertices[ib3];
                ASSERT_LE(d.Length(), 1e-4f) << "mesh " << k << " face " << f;
                const aiVector3D dn = ma->mNormals[ia3] - mb->mNormals[ib3];
                ASSERT_LE(dn.Length(), 2e-3f);
                const aiVector3D dt = ma->mTextureCoords[0][ia3] - mb->mTextureCoords[0][ib3];
                ASSERT_LE(dt.Length(), 1e-4f);
            }
        }
    }
    std::filesystem::remove_all(dir);
}
