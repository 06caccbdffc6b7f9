#include <gtest/gtest.h>

#include <atomic>
#include <filesystem>
#include <fstream>
#include <sstream>

#include <glm/gtc/packing.hpp>

#include "engine/export/fbx/sceneexport.h"
#include "engine/export/treeexport.h"
#include "engine/export/usd/usdcompose.h"
#include "engine/export/usd/usdformat.h"
#include "engine/export/usd/usdstagewriter.h"
#include "engine/util/error.h"

using namespace sylva;
using namespace sylva::exporter::usd;
namespace fs = std::filesystem;

namespace {

fs::path tempDir(const std::string& name) {
    auto dir = fs::temp_directory_path() / ("sylva_usd_" + name);
    fs::remove_all(dir);
    fs::create_directories(dir);
    return dir;
}

std::string readAll(const fs::path& p) {
    std::ifstream in(p, std::ios::binary);
    std::stringstream s;
    s << in.rdbuf();
    return s.str();
}

std::size_t count(const std::string& text, const std::string& what) {
    std::size_t n = 0;
    for (std::size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1))
        ++n;
    return n;
}

// Two triangles of bark (vertices 0..3) and one leaf triangle (vertices 4..6) in one mesh.
std::shared_ptr<const mesh::Mesh> barkAndLeaf(float size) {
    auto m = std::make_shared<mesh::Mesh>();
    m->positions = {{0, 0, 0}, {size, 0, 0}, {size, size, 0}, {0, size, 0},
                    {0, 2, 0}, {1, 2, 0},    {0, 3, 0}};
    // Bark's normals differ at its corners (written per vertex), the leaf's is flat (per face).
    m->normals = {{0, 0, 1}, {0.6f, 0, 0.8f}, {0.6f, 0.8f, 0}, {0, 0.6f, 0.8f},
                  {0, 0, 1}, {0, 0, 1},       {0, 0, 1}};
    m->uvs = {{0, 0}, {1, 0}, {1, 1}, {0, 1}, {0, 0}, {1, 0}, {0, 1}};
    m->indices = {0, 1, 2, 0, 2, 3, 4, 5, 6};
    m->submeshes = {{"bark", 0, 6, ""}, {"leaf", 6, 3, ""}};
    return m;
}

class CancelAfter : public Progress {
public:
    explicit CancelAfter(int checks) : mLeft(checks) {}
    bool isCancelled() const override { return --mLeft < 0; }

private:
    mutable std::atomic<int> mLeft;
};

UsdLayerOptions options(int tile = 0, int tiles = 1) {
    UsdLayerOptions o;
    o.species = {"English oak", "3-leaf"};
    o.tile = tile;
    o.tileCount = tiles;
    o.sceneKey = "k1";
    return o;
}

// A small forest: species 0 has two variants, species 1 one; trees 10, 11 unique.
void writeForest(UsdStageWriter& w, const std::vector<std::uint64_t>& ids) {
    w.setVariants({{0, 0, barkAndLeaf(1)}, {0, 1, barkAndLeaf(2)}, {1, 0, barkAndLeaf(3)}});
    std::vector<UsdTree> trees;
    for (std::uint64_t id : ids) {
        UsdTree t;
        t.id = id;
        t.species = static_cast<std::uint32_t>(id % 2);
        t.position = {static_cast<float>(id) * 1.5f, 0.25f, -static_cast<float>(id)};
        t.rotationY = 0.1f * static_cast<float>(id);
        t.scale = 0.9f;
        if (id == 10 || id == 11)
            t.mesh = barkAndLeaf(0.5f);
        else
            t.variant = t.species == 0 ? static_cast<std::int32_t>(id % 4 / 2) : 2;
        trees.push_back(t);
    }
    w.add(trees);
}

} // namespace

TEST(UsdFormat, PrimNamesAreIdentifiers) {
    EXPECT_EQ(primName("English oak"), "English_oak");
    EXPECT_EQ(primName("3-leaf"), "_3_leaf");
    EXPECT_EQ(primName(""), "_");
    EXPECT_EQ(primName("a_b9"), "a_b9");
}

