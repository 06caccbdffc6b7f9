// The format table (engine/export/formats.h): the one place that knows a file extension. Every
// row is written here through its own writer, so a new format is tested by adding its row.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>

#include <stdlib.h>

#include "engine/export/formats.h"
#include "engine/export/treeexport.h"
#include "engine/export/windexport.h"
#include "engine/util/error.h"

using namespace sylva;
using namespace sylva::exporter;
namespace fs = std::filesystem;

namespace {

std::shared_ptr<const mesh::Mesh> barkAndLeaf(float size) {
    auto m = std::make_shared<mesh::Mesh>();
    m->positions = {{0, 0, 0}, {size, 0, 0}, {size, size, 0}, {0, size, 0},
                    {0, 2, 0}, {1, 2, 0},    {0, 3, 0}};
    m->normals = {{0, 0, 1}, {0, 0, 1}, {0, 0, 1}, {0, 0, 1}, {0, 0, 1}, {0, 0, 1}, {0, 0, 1}};
    m->uvs = {{0, 0}, {1, 0}, {1, 1}, {0, 1}, {0, 0}, {1, 0}, {0, 1}};
    m->indices = {0, 1, 2, 0, 2, 3, 4, 5, 6};
    m->submeshes = {{"bark", 0, 6, ""}, {"leaf", 6, 3, ""}};
    return m;
}

fs::path tempDir(const std::string& name) {
    const fs::path dir = fs::temp_directory_path() / ("sylva_formats_" + name);
    fs::remove_all(dir);
    fs::create_directories(dir);
    return dir;
}

std::string readAll(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    std::stringstream s;
    s << in.rdbuf();
    return s.str();
}

} // namespace

TEST(FormatTable, OneRowPerFormatFoundByItsExtensionInAnyCase) {
    std::set<std::string> extensions;
    std::set<Format> formats;
    for (const FormatRow& row : formatTable()) {
        EXPECT_TRUE(extensions.insert(row.extension).second) << row.extension;
        EXPECT_TRUE(formats.insert(row.format).second) << row.extension;
        EXPECT_EQ(&formatRow(row.format), &row);
        EXPECT_EQ(&formatFor(std::string("a/forest") + row.extension), &row);
        std::string upper = row.extension;
        for (char& c : upper)
            c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
        EXPECT_EQ(findFormat("FOREST" + upper), &row) << upper;
        EXPECT_TRUE(isFormat("x" + upper, row.format));
        EXPECT_NE(row.makeWriter, nullptr);
        EXPECT_NE(std::string(row.name), "");
    }
    EXPECT_EQ(findFormat("forest.stl"), nullptr);
    EXPECT_EQ(findFormat("forest"), nullptr);
    try {
        formatFor("forest.stl");
        ADD_FAILURE() << "no throw";
    } catch (const InvalidInput& e) {
        EXPECT_STREQ(e.what(),
                     "unknown scene format '.stl' (use .obj, .usda, .glb, .gltf or .fbx)");
    }
}

TEST(FormatTable, ListsAndDialogFilterComeFromTheRows) {
    EXPECT_EQ(extensionList(), ".obj, .usda, .glb, .gltf or .fbx");
    EXPECT_EQ(extensionList(nullptr, ",", ",", false), "obj,usda,glb,gltf,fbx");
    EXPECT_EQ(extensionList([](const FormatRow& r) { return r.wind == WindSupport::Rig; }),
              ".glb, .gltf or .fbx");
    EXPECT_EQ(extensionList([](const FormatRow& r) { return r.tileLayers; }), ".usda");
    EXPECT_EQ(dialogFilter(), "Wavefront OBJ (*.obj);;USD text (*.usda);;glTF binary (*.glb);;"
                              "glTF (*.gltf);;FBX binary (*.fbx)");
}

// Every row's writer writes a small forest (two variants of two species, an instance of each,
// a unique tree) to its file; what the row claims about instancing, tile layers, instance
// tables and embedded textures is what the writer does.
TEST(FormatTable, EveryRowsWriterWritesWhatItsRowClaims) {
    // The shipped textures, for the formats that copy them beside the file.
    ::setenv("SYLVA_RESOURCES_DIR",
             (fs::path(SYLVA_PRESETS_DIR).parent_path() / "resources").c_str(), 1);
    for (const FormatRow& row : formatTable()) {
        SCOPED_TRACE(row.extension);
        const fs::path dir = tempDir(row.extension + 1);
        const fs::path path = dir / (std::string("forest") + row.extension);
        ForestWriterOptions options;
        options.species = {"oak", "birch"};
        if (row.tileLayers) {
            options.tile = 1;
            options.tileCount = 2;
            options.sceneKey = "k";
        }
        TreeExporter out(path, options);
        EXPECT_EQ(&out.format(), &row);
        EXPECT_EQ(out.writesInstances(), row.instancing);
        if (row.instanceTables)
            out.setInstanceTables(true);
        else
            EXPECT_THROW(out.setInstanceTables(true), InvalidInput);
        out.addVariants({{"oak_v0", barkAndLeaf(1), 0, 0}, {"birch_v0", barkAndLeaf(2), 1, 0}});
        out.add({{"oak_1", barkAndLeaf(1), {1, 0, 0}, 0.0f, 1.0f, 0, 1, 0},
                 {"birch_2", barkAndLeaf(2), {5, 0, 0}, 0.5f, 1.2f, 1, 2, 1},
                 {"birch_3", barkAndLeaf(0.5f), {9, 0, 0}, 0.0f, 1.0f, -1, 3, 1}});
        const std::vector<fs::path> written = out.commit();
        ASSERT_FALSE(written.empty());
        EXPECT_EQ(written.front(), path);
        ASSERT_TRUE(fs::exists(path));
        EXPECT_GT(fs::file_size(path), 100u);
        // Embedded textures, or copied beside the file.
        EXPECT_EQ(fs::exists(dir / "textures"), !row.embedsTextures);
        EXPECT_EQ(fs::exists(dir / "forest.instances.csv"), row.instanceTables);
        if (row.tileLayers) {
            const std::string text = readAll(path);
            EXPECT_NE(text.find("\"k\""), std::string::npos) << "the scene key of the tile layer";
        }
        fs::remove_all(dir);
    }
}

// The wind exporter takes the formats the table gives a wind, and refuses the others.
TEST(FormatTable, WindExporterFollowsTheRows) {
    for (const FormatRow& row : formatTable()) {
        const fs::path path = std::string("w") + row.extension;
        if (row.wind == WindSupport::None)
            EXPECT_THROW(WindExporter(path, {}), InvalidInput) << row.extension;
        else
            EXPECT_NO_THROW(WindExporter(path, {})) << row.extension;
    }
    EXPECT_THROW(WindExporter("w.stl", {}), InvalidInput);
}
