#include <gtest/gtest.h>

#include <filesystem>
#include <functional>

#include <assimp/Importer.hpp>
#include <assimp/scene.h>

#include "../common/testwords.h"
#include "engine/export/lodexport.h"
#include "engine/lsystem/turtle.h"
#include "engine/util/error.h"

using namespace sylva;

namespace {

std::filesystem::path tempDir(const std::string& name) {
    auto dir = std::filesystem::temp_directory_path() / ("sylva_geometry_" + name);
    std::filesystem::remove_all(dir);
    return dir; // writeLodChain creates it
}

skel::Skeleton leafyTree() {
    lsys::TurtleSettings t;
    t.angleDegrees = 30;
    t.step = 0.5;
    t.width = 0.3;
    return lsys::interpret(sylva::testing::makeWord(sylva::testing::testTreeWord(5)), t);
}

std::size_t faces(const aiScene* s, const aiNode* node) {
    std::size_t n = 0;
    for (unsigned i = 0; i < node->mNumMeshes; ++i)
        n += s->mMeshes[node->mMeshes[i]]->mNumFaces;
    for (unsigned i = 0; i < node->mNumChildren; ++i)
        n += faces(s, node->mChildren[i]);
    return n;
}

const aiNode* findNode(const aiNode* node, const std::string& name) {
    if (name == node->mName.C_Str()) return node;
    for (unsigned i = 0; i < node->mNumChildren; ++i)
        if (const aiNode* f = findNode(node->mChildren[i], name)) return f;
    return nullptr;
}

} // namespace

// Every level is written as its own OBJ and as a node of one GLB; Assimp reads back the names
// and the triangle counts the writer reported, which equal the meshes of buildLodChain().
TEST(LodExport, WritesObjFilesAndGlbNodesWithTriangleCounts) {
    const auto skeleton = leafyTree();
    ASSERT_GT(skeleton.leaves.size(), 10u);
    mesh::TreeMeshSettings settings;
    const auto dir = tempDir("lodexport");
    const auto files = exporter::writeLodChain(dir, "Common alder", skeleton, settings);
    const auto chain = mesh::buildLodChain(skeleton, settings);
    ASSERT_EQ(files.levels.size(), settings.lod.bands.size());
    ASSERT_EQ(chain.size(), files.levels.size());

    for (std::size_t i = 0; i < files.levels.size(); ++i) {
        const auto& level = files.levels[i];
        EXPECT_EQ(level.name, "Common_alder_LOD" + std::to_string(i));
        EXPECT_EQ(level.objPath, dir / (level.name + ".obj"));
        EXPECT_EQ(level.triangles, chain[i].mesh.triangleCount());
        EXPECT_EQ(level.distance, settings.lod.bands[i].distance);
        if (i > 0) {
            EXPECT_LT(level.triangles, files.levels[i - 1].triangles);
        }

        Assimp::Importer importer;
        const aiScene* s = importer.ReadFile(level.objPath.string(), 0);
        ASSERT_NE(s, nullptr) << importer.GetErrorString();
        const aiNode* node = findNode(s->mRootNode, level.name);
        ASSERT_NE(node, nullptr) << level.name;
        EXPECT_EQ(faces(s, node), level.triangles);
        bool bark = false, leaf = false;
        for (unsigned m = 0; m < s->mNumMaterials; ++m) {
            const std::string name = s->mMaterials[m]->GetName().C_Str();
            bark |= name == "bark";
            leaf |= name == "leaf";
        }
        EXPECT_TRUE(bark && leaf) << "materials of " << level.name << " (via the MTL)";
    }
    EXPECT_TRUE(std::filesystem::exists(files.mtlPath));

    Assimp::Importer importer;
    const aiScene* s = importer.ReadFile(files.glbPath.string(), 0);
    ASSERT_NE(s, nullptr) << importer.GetErrorString();
    for (const auto& level : files.levels) {
        const aiNode* node = findNode(s->mRootNode, level.name);
        ASSERT_NE(node, nullptr) << level.name;
        EXPECT_EQ(faces(s, node), level.triangles) << level.name;
    }
    std::filesystem::remove_all(dir);
}

TEST(LodExport, RejectsBadInput) {
    const auto skeleton = leafyTree();
    mesh::TreeMeshSettings settings;
    const auto dir = tempDir("lodexport_bad");
    EXPECT_THROW(exporter::writeLodChain(dir, "", skeleton, settings), InvalidInput);
    settings.lod.bands.clear();
    EXPECT_THROW(exporter::writeLodChain(dir, "oak", skeleton, settings), InvalidInput);
    std::filesystem::remove_all(dir);
}