TEST(UsdFormat, StringsAreEscaped) {
    EXPECT_EQ(usdString("say \"hi\"\\\n"), "\"say \\\"hi\\\"\\\\\\n\"");
}

TEST(UsdFormat, HalvesReadBackExactlyInFewDigits) {
    for (float v : {0.0f, 1.0f, -1.0f, 0.5f, 0.70710678f, -0.38268343f, 0.123456f, 65504.0f}) {
        std::string s;
        appendHalf(s, v);
        EXPECT_LE(s.size(), 8u) << s;
        EXPECT_EQ(glm::packHalf1x16(std::stof(s)), glm::packHalf1x16(v)) << v << " -> " << s;
    }
    std::string one;
    appendHalf(one, 1.0f);
    EXPECT_EQ(one, "1");
}

TEST(UsdFormat, QuaternionsInUsdOrderRealFirst) {
    std::string s;
    appendQuath(s, glm::quat(0.5f, 0.25f, -0.125f, 0.0f)); // glm: (w, x, y, z)
    EXPECT_EQ(s, "(0.5,0.25,-0.125,0)");
}

TEST(UsdFormat, FloatsRoundTrip) {
    std::string s;
    appendFloat(s, 14.325227f);
    EXPECT_EQ(s, "14.325227");
    EXPECT_EQ(std::stof(s), 14.325227f);
}

TEST(UsdStageWriter, WritesInstancersUniqueMeshesAndMaterials) {
    const fs::path dir = tempDir("stage");
    UsdStageWriter w(dir / "forest.usda", options());
    writeForest(w, {0, 1, 2, 3, 4, 5, 10, 11});
    w.commit();
    const std::string text = readAll(dir / "forest.usda");
    EXPECT_EQ(text.rfind("#usda 1.0\n", 0), 0u);
    EXPECT_NE(text.find("upAxis = \"Y\""), std::string::npos);
    EXPECT_NE(text.find("metersPerUnit = 1"), std::string::npos);
    EXPECT_NE(text.find("defaultPrim = \"Forest\""), std::string::npos);
    EXPECT_EQ(count(text, "def PointInstancer "), 2u);
    EXPECT_NE(text.find("def PointInstancer \"English_oak\""), std::string::npos);
    EXPECT_NE(text.find("def PointInstancer \"_3_leaf\""), std::string::npos);
    // Species 0: trees 0, 2, 4 (variants 0, 1, 0); species 1: trees 1, 3, 5.
    EXPECT_NE(text.find("int64[] ids = [0,2,4]"), std::string::npos);
    EXPECT_NE(text.find("int[] protoIndices = [0,1,0]"), std::string::npos);
    EXPECT_NE(text.find("int64[] ids = [1,3,5]"), std::string::npos);
    EXPECT_NE(text.find("int[] protoIndices = [0,0,0]"), std::string::npos);
    EXPECT_EQ(count(text, "over \"Prototypes\""), 2u);
    EXPECT_EQ(count(text, "def Xform \"variant_"), 3u);
    EXPECT_EQ(count(text, "kind = \"component\""), 3u + 2u);
    EXPECT_NE(text.find("def Xform \"tree_10\""), std::string::npos);
    EXPECT_NE(text.find("def Xform \"tree_11\""), std::string::npos);
    // Each material run its own Mesh with only its vertices: the leaf's 3, reindexed from 0.
    EXPECT_NE(text.find("int[] faceVertexIndices = [0,1,2]"), std::string::npos);
    // The bark's triangle pair (0,1,2),(0,2,3) is written as one quad.
    EXPECT_NE(text.find("int[] faceVertexCounts = [4]"), std::string::npos);
    EXPECT_NE(text.find("int[] faceVertexIndices = [0,1,2,3]"), std::string::npos);
    EXPECT_EQ(text.find("int[] faceVertexIndices = [0,1,2,0,2,3]"), std::string::npos);
    EXPECT_NE(text.find("normal3f[] normals = [(0,0,1)] (\n"), std::string::npos);
    EXPECT_EQ(count(text, "def Mesh \"bark\""), 5u);
    EXPECT_EQ(count(text, "def Mesh \"leaf\""), 5u);
    // st per vertex everywhere, normals per vertex on bark and per face on the flat leaf.
    EXPECT_EQ(count(text, "interpolation = \"vertex\""), 10u + 5u);
    EXPECT_EQ(count(text, "interpolation = \"uniform\""), 5u);
    EXPECT_EQ(count(text, "def Material "), 2u);
    EXPECT_NE(text.find("rel material:binding = </Forest/Materials/leaf>"), std::string::npos);
    EXPECT_NE(text.find("float inputs:opacityThreshold = 0.5"), std::string::npos);
    EXPECT_NE(text.find("asset inputs:file = @textures/leaf.png@"), std::string::npos);
    // The normal and roughness maps (issue 33) feed the surface, read raw, the normal remapped.
    EXPECT_NE(text.find("asset inputs:file = @textures/leaf_normal.png@"), std::string::npos);
    EXPECT_NE(text.find("asset inputs:file = @textures/bark_roughness.png@"), std::string::npos);
    EXPECT_EQ(count(text, "normal3f inputs:normal.connect = </Forest/Materials/"), 2u);
    EXPECT_EQ(count(text, "float inputs:roughness.connect = </Forest/Materials/"), 2u);
    EXPECT_EQ(count(text, "float4 inputs:bias = (-1, -1, -1, 0)"), 2u);
    EXPECT_EQ(count(text, "token inputs:sourceColorSpace = \"raw\""), 4u);
    EXPECT_EQ(w.stats().instances, 6u);
    EXPECT_EQ(w.stats().uniqueTrees, 2u);
    EXPECT_EQ(w.stats().prototypes, 3u);
    EXPECT_EQ(w.stats().meshes, 10u);
    // Balanced braces: every prim block closed.
    EXPECT_EQ(count(text, "{"), count(text, "}"));
}

