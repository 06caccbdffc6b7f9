#include <gtest/gtest.h>

#include <filesystem>
#include <functional>

#include <assimp/Importer.hpp>
#include <assimp/scene.h>

#include "../common/testtrees.h"
#include "engine/export/lodchainexport.h"
#include "engine/util/error.h"

using namespace sylva;

namespace {

std::filesystem::path tempDir(const std::string& name) {
    auto dir = std::filesystem::temp_directory_path() / ("sylva_geometry_" + name);
    std::filesystem::remove_all(dir);
    return dir; // writeGameLodChain creates it
}

// The live game chain of a small leafy tree: three budgets, no impostor (its bake is tested
// in tests/core/forest/test_lodchain).
mesh::BudgetLodChain smallChain(const skel::Skeleton& skeleton) {
    mesh::LodChainSettings settings;
    settings.budgets = {1.0, 0.4, 0.15};
    settings.impostor = false;
    return mesh::buildBudgetLodChain(skeleton, mesh::TreeMeshSettings{}, settings);
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

// Every level is written as its own OBJ and as a node of the FBX (the glTF nests its coarser
// levels under MSFT_lod, which Assimp does not follow); Assimp reads back the names and the
// triangle counts the writer reported, which equal the chain's meshes. (Ported from the test of
// the dropped exporter::writeLodChain, whose levels were the distance LOD's bands.)
TEST(LodChainExport, WritesObjFilesAndFbxNodesWithTriangleCounts) {
    const skel::Skeleton skeleton = sylva::testing::leafyTree();
    ASSERT_GT(skeleton.leaves.size(), 10u);
    const mesh::BudgetLodChain chain = smallChain(skeleton);
    ASSERT_GE(chain.levels.size(), 2u);
    const auto dir = tempDir("lodchainexport");
    exporter::GameLodOptions options;
    options.usd = false;
    const auto files =
        exporter::writeGameLodChain(dir, "Common alder", chain, mesh::LodSettings{}, options);
    ASSERT_EQ(files.levels.size(), chain.levels.size());

    for (std::size_t i = 0; i < files.levels.size(); ++i) {
        const auto& level = files.levels[i];
        EXPECT_EQ(level.name, "Common_alder_LOD" + std::to_string(i));
        EXPECT_EQ(level.obj, dir / (level.name + ".obj"));
        EXPECT_EQ(level.triangles, chain.levels[i].mesh.triangleCount());
        EXPECT_EQ(level.distance, chain.levels[i].distance);
        if (i > 0) {
            EXPECT_LT(level.triangles, files.levels[i - 1].triangles);
            EXPECT_GT(level.distance, files.levels[i - 1].distance);
        }

        Assimp::Importer importer;
        const aiScene* s = importer.ReadFile(level.obj.string(), 0);
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
    EXPECT_TRUE(std::filesystem::exists(files.mtl));
    EXPECT_TRUE(std::filesystem::exists(files.glb));
    EXPECT_TRUE(std::filesystem::exists(files.json));
    EXPECT_TRUE(files.usd.empty());

    Assimp::Importer importer;
    const aiScene* s = importer.ReadFile(files.fbx.string(), 0);
    ASSERT_NE(s, nullptr) << importer.GetErrorString();
    for (const auto& level : files.levels) {
        const aiNode* node = findNode(s->mRootNode, level.name);
        ASSERT_NE(node, nullptr) << level.name;
        EXPECT_EQ(faces(s, node), level.triangles) << level.name;
    }
    std::filesystem::remove_all(dir);
}

TEST(LodChainExport, RejectsBadInput) {
    const mesh::BudgetLodChain chain = smallChain(sylva::testing::leafyTree());
    const auto dir = tempDir("lodchainexport_bad");
    EXPECT_THROW(exporter::writeGameLodChain(dir, "", chain, mesh::LodSettings{}), InvalidInput);
    EXPECT_THROW(
        exporter::writeGameLodChain(dir, "oak", mesh::BudgetLodChain{}, mesh::LodSettings{}),
        InvalidInput);
    EXPECT_FALSE(std::filesystem::exists(dir / "oak_lods.json"));
    std::filesystem::remove_all(dir);
}
