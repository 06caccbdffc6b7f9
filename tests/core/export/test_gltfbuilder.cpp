#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <limits>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include <assimp/Importer.hpp>
#include <assimp/scene.h>

#include "engine/export/gltf/forestgltf.h"
#include "engine/export/gltf/gltfbuilder.h"
#include "engine/export/gltf/gltfmesh.h"
#include "engine/export/treeexport.h"
#include "engine/util/error.h"

using namespace sylva;
using namespace sylva::exporter::gltf;
namespace fs = std::filesystem;

namespace {

fs::path tempDir(const std::string& name) {
    auto dir = fs::temp_directory_path() / ("sylva_gltf_" + name);
    fs::remove_all(dir);
    fs::create_directories(dir);
    return dir;
}

std::string readFile(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

std::uint32_t u32At(const std::string& s, std::size_t at) {
    std::uint32_t v = 0;
    std::memcpy(&v, s.data() + at, 4);
    return v;
}

std::size_t filesIn(const fs::path& dir) {
    return static_cast<std::size_t>(
        std::distance(fs::directory_iterator(dir), fs::directory_iterator()));
}

// A skinned, animated triangle with a custom attribute, an instanced node, an LOD extension and
// an embedded image: every feature the forest, wind and LOD writers use.
void buildSample(GltfBuilder& b) {
    const std::vector<glm::vec3> positions = {{-1, 0, 0}, {1, 0, 0.5f}, {0, 2, -0.25f}};
    const std::vector<glm::vec3> normals = {{0, 0, 1}, {0, 0, 1}, {0, 0, 1}};
    const std::vector<glm::vec2> uvs = {{0, 0}, {1, 0}, {0.5f, 1}};
    const std::vector<std::uint16_t> joints = {0, 0, 0, 0, 0, 1, 0, 0, 1, 0, 0, 0};
    const std::vector<glm::vec4> weights = {{1, 0, 0, 0}, {0.5f, 0.5f, 0, 0}, {1, 0, 0, 0}};
    const std::vector<std::uint8_t> order = {0, 1, 2}; // 1 byte a vertex: padded to a 4-byte stride
    const std::vector<float> wind = {0.0f, 0.5f, 1.0f};
    const std::vector<std::uint32_t> indices = {0, 1, 2};

    Primitive p;
    p.attributes = {{"POSITION", b.addVec3(positions, Target::ArrayBuffer, true)},
                    {"NORMAL", b.addVec3(normals)},
                    {"TEXCOORD_0", b.addVec2(uvs)},
                    {"JOINTS_0", b.addUint16(joints, 4)},
                    {"WEIGHTS_0", b.addVec4(weights)},
                    {"_ORDER", b.addUint8(order, 1)},
                    {"_WIND", b.addFloats(wind, Target::ArrayBuffer)}};
    p.indices = b.addIndices(indices);
    const std::string png = "\x89PNG\r\n\x1a\nnot really a png"; // 25 bytes: forces padding
    const int image =
        b.addImage(std::as_bytes(std::span(png.data(), png.size())), "image/png", "bark");
    const int texture = b.addTexture(image, b.addSampler({{"magFilter", 9729}}));
    p.material = b.addMaterial(
        {{"name", "bark"}, {"pbrMetallicRoughness", {{"baseColorTexture", {{"index", texture}}}}}});
    const int mesh = b.addMesh("tree", {p}, {{"sylva", "test"}});

    Node root;
    root.name = "root";
    const int rootNode = b.addNode(root);
    Node bone;
    bone.name = "bone";
    bone.translation = {0, 1, 0};
    const int boneNode = b.addNode(bone);
    b.addChild(rootNode, boneNode);
    const std::vector<glm::mat4> ibm = {glm::mat4(1.0f),
                                        glm::mat4(glm::vec4(1, 0, 0, 0), glm::vec4(0, 1, 0, 0),
                                                  glm::vec4(0, 0, 1, 0), glm::vec4(0, -1, 0, 1))};
    const int skin = b.addSkin({"rig", b.addMat4(ibm), {rootNode, boneNode}, rootNode});

    Node skinned;
    skinned.name = "tree_42";
    skinned.mesh = mesh;
    skinned.skin = skin;
    skinned.extras = {{"id", 42}};
    const int treeNode = b.addNode(skinned);

    const std::vector<float> times = {0.0f, 1.0f, 2.0f};
    const std::vector<glm::quat> keys = {
        glm::quat(1, 0, 0, 0), glm::quat(0.9950042f, 0.0998334f, 0, 0), glm::quat(1, 0, 0, 0)};
    const int input = b.addFloats(times, Target::None, true);
    b.addAnimation({"wind", {{input, b.addQuats(keys), "LINEAR"}}, {{0, boneNode, "rotation"}}});

    // Two instances of the mesh through EXT_mesh_gpu_instancing, with an _ID attribute.
    const std::vector<glm::vec3> t = {{5, 0, 0}, {10, 0, 3}};
    const std::vector<glm::quat> r = {glm::quat(1, 0, 0, 0),
                                      glm::quat(0.7071068f, 0, 0.7071068f, 0)};
    const std::vector<glm::vec3> s = {{1, 1, 1}, {1.5f, 1.5f, 1.5f}};
    const std::vector<float> ids = {7.0f, 8.0f};
    Node instanced;
    instanced.name = "cell_0_0";
    instanced.mesh = mesh;
    instanced.extensions = {{"EXT_mesh_gpu_instancing",
                             {{"attributes",
                               {{"TRANSLATION", b.addVec3(t, Target::None)},
                                {"ROTATION", b.addQuats(r)},
                                {"SCALE", b.addVec3(s, Target::None)},
                                {"_ID", b.addFloats(ids)}}}}}};
    const int instNode = b.addNode(instanced);
    b.useExtension("EXT_mesh_gpu_instancing");
    b.useExtension("EXT_mesh_gpu_instancing"); // listed once
    b.node(treeNode)["extensions"]["MSFT_lod"] = {{"ids", Json::array({instNode})}};
    b.useExtension("MSFT_lod");
    b.addScene("forest", {rootNode, treeNode});
}

struct ParsedGlb {
    std::uint32_t magic = 0, version = 0, length = 0;
    std::uint32_t jsonLength = 0, jsonType = 0, binLength = 0, binType = 0;
    std::string jsonText;
    std::string bin;
    Json json;
};

ParsedGlb parseGlb(const std::string& bytes) {
    ParsedGlb g;
    g.magic = u32At(bytes, 0);
    g.version = u32At(bytes, 4);
    g.length = u32At(bytes, 8);
    g.jsonLength = u32At(bytes, 12);
    g.jsonType = u32At(bytes, 16);
    g.jsonText = bytes.substr(20, g.jsonLength);
    const std::size_t bin = 20 + g.jsonLength;
    g.binLength = u32At(bytes, bin);
    g.binType = u32At(bytes, bin + 4);
    g.bin = bytes.substr(bin + 8, g.binLength);
    g.json = Json::parse(g.jsonText);
    return g;
}

template <class T> std::vector<T> readAccessor(const ParsedGlb& g, int accessor, int components) {
    const Json& a = g.json["accessors"][static_cast<std::size_t>(accessor)];
    const Json& v = g.json["bufferViews"][a["bufferView"].get<std::size_t>()];
    const std::size_t count = a["count"].get<std::size_t>() * static_cast<std::size_t>(components);
    std::vector<T> out(count);
    std::memcpy(out.data(), g.bin.data() + v["byteOffset"].get<std::size_t>(), count * sizeof(T));
    return out;
}

} // namespace

TEST(GltfBuilder, GlbChunksArePaddedAndBoundsMatchTheData) {
    const fs::path dir = tempDir("layout");
    const fs::path path = dir / "sample.glb";
    {
        GltfBuilder b(path, GltfFormat::Glb);
        buildSample(b);
        EXPECT_FALSE(fs::exists(path)); // nothing at the path before finish()
        EXPECT_EQ(b.finish(), std::vector<fs::path>{path});
    }
    EXPECT_EQ(filesIn(dir), 1u); // the temporary is gone
    const std::string bytes = readFile(path);
    const ParsedGlb g = parseGlb(bytes);
    EXPECT_EQ(g.magic, 0x46546C67u);
    EXPECT_EQ(g.version, 2u);
    EXPECT_EQ(g.length, bytes.size());
    EXPECT_EQ(g.jsonType, 0x4E4F534Au);
    EXPECT_EQ(g.binType, 0x004E4942u);
    EXPECT_EQ(g.jsonLength % 4, 0u);
    EXPECT_EQ(g.binLength % 4, 0u);
    EXPECT_EQ(20 + g.jsonLength + 8 + g.binLength, bytes.size());
    // The JSON chunk is padded with spaces, never zeros.
    EXPECT_EQ(g.jsonText.find('\0'), std::string::npos);
    EXPECT_EQ(g.json["buffers"][0]["byteLength"].get<std::uint32_t>(), g.binLength);
    EXPECT_FALSE(g.json["buffers"][0].contains("uri"));

    // Every bufferView starts on 4 bytes and lies inside the BIN chunk.
    for (const Json& v : g.json["bufferViews"]) {
        EXPECT_EQ(v["byteOffset"].get<std::size_t>() % 4, 0u);
        EXPECT_LE(v["byteOffset"].get<std::size_t>() + v["byteLength"].get<std::size_t>(),
                  g.binLength);
        EXPECT_EQ(v.value("byteStride", 0) % 4, 0);
    }

    const Json& prim = g.json["meshes"][0]["primitives"][0];
    const int pos = prim["attributes"]["POSITION"].get<int>();
    const Json& acc = g.json["accessors"][static_cast<std::size_t>(pos)];
    EXPECT_EQ(acc["min"], Json::array({-1.0, 0.0, -0.25}));
    EXPECT_EQ(acc["max"], Json::array({1.0, 2.0, 0.5}));
    const auto positions = readAccessor<float>(g, pos, 3);
    EXPECT_EQ(positions, (std::vector<float>{-1, 0, 0, 1, 0, 0.5f, 0, 2, -0.25f}));
    // Custom attributes keep their names; a one-byte attribute gets a 4-byte stride.
    EXPECT_TRUE(prim["attributes"].contains("_WIND"));
    const Json& orderAcc = g.json["accessors"][prim["attributes"]["_ORDER"].get<std::size_t>()];
    EXPECT_EQ(orderAcc["componentType"], 5121);
    EXPECT_EQ(g.json["bufferViews"][orderAcc["bufferView"].get<std::size_t>()]["byteStride"], 4);
    // Small meshes use 16-bit indices.
    EXPECT_EQ(g.json["accessors"][prim["indices"].get<std::size_t>()]["componentType"], 5123);

    EXPECT_EQ(g.json["extensionsUsed"], Json::array({"EXT_mesh_gpu_instancing", "MSFT_lod"}));
    EXPECT_FALSE(g.json.contains("extensionsRequired"));
    EXPECT_EQ(g.json["scene"], 0);
    EXPECT_EQ(g.json["nodes"][0]["children"], Json::array({1}));
    EXPECT_EQ(g.json["nodes"][1]["translation"], Json::array({0.0, 1.0, 0.0}));
    EXPECT_EQ(g.json["nodes"][2]["extras"]["id"], 42);
    EXPECT_EQ(g.json["skins"][0]["joints"], Json::array({0, 1}));
    EXPECT_EQ(g.json["animations"][0]["channels"][0]["target"]["path"], "rotation");
    const Json& input =
        g.json["accessors"][g.json["animations"][0]["samplers"][0]["input"].get<std::size_t>()];
    EXPECT_EQ(input["min"], Json::array({0.0}));
    EXPECT_EQ(input["max"], Json::array({2.0}));
    const Json& inst = g.json["nodes"][3]["extensions"]["EXT_mesh_gpu_instancing"]["attributes"];
    const auto rotations = readAccessor<float>(g, inst["ROTATION"].get<int>(), 4);
    EXPECT_FLOAT_EQ(rotations[4 + 1], 0.7071068f); // y of the second quaternion: x, y, z, w
    EXPECT_FLOAT_EQ(rotations[4 + 3], 0.7071068f);
    EXPECT_EQ(readAccessor<float>(g, inst["_ID"].get<int>(), 1), (std::vector<float>{7, 8}));
    // The embedded image's bytes come back as they went in.
    const Json& img = g.json["images"][0];
    EXPECT_EQ(img["mimeType"], "image/png");
    const Json& iv = g.json["bufferViews"][img["bufferView"].get<std::size_t>()];
    EXPECT_EQ(
        g.bin.substr(iv["byteOffset"].get<std::size_t>(), iv["byteLength"].get<std::size_t>()),
        std::string("\x89PNG\r\n\x1a\nnot really a png"));
}

TEST(GltfBuilder, SameCallsGiveByteIdenticalFiles) {
    const fs::path dir = tempDir("determinism");
    for (const char* name : {"a.glb", "b.glb"}) {
        GltfBuilder b(dir / name, GltfFormat::Glb);
        buildSample(b);
        b.finish();
    }
    const std::string a = readFile(dir / "a.glb");
    EXPECT_FALSE(a.empty());
    EXPECT_EQ(a, readFile(dir / "b.glb"));
}

TEST(GltfBuilder, TextGltfReferencesItsBin) {
    const fs::path dir = tempDir("text");
    GltfBuilder b(dir / "sample.gltf", GltfFormat::Gltf);
    buildSample(b);
    const auto written = b.finish();
    ASSERT_EQ(written.size(), 2u);
    EXPECT_EQ(written[1], dir / "sample.bin");
    EXPECT_EQ(filesIn(dir), 2u);
    const Json json = Json::parse(readFile(dir / "sample.gltf"));
    EXPECT_EQ(json["buffers"][0]["uri"], "sample.bin");
    EXPECT_EQ(json["buffers"][0]["byteLength"].get<std::uintmax_t>(),
              fs::file_size(dir / "sample.bin"));
    // The same binary as the GLB's BIN chunk.
    GltfBuilder g(dir / "sample.glb", GltfFormat::Glb);
    buildSample(g);
    g.finish();
    EXPECT_EQ(parseGlb(readFile(dir / "sample.glb")).bin, readFile(dir / "sample.bin"));
}

TEST(GltfBuilder, AssimpReadsTheGlb) {
    const fs::path dir = tempDir("assimp");
    GltfBuilder b(dir / "sample.glb", GltfFormat::Glb);
    buildSample(b);
    b.finish();
    Assimp::Importer importer;
    const aiScene* scene = importer.ReadFile((dir / "sample.glb").string(), 0);
    ASSERT_NE(scene, nullptr) << importer.GetErrorString();
    ASSERT_GE(scene->mNumMeshes, 1u);
    EXPECT_EQ(scene->mMeshes[0]->mNumVertices, 3u);
    EXPECT_EQ(scene->mMeshes[0]->mNumBones, 2u);
    EXPECT_EQ(scene->mNumAnimations, 1u);
}

namespace {
class CancelAfter : public Progress {
public:
    explicit CancelAfter(int calls) : mLeft(calls) {}
    bool isCancelled() const override { return --mLeft < 0; }

private:
    mutable int mLeft;
};
} // namespace

TEST(GltfBuilder, CancelLeavesNoFile) {
    const fs::path dir = tempDir("cancel");
    // While adding arrays (the sample adds 16), and at each of finish()'s three checks.
    for (int calls : {3, 16, 17, 18}) {
        CancelAfter progress(calls);
        EXPECT_THROW(
            {
                GltfBuilder b(dir / "sample.glb", GltfFormat::Glb, progress);
                buildSample(b);
                b.finish();
            },
            Cancelled);
        EXPECT_EQ(filesIn(dir), 0u);
    }
}

TEST(GltfBuilder, NonFiniteNumbersAreRefused) {
    const fs::path dir = tempDir("nan");
    GltfBuilder b(dir / "bad.glb", GltfFormat::Glb);
    Node n;
    n.extras = {{"value", std::numeric_limits<double>::quiet_NaN()}};
    b.addNode(n);
    try {
        b.finish();
        ADD_FAILURE() << "a NaN was written";
    } catch (const InvalidInput& e) {
        EXPECT_NE(std::string(e.what()).find("/nodes/0/extras/value"), std::string::npos)
            << e.what();
    }
    EXPECT_FALSE(fs::exists(dir / "bad.glb"));
}

TEST(GltfMesh, SubmeshesShareVerticesAndTexturesAreEmbeddedOnce) {
    const fs::path dir = tempDir("mesh");
    mesh::Mesh m;
    m.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0}};
    m.normals = {{0, 0, 2}, {0, 0, 1}, {0, 0, 0}, {0, 0, 1}}; // not unit, one zero
    m.uvs = {{0, 0}, {1, 0}, {0, 1}, {1, 1}};
    m.indices = {0, 1, 2, 1, 3, 2};
    const std::string leaf = std::string(SYLVA_PRESETS_DIR) + "/textures/english-oak_leaf.png";
    m.submeshes = {{"bark", 0, 3, ""}, {"leaf", 3, 3, leaf}};
    std::vector<exporter::Material> materials = exporter::defaultMaterials();
    exporter::addMaterialsOf(m, materials);
    {
        GltfBuilder b(dir / "tree.glb", GltfFormat::Glb);
        MaterialTable table(b, materials, fs::path(SYLVA_PRESETS_DIR) / "textures", true);
        const std::vector<float> flex = {0, 0.25f, 0.5f, 1};
        const int first =
            addTreeMesh(b, m, "oak", table, {{"_FLEX", b.addFloats(flex, Target::ArrayBuffer)}});
        const int second = addTreeMesh(b, m, "oak2", table);
        EXPECT_EQ(first, 0);
        EXPECT_EQ(second, 1);
        b.addScene("", {});
        b.finish();
    }
    const ParsedGlb g = parseGlb(readFile(dir / "tree.glb"));
    const Json& prims = g.json["meshes"][0]["primitives"];
    ASSERT_EQ(prims.size(), 2u);
    EXPECT_EQ(prims[0]["attributes"], prims[1]["attributes"]); // one vertex set
    EXPECT_TRUE(prims[0]["attributes"].contains("_FLEX"));
    EXPECT_FALSE(g.json["meshes"][1]["primitives"][0]["attributes"].contains("_FLEX"));
    // Two materials, each made once although two meshes use them; one embedded texture (the
    // shipped bark.png is not in the presets folder given, so bark keeps its colour).
    ASSERT_EQ(g.json["materials"].size(), 2u);
    EXPECT_EQ(g.json["materials"][0]["name"], "bark");
    EXPECT_TRUE(g.json["materials"][0]["pbrMetallicRoughness"].contains("baseColorFactor"));
    EXPECT_EQ(g.json["materials"][1]["name"], "english-oak_leaf");
    EXPECT_EQ(g.json["materials"][1]["alphaMode"], "MASK");
    EXPECT_EQ(g.json["materials"][1]["doubleSided"], true);
    // The leaf's colour, normal and roughness maps: three images, bark's maps are shipped
    // files not in the folder given.
    ASSERT_EQ(g.json["images"].size(), 3u);
    EXPECT_EQ(g.json["images"][0]["mimeType"], "image/png");
    const Json& leafMaterial = g.json["materials"][1];
    ASSERT_TRUE(leafMaterial.contains("normalTexture"));
    ASSERT_TRUE(leafMaterial["pbrMetallicRoughness"].contains("metallicRoughnessTexture"));
    EXPECT_EQ(leafMaterial["pbrMetallicRoughness"]["roughnessFactor"], 1.0);
    EXPECT_EQ(leafMaterial["pbrMetallicRoughness"]["metallicFactor"], 0.0);
    const int normalImage =
        g.json["textures"][leafMaterial["normalTexture"]["index"].get<int>()]["source"].get<int>();
    EXPECT_EQ(g.json["images"][normalImage]["name"], "english-oak_leaf_normal");
    EXPECT_FALSE(g.json["materials"][0].contains("normalTexture"));
    const auto normals = readAccessor<float>(g, prims[0]["attributes"]["NORMAL"].get<int>(), 3);
    EXPECT_EQ(normals, (std::vector<float>{0, 0, 1, 0, 0, 1, 0, 1, 0, 0, 0, 1}));
    // glTF's uv origin is the image's top-left: v is stored as 1 - v.
    const auto uvs = readAccessor<float>(g, prims[0]["attributes"]["TEXCOORD_0"].get<int>(), 2);
    EXPECT_EQ(uvs, (std::vector<float>{0, 1, 1, 1, 0, 0, 1, 0}));
}