TEST(UsdStageWriter, SameBytesWhateverTheBatches) {
    const fs::path dir = tempDir("batches");
    UsdStageWriter a(dir / "a.usda", options());
    writeForest(a, {0, 1, 2, 3, 4, 5, 10, 11});
    a.commit();
    // The same trees in two batches.
    UsdStageWriter c(dir / "c.usda", options());
    writeForest(c, {0, 1, 2});
    std::vector<UsdTree> rest;
    for (std::uint64_t id : {3, 4, 5, 10, 11}) {
        UsdTree t;
        t.id = id;
        t.species = static_cast<std::uint32_t>(id % 2);
        t.position = {static_cast<float>(id) * 1.5f, 0.25f, -static_cast<float>(id)};
        t.rotationY = 0.1f * static_cast<float>(id);
        t.scale = 0.9f;
        if (id == 10 || id == 11)
            t.mesh = barkAndLeaf(0.5f);
        else
            t.variant = t.species == 0 ? static_cast<std::int32_t>(id % 4 / 2) : 2;
        rest.push_back(t);
    }
    c.add(rest);
    c.commit();
    EXPECT_EQ(readAll(dir / "a.usda"), readAll(dir / "c.usda"));
    {
        UsdStageWriter never(dir / "never.usda", options());
        writeForest(never, {0, 1});
    }
    EXPECT_FALSE(fs::exists(dir / "never.usda")); // never committed: nothing at the path
    std::size_t files = 0;
    for (const auto& e : fs::directory_iterator(dir))
        files += e.is_regular_file() ? 1 : 0;
    EXPECT_EQ(files, 2u); // no temporary left
}

