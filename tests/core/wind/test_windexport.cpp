// The wind exports read back by a reader we did not write: Assimp reads the FBX's bones and its
// animation stack with the clip's keys (Blender's side is ctest blender_wind_fbx).
#include <gtest/gtest.h>

#include <OpenEXR/ImfRgbaFile.h>
#include <assimp/Importer.hpp>
#include <assimp/scene.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <map>
#include <memory>
#include <set>
#include <string>

#include "engine/export/windexport.h"
#include "engine/util/image.h"
#include "engine/wind/windelements.h"
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

// Unreal's Pivot Painter 2 textures, read back with OpenEXR's own reader and decoded as
// PivotPainter2FoliageShader does, against the elements they were made from; the element index
// read from the FBX's second UV set by Assimp.
TEST(WindExport, PivotPainterTexturesDecodeToTheElements) {
    TempDir dir("sylva_wind_pp");
    exporter::WindExportOptions options;
    const exporter::WindExportTree tree = testTree();
    const auto prepared = exporter::WindExporter::prepare(tree, options);
    const wind::WindElements elements = wind::buildWindElements(*tree.skeleton);
    exporter::WindExporter writer(dir.path / "tree.fbx", options);
    writer.add({tree});
    const std::vector<std::filesystem::path> files = writer.commit();
    const std::filesystem::path exr = dir.path / "tree_pivot_index.exr";
    const std::filesystem::path png = dir.path / "tree_xaxis_extent.png";
    ASSERT_NE(std::find(files.begin(), files.end(), exr), files.end());
    ASSERT_NE(std::find(files.begin(), files.end(), png), files.end());

    const std::size_t n = elements.elements.size();
    ASSERT_GT(n, 8u);
    Imf::RgbaInputFile in(exr.string().c_str());
    const Imath::Box2i window = in.dataWindow();
    const int w = window.max.x - window.min.x + 1, h = window.max.y - window.min.y + 1;
    ASSERT_GE(static_cast<std::size_t>(w * h), n);
    ASSERT_LT(static_cast<std::size_t>(w * (h - 1)), n) << "no wasted row";
    std::vector<Imf::Rgba> px(static_cast<std::size_t>(w * h));
    in.setFrameBuffer(px.data(), 1, static_cast<std::size_t>(w));
    in.readPixels(window.min.y, window.max.y);
    const Image axis = readPng(png);
    ASSERT_EQ(axis.width, w);
    ASSERT_EQ(axis.height, h);
    for (std::size_t e = 0; e < n; ++e) {
        const wind::WindElement& el = elements.elements[e];
        const Imf::Rgba& p = px[e]; // row-major from the top-left, as the UVs address it
        // Unreal: centimetres, X forward, Y right, Z up = Sylva's (x, z, y) × 100.
        const glm::vec3 want = glm::vec3(el.pivot.x, el.pivot.z, el.pivot.y) * 100.0f;
        const glm::vec3 got(p.r, p.g, p.b);
        EXPECT_LT(glm::length(got - want), 1e-3f * glm::length(want) + 0.05f) << "element " << e;
        // ms_PivotPainter2_UnpackIntegerAsFloat: the half's bits minus 1024.
        const int parent = static_cast<int>(p.a.bits()) - 1024;
        EXPECT_EQ(parent, el.parent >= 0 ? el.parent : static_cast<int>(e)) << "element " << e;
        const std::uint8_t* a = &axis.pixels[4 * e];
        const glm::vec3 x(a[0] / 255.0f * 2.0f - 1.0f, a[1] / 255.0f * 2.0f - 1.0f,
                          a[2] / 255.0f * 2.0f - 1.0f);
        const glm::vec3 wantX(el.direction.x, el.direction.z, el.direction.y);
        EXPECT_LT(glm::length(x - wantX), 0.02f) << "element " << e;
        // ms_PivotPainter2_Decode8BitAlphaAxisExtent: alpha × 2048 cm, in steps of 8 cm.
        const glm::vec3 tip = tree.skeleton->position[static_cast<std::size_t>(el.tipNode)];
        const float extentCm = 100.0f * glm::dot(tip - el.pivot, el.direction);
        EXPECT_NEAR(a[3] / 255.0f * 2048.0f, std::clamp(extentCm, 8.0f, 2048.0f), 8.1f)
            << "element " << e;
    }

    // Each vertex's element: the deepest level of its node's ancestry.
    const mesh::Mesh& m = *prepared.mesh;
    std::vector<std::int32_t> expected(m.positions.size());
    for (std::size_t i = 0; i < m.positions.size(); ++i) {
        std::int32_t lv[3];
        float u[3];
        elements.levelsOf(static_cast<std::size_t>(m.node[i]), lv, u);
        expected[i] = lv[2] >= 0 ? lv[2] : lv[1] >= 0 ? lv[1] : lv[0];
    }
    Assimp::Importer importer;
    const aiScene* scene = importer.ReadFile((dir.path / "tree.fbx").string(), 0);
    ASSERT_NE(scene, nullptr) << importer.GetErrorString();
    ASSERT_GE(scene->mNumMeshes, 1u);
    std::size_t checked = 0;
    std::set<int> addressed;
    for (unsigned k = 0; k < scene->mNumMeshes; ++k) {
        const aiMesh& am = *scene->mMeshes[k];
        ASSERT_TRUE(am.HasTextureCoords(1)) << "the Pivot Painter UV set";
        // Assimp's mesh k is submesh k, its faces the submesh's triangles in order.
        const mesh::Submesh& sub = m.submeshes[k];
        ASSERT_EQ(am.mNumFaces * 3, sub.indexCount);
        for (unsigned f = 0; f < am.mNumFaces; ++f)
            for (unsigned c = 0; c < 3; ++c) {
                // Unreal flips FBX's v: pixel row from the top = floor((1 − v) · h).
                const aiVector3D uv = am.mTextureCoords[1][am.mFaces[f].mIndices[c]];
                const int col = static_cast<int>(std::floor(uv.x * static_cast<float>(w)));
                const int row = static_cast<int>(std::floor((1.0f - uv.y) * static_cast<float>(h)));
                const int index = row * w + col;
                addressed.insert(index);
                const std::uint32_t vertex = m.indices[sub.firstIndex + 3 * f + c];
                EXPECT_EQ(index, expected[vertex]) << "face " << f << " of mesh " << k;
                ++checked;
            }
    }
    EXPECT_EQ(checked, m.indices.size()) << "every corner read back";
    EXPECT_EQ(addressed.size(), n) << "every element has geometry and its pixel";
}