TEST(GltfMesh, LeafTintsAreColor0AsNormalizedBytes) {
    // Mesh::colors are linear multipliers: COLOR_0 as glTF defines it, four normalized bytes.
    const fs::path dir = tempDir("color");
    mesh::Mesh m;
    m.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
    m.indices = {0, 1, 2};
    m.submeshes = {{"leaf", 0, 3, ""}};
    m.colors = {{255, 255, 255, 255}, {200, 180, 90, 255}, {64, 128, 32, 255}};
    {
        GltfBuilder b(dir / "tint.glb", GltfFormat::Glb);
        MaterialTable table(b, exporter::defaultMaterials(), {}, true);
        addTreeMesh(b, m, "tinted", table);
        m.colors.clear();
        addTreeMesh(b, m, "plain", table);
        b.addScene("", {});
        b.finish();
    }
    const ParsedGlb g = parseGlb(readFile(dir / "tint.glb"));
    const Json& attributes = g.json["meshes"][0]["primitives"][0]["attributes"];
    ASSERT_TRUE(attributes.contains("COLOR_0"));
    const Json& a = g.json["accessors"][attributes["COLOR_0"].get<std::size_t>()];
    EXPECT_EQ(a["componentType"], 5121);
    EXPECT_EQ(a["type"], "VEC4");
    EXPECT_EQ(a["normalized"], true);
    const auto bytes = readAccessor<std::uint8_t>(g, attributes["COLOR_0"].get<int>(), 4);
    EXPECT_EQ(bytes,
              (std::vector<std::uint8_t>{255, 255, 255, 255, 200, 180, 90, 255, 64, 128, 32, 255}));
    EXPECT_FALSE(g.json["meshes"][1]["primitives"][0]["attributes"].contains("COLOR_0"));
}