TEST(UsdStageWriter, ProtoIndicesFollowThePrototypesOrder) {
    // Variants numbered 3 and 7, handed over in reverse: protoIndices 0 and 1 by number.
    const fs::path dir = tempDir("protoorder");
    UsdStageWriter w(dir / "f.usda", options());
    w.setVariants({{0, 7, barkAndLeaf(1)}, {0, 3, barkAndLeaf(2)}});
    UsdTree a, b;
    a.id = 1;
    a.variant = 0; // variant 7
    b.id = 2;
    b.variant = 1; // variant 3
    w.add({a, b});
    w.commit();
    const std::string text = readAll(dir / "f.usda");
    EXPECT_NE(text.find("int[] protoIndices = [1,0]"), std::string::npos);
    EXPECT_NE(text.find("rel prototypes = [</Forest/Instancers/English_oak/Prototypes/variant_3>, "
                        "</Forest/Instancers/English_oak/Prototypes/variant_7>]"),
              std::string::npos);
}

TEST(UsdStageWriter, RefusesAVariantOfAnotherSpecies) {
    const fs::path dir = tempDir("badvariant");
    UsdStageWriter w(dir / "f.usda", options());
    w.setVariants({{0, 0, barkAndLeaf(1)}});
    UsdTree t;
    t.species = 1;
    t.variant = 0;
    EXPECT_THROW(w.add({t}), InvalidInput);
    UsdTree noMesh;
    EXPECT_THROW(w.add({noMesh}), InvalidInput);
}

TEST(UsdStageWriter, CancelledLeavesNothing) {
    const fs::path dir = tempDir("cancel");
    for (int checks : {0, 1, 2, 3}) {
        {
            UsdStageWriter w(dir / "f.usda", options());
            CancelAfter progress(checks);
            try {
                w.setVariants(
                    {{0, 0, barkAndLeaf(1)}, {0, 1, barkAndLeaf(2)}, {1, 0, barkAndLeaf(3)}});
                UsdTree t;
                t.id = 10;
                t.mesh = barkAndLeaf(1);
                w.add({t}, progress);
                w.commit(progress);
                ADD_FAILURE() << "not cancelled after " << checks << " checks";
            } catch (const Cancelled&) {
            }
        }
        EXPECT_TRUE(fs::is_empty(dir)) << checks;
    }
}

TEST(UsdStageWriter, TileLayersShareThePrototypesOfTheSingleRun) {
    const fs::path dir = tempDir("tile");
    UsdStageWriter w(dir / "t2.usda", options(1, 3));
    writeForest(w, {0, 1, 2, 10});
    w.commit();
    const std::string text = readAll(dir / "t2.usda");
    EXPECT_NE(text.find("int sylvaTile = 2"), std::string::npos);
    EXPECT_NE(text.find("int sylvaTiles = 3"), std::string::npos);
    EXPECT_NE(text.find("over \"English_oak\""), std::string::npos);
    EXPECT_NE(text.find("def PointInstancer \"English_oak_tile2\""), std::string::npos);
    EXPECT_NE(text.find("</Forest/Instancers/English_oak/Prototypes/variant_1>"),
              std::string::npos);
    EXPECT_EQ(readTileHeader(dir / "t2.usda").tile, 2);
    EXPECT_THROW(UsdStageWriter(dir / "bad.usda", options(3, 3)), InvalidInput);
}

