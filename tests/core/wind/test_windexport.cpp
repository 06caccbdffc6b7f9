// The wind exports read back by a reader we did not write: Assimp reads the FBX's bones and its
// animation stack with the clip's keys (Blender's side is ctest blender_wind_fbx).
#include <gtest/gtest.h>

#include <assimp/Importer.hpp>
#include <assimp/scene.h>

#include <filesystem>
#include <map>
#include <memory>
#include <set>
#include <string>

#include "engine/export/windexport.h"
#include "windtree.h"

using namespace sylva;

namespace {

struct TempDir {
    std::filesystem::path path;
    explicit TempDir(const std::string& name)
        : path(std::filesystem::temp_directory_path() /
               (name + "_" + std::to_string(::testing::UnitTest::GetInstance()->random_seed()))) {
        std::filesystem::remove_all(path);
        std::filesystem::create_directories(path);
    }
    ~TempDir() { std::filesystem::remove_all(path); }
};

exporter::WindExportTree testTree() {
    auto skeleton = std::make_shared<skel::Skeleton>(windtest::windTree());
    auto mesh = std::make_shared<mesh::Mesh>(windtest::windTreeMesh(*skeleton));
    exporter::WindExportTree tree;
    tree.name = "tree";
    tree.mesh = mesh;
    tree.skeleton = skeleton;
    return tree;
}

} // namespace

TEST(WindExport, AssimpReadsTheFbxBonesAndClip) {
    TempDir dir("sylva_wind_fbx");
    exporter::WindExportOptions options;
    options.wind.strength = 1.0f;
    options.wind.period = 2.5f; // not a whole second: Assimp's exporter truncates the stack
    options.rig.fps = 24.0f;
    const exporter::WindExportTree tree = testTree();
    const auto prepared = exporter::WindExporter::prepare(tree, options);
    exporter::WindExporter writer(dir.path / "tree.fbx", options);
    writer.add({tree});
    writer.commit();

    Assimp::Importer importer;
    const aiScene* scene = importer.ReadFile((dir.path / "tree.fbx").string(), 0);
    ASSERT_NE(scene, nullptr) << importer.GetErrorString();
    ASSERT_EQ(scene->mNumAnimations, 1u) << "the animation stack is read";
    const aiAnimation& anim = *scene->mAnimations[0];
    EXPECT_STREQ(anim.mName.C_Str(), "wind");
    EXPECT_NEAR(anim.mTicksPerSecond, 24.0, 1e-6) << "the file's frame rate is the clip's";
    EXPECT_NEAR(anim.mDuration / anim.mTicksPerSecond, 2.5, 1e-6) << "the stack's length";

    const std::size_t nj = prepared.rig.joints.size();
    const std::size_t nf = prepared.clip.frameCount();
    ASSERT_EQ(anim.mNumChannels, nj) << "one channel per joint";
    std::set<std::string> boneNames;
    for (unsigned m = 0; m < scene->mNumMeshes; ++m)
        for (unsigned b = 0; b < scene->mMeshes[m]->mNumBones; ++b)
            boneNames.insert(scene->mMeshes[m]->mBones[b]->mName.C_Str());
    EXPECT_EQ(boneNames.size(), nj) << "every joint is a bone (Blender needs the whole chain)";

    std::map<std::string, std::size_t> jointOf;
    for (std::size_t j = 0; j < nj; ++j)
        jointOf["tree_" + prepared.rig.joints[j].name] = j;
    float worstT = 0.0f, worstR = 0.0f;
    for (unsigned c = 0; c < anim.mNumChannels; ++c) {
        const aiNodeAnim& ch = *anim.mChannels[c];
        const auto found = jointOf.find(ch.mNodeName.C_Str());
        ASSERT_NE(found, jointOf.end()) << ch.mNodeName.C_Str();
        ASSERT_EQ(ch.mNumPositionKeys, nf);
        ASSERT_EQ(ch.mNumRotationKeys, nf);
        for (std::size_t f = 0; f < nf; ++f) {
            EXPECT_NEAR(ch.mPositionKeys[f].mTime, static_cast<double>(f), 1e-3)
                << "key " << f << " at its frame";
            const glm::vec3& t = prepared.clip.translation[f * nj + found->second];
            const glm::quat& q = prepared.clip.rotation[f * nj + found->second];
            const aiVector3D& at = ch.mPositionKeys[f].mValue;
            const aiQuaternion& aq = ch.mRotationKeys[f].mValue;
            worstT = std::max(worstT, glm::length(t - glm::vec3(at.x, at.y, at.z)));
            // q and −q are the same rotation.
            const float dot = std::abs(q.w * aq.w + q.x * aq.x + q.y * aq.y + q.z * aq.z);
            worstR = std::max(worstR, 1.0f - std::min(dot, 1.0f));
        }
    }
    EXPECT_LT(worstT, 1e-5f) << "translation keys as baked";
    EXPECT_LT(worstR, 1e-6f) << "rotation keys as baked (through FBX's Euler angles)";
    // The clip moves: some joint turns by more than a degree somewhere.
    float most = 0.0f;
    for (const glm::quat& q : prepared.clip.rotation)
        most = std::max(most, 2.0f * std::acos(std::min(1.0f, std::abs(q.w))));
    EXPECT_GT(most, 0.0175f);
}