namespace {
mesh::Mesh triangle(float size) {
    mesh::Mesh m;
    m.positions = {{0, 0, 0}, {size, 0, 0}, {0, size, 0}};
    m.normals = {{0, 0, 1}, {0, 0, 1}, {0, 0, 1}};
    m.uvs = {{0, 0}, {1, 0}, {0, 1}};
    m.indices = {0, 1, 2};
    return m;
}
} // namespace

TEST(ForestGltf, InstancesGoByCellAndVariantWithTheirIds) {
    const fs::path dir = tempDir("forest");
    {
        ForestGltfOptions options;
        options.cellSize = 10.0f;
        ForestGltfWriter w(dir / "f.glb", GltfFormat::Glb, noProgress(), options);
        const mesh::Mesh a = triangle(1), b = triangle(2), empty;
        EXPECT_EQ(w.addVariant("oak_v0", a), 0);
        EXPECT_EQ(w.addVariant("oak_v1", b), 1);
        EXPECT_EQ(w.addVariant("oak_v2", empty), 2);
        const glm::quat turn = glm::angleAxis(1.0f, glm::vec3(0, 1, 0));
        // Cell (0,0): two of v0 and one of v1; cell (-1,0): one of v0; an empty variant's tree.
        w.addInstance(0, 11, {1, 0, 1}, turn, glm::vec3(1.5f));
        w.addInstance(1, 12, {2, 0, 2}, turn, glm::vec3(1.0f));
        w.addInstance(0, 13, {9, 0, 9}, turn, glm::vec3(0.5f));
        w.addInstance(0, 14, {-3, 0, 4}, turn, glm::vec3(1.0f));
        w.addInstance(2, 15, {5, 0, 5}, turn, glm::vec3(1.0f));
        EXPECT_THROW(w.addInstance(3, 16, {}, turn, glm::vec3(1)), InvalidInput);
        const int mesh = w.addTreeMesh("oak_20", b);
        w.addTree("oak_20", 20, mesh, {25, 1, -5}, turn, glm::vec3(2.0f));
        EXPECT_EQ(w.instanceCount(), 5u);
        w.commit();
    }
    const ParsedGlb g = parseGlb(readFile(dir / "f.glb"));
    const Json& nodes = g.json["nodes"];
    EXPECT_EQ(g.json["extensionsUsed"], Json::array({"EXT_mesh_gpu_instancing"}));
    EXPECT_FALSE(g.json.contains("extensionsRequired")); // older readers still open it
    EXPECT_EQ(g.json["meshes"].size(), 3u);              // v0, v1, the unique tree; v2 empty
    EXPECT_EQ(nodes[0]["name"], "sylva");
    std::vector<std::string> cells;
    for (const Json& c : nodes[0]["children"])
        cells.push_back(nodes[c.get<std::size_t>()]["name"]);
    EXPECT_EQ(cells, (std::vector<std::string>{"cell_-1_0", "cell_0_0", "cell_2_-1"}));
    const auto child = [&](const std::string& name) -> const Json& {
        for (const Json& n : nodes)
            if (n.value("name", "") == name) return n;
        throw std::runtime_error("no node " + name);
    };
    const Json& v0 = child("oak_v0_cell_0_0");
    EXPECT_EQ(v0["extras"]["sylva_ids"], Json::array({11, 13}));
    EXPECT_EQ(v0["translation"], Json::array({1.0, 0.0, 1.0})); // at its first instance
    const Json& attributes = v0["extensions"]["EXT_mesh_gpu_instancing"]["attributes"];
    // Translations are relative to the node; rotations and scales as given.
    EXPECT_EQ(readAccessor<float>(g, attributes["TRANSLATION"].get<int>(), 3),
              (std::vector<float>{0, 0, 0, 8, 0, 8}));
    EXPECT_EQ(readAccessor<float>(g, attributes["SCALE"].get<int>(), 3),
              (std::vector<float>{1.5f, 1.5f, 1.5f, 0.5f, 0.5f, 0.5f}));
    const auto r = readAccessor<float>(g, attributes["ROTATION"].get<int>(), 4);
    EXPECT_NEAR(r[1], std::sin(0.5f), 1e-6f);
    EXPECT_NEAR(r[3], std::cos(0.5f), 1e-6f);
    EXPECT_EQ(child("oak_v1_cell_0_0")["extras"]["sylva_ids"], Json::array({12}));
    EXPECT_EQ(child("oak_v0_cell_-1_0")["extras"]["sylva_ids"], Json::array({14}));
    const Json& empty = child("oak_v2_cell_0_0");
    EXPECT_FALSE(empty.contains("mesh"));
    EXPECT_FALSE(empty.contains("extensions"));
    EXPECT_EQ(empty["extras"]["sylva_ids"], Json::array({15}));
    const Json& unique = child("oak_20");
    EXPECT_EQ(unique["extras"]["sylva_id"], 20);
    EXPECT_EQ(unique["mesh"], 2);
    EXPECT_EQ(unique["scale"], Json::array({2.0, 2.0, 2.0}));
}