TEST(UsdCompose, RootNamesEveryTileOnceRelativeToIt) {
    const fs::path dir = tempDir("compose");
    for (int t = 0; t < 3; ++t) {
        UsdStageWriter w(dir / "tiles" / ("f" + std::to_string(t + 1) + ".usda"), options(t, 3));
        writeForest(w, {static_cast<std::uint64_t>(t)});
        w.commit();
    }
    writeRootLayer(dir / "root.usda",
                   {dir / "tiles/f3.usda", dir / "tiles/f1.usda", dir / "tiles/f2.usda"});
    const std::string root = readAll(dir / "root.usda");
    EXPECT_NE(root.find("subLayers = [\n        @tiles/f1.usda@,\n        @tiles/f2.usda@,\n"
                        "        @tiles/f3.usda@\n    ]"),
              std::string::npos)
        << root;
    EXPECT_NE(root.find("upAxis = \"Y\""), std::string::npos);
    EXPECT_NE(root.find("defaultPrim = \"Forest\""), std::string::npos);

    EXPECT_THROW(writeRootLayer(dir / "bad.usda", {dir / "tiles/f1.usda", dir / "tiles/f2.usda"}),
                 InvalidInput);
    EXPECT_THROW(writeRootLayer(dir / "bad.usda", {dir / "tiles/f1.usda", dir / "tiles/f1.usda",
                                                   dir / "tiles/f2.usda", dir / "tiles/f3.usda"}),
                 InvalidInput);
    UsdLayerOptions other = options(1, 3);
    other.sceneKey = "k2";
    {
        UsdStageWriter w(dir / "other/f2.usda", other);
        w.commit();
    }
    EXPECT_THROW(writeRootLayer(dir / "bad.usda", {dir / "tiles/f1.usda", dir / "other/f2.usda",
                                                   dir / "tiles/f3.usda"}),
                 InvalidInput);
    EXPECT_FALSE(fs::exists(dir / "bad.usda"));
    std::ofstream(dir / "plain.usda") << "#usda 1.0\n(\n)\n";
    EXPECT_THROW(readTileHeader(dir / "plain.usda"), InvalidInput);
    EXPECT_THROW(readTileHeader(dir / "missing.usda"), IoError);
}

TEST(SceneExport, CancelledExportLeavesNoFile) {
    // Assimp cannot be interrupted: writeScene abandons its thread and throws Cancelled.
    const fs::path dir = tempDir("scenecancel");
    auto m = barkAndLeaf(1);
    exporter::SceneDesc scene;
    scene.meshes.push_back({"tree", m.get()});
    for (int i = 0; i < 200; ++i)
        scene.instances.push_back({"tree_" + std::to_string(i), 0, glm::vec3(float(i), 0, 0)});
    for (const char* name : {"f.fbx", "f.glb"}) {
        CancelAfter progress(0);
        EXPECT_THROW(
            exporter::writeScene(dir / name, scene, exporter::sceneFormatFor(dir / name), progress),
            Cancelled);
        EXPECT_TRUE(fs::is_empty(dir)) << name;
        exporter::writeScene(dir / name, scene, exporter::sceneFormatFor(dir / name));
        EXPECT_GT(fs::file_size(dir / name), 1000u);
        fs::remove(dir / name);
    }
}

TEST(TreeExporter, WritesUsdWithSpeciesAndVariantsByNumber) {
    // What every front door hands over: species and variants as numbers, the names only labels
    // (these say nothing of the species: nothing is parsed back out of them).
    const fs::path dir = tempDir("treeexporter");
    exporter::ForestWriterOptions options;
    options.species = {"english-oak", "birch"};
    exporter::TreeExporter out(dir / "f.usda", options);
    EXPECT_TRUE(out.writesInstances());
    out.addVariants({{"first", barkAndLeaf(1), 0, 0},
                     {"second_v7", barkAndLeaf(2), 0, 1},
                     {"third", barkAndLeaf(3), 1, 0}});
    out.add({{"x_1", barkAndLeaf(1), {1, 0, 0}, 0.5f, 1.0f, 1, 1, 0},
             {"y", barkAndLeaf(3), {2, 0, 0}, 0.0f, 1.0f, 2, 2, 1},
             {"english-oak_3", barkAndLeaf(0.5f), {3, 0, 0}, 0.0f, 0.8f, -1, 3, 1}});
    const auto written = out.commit();
    ASSERT_FALSE(written.empty());
    const std::string text = readAll(dir / "f.usda");
    EXPECT_NE(text.find("def PointInstancer \"english_oak\""), std::string::npos);
    EXPECT_NE(text.find("def PointInstancer \"birch\""), std::string::npos);
    EXPECT_NE(text.find("int[] protoIndices = [1]"), std::string::npos);
    EXPECT_NE(text.find("def Xform \"tree_3\""), std::string::npos);
    EXPECT_NE(text.find("custom string sylva:species = \"birch\""), std::string::npos);
    EXPECT_EQ(count(text, "def Xform \"variant_"), 3u);
    // A tree whose variant is of another species is refused, whatever its label says.
    exporter::TreeExporter bad(dir / "g.usda", options);
    bad.addVariants({{"birch_v0", barkAndLeaf(1), 1, 0}});
    EXPECT_THROW(bad.add({{"birch_1", barkAndLeaf(1), {}, 0.0f, 1.0f, 0, 1, 0}}), InvalidInput);
}

// What keeps a forest's text small (issue 30): leaf cards are quads with one normal each and
// corners from a few atlas cells (an indexed st primvar); a unique tree meshed for a far camera
// is written with coarser numbers.
TEST(UsdStageWriter, LeafCardsAreQuadsWithFlatNormalsAndIndexedUvsFarTreesCoarser) {
    auto cards = std::make_shared<mesh::Mesh>();
    const glm::vec2 corners[4] = {{0, 0}, {0.5f, 0}, {0.5f, 0.5f}, {0, 0.5f}};
    for (int c = 0; c < 5; ++c) {
        const auto base = static_cast<std::uint32_t>(cards->positions.size());
        const float x = 1.23456f * static_cast<float>(c + 1);
        for (int k = 0; k < 4; ++k) {
            cards->positions.push_back({x + static_cast<float>(k % 2), 0.11111f * k, 0.5f});
            cards->normals.push_back(glm::normalize(glm::vec3(0.1f * c, 0.3f, 1.0f)));
            cards->uvs.push_back(corners[k]);
        }
        for (std::uint32_t i : {0u, 1u, 2u, 0u, 2u, 3u})
            cards->indices.push_back(base + i);
    }
    cards->submeshes = {{"leaf", 0, 30, ""}};
    const fs::path dir = tempDir("cards");
    auto write = [&](double distance) {
        UsdStageWriter w(dir / "f.usda", options());
        UsdTree t;
        t.id = 5;
        t.mesh = cards;
        t.cameraDistance = distance;
        w.add({t});
        w.commit();
        return readAll(dir / "f.usda");
    };
    const std::string near = write(0.0);
    EXPECT_NE(near.find("int[] faceVertexCounts = [4,4,4,4,4]"), std::string::npos);
    EXPECT_NE(
        near.find("int[] faceVertexIndices = [0,1,2,3,4,5,6,7,8,9,10,11,12,13,14,15,16,17,18,19]"),
        std::string::npos);
    EXPECT_NE(near.find("texCoord2f[] primvars:st = [(0,0),(0.5,0),(0.5,0.5),(0,0.5)] (\n"),
              std::string::npos);
    EXPECT_NE(near.find("int[] primvars:st:indices = [0,1,2,3,0,1,2,3,0,1,2,3,0,1,2,3,0,1,2,3]"),
              std::string::npos);
    EXPECT_NE(near.find("interpolation = \"uniform\""), std::string::npos);
    EXPECT_NE(near.find("normal3f[] normals = [(0,0.287,0.958),(0.095,0.286,0.953),"),
              std::string::npos);
    EXPECT_NE(near.find("(1.2346,0,0.5)"), std::string::npos) << "0.1 mm near";
    const std::string far = write(150.0);
    EXPECT_NE(far.find("(1.235,0,0.5)"), std::string::npos) << "1 mm from 100 m";
    EXPECT_NE(far.find("normal3f[] normals = [(0,0.29,0.96),(0.1,0.29,0.95),"), std::string::npos);
    EXPECT_NE(write(1500.0).find("(1.23,0,0.5)"), std::string::npos) << "1 cm from 1 km";
}