TEST(ForestGltf, TreeExporterInstancesVariantsAndSharesUniqueMeshes) {
    const fs::path dir = tempDir("treeexporter");
    auto variant = std::make_shared<const mesh::Mesh>(triangle(1));
    auto shared = std::make_shared<const mesh::Mesh>(triangle(3));
    {
        exporter::TreeExporter out(dir / "f.glb");
        out.addVariants({{"oak_v0", variant}});
        out.add({{"oak_1", variant, {1, 0, 1}, 0.5f, 1.0f, 0, 1},
                 {"oak_2", variant, {2, 0, 2}, 0.5f, 1.0f, 0, 2},
                 {"oak_3", shared, {3, 0, 3}, 0.0f, 1.0f, -1, 3},
                 {"oak_4", shared, {4, 0, 4}, 0.0f, 1.0f, -1, 4}});
        EXPECT_THROW(out.add({{"oak_5", variant, {}, 0.0f, 1.0f, 1, 5}}), InvalidInput);
        out.commit();
    }
    const ParsedGlb g = parseGlb(readFile(dir / "f.glb"));
    EXPECT_EQ(g.json["meshes"].size(), 2u); // the variant, and the unique trees' shared mesh
    std::size_t ids = 0, unique = 0;
    for (const Json& n : g.json["nodes"]) {
        if (n.contains("extras") && n["extras"].contains("sylva_ids"))
            ids += n["extras"]["sylva_ids"].size();
        if (n.contains("extras") && n["extras"].contains("sylva_id")) {
            ++unique;
            EXPECT_EQ(n["mesh"], 1);
        }
    }
    EXPECT_EQ(ids, 2u);
    EXPECT_EQ(unique, 2u);
}

// Where the file system can insert blocks (ext4, XFS) the BIN temporary becomes the .glb in
// place; elsewhere (tmpfs) the BIN chunk is copied. Both give the same bytes.
TEST(GltfBuilder, InPlaceAndCopiedGlbAreIdentical) {
    const fs::path shm = "/dev/shm";
    if (!fs::is_directory(shm)) GTEST_SKIP() << "no /dev/shm to write a copied GLB on";
    const fs::path dir = tempDir("inplace");
    const fs::path other = shm / "sylva_gltf_inplace.glb";
    for (const fs::path& path : {dir / "a.glb", other}) {
        GltfBuilder b(path, GltfFormat::Glb);
        buildSample(b);
        b.finish();
    }
    const std::string a = readFile(dir / "a.glb");
    EXPECT_EQ(a, readFile(other));
    fs::remove(other);
    // What precedes the BIN data ends on 4 KiB; the JSON's padding is spaces.
    const ParsedGlb g = parseGlb(a);
    EXPECT_EQ((20 + g.jsonLength + 8) % 4096, 0u);
    EXPECT_EQ(a.size(), 20 + g.jsonLength + 8 + g.binLength);
}
