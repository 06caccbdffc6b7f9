// WindExporter's FBX: bones, skin deformers and the "wind" animation stack (windexport.h).
#include "engine/export/windexport.h"

#include <assimp/scene.h>

#include <cstring>
#include <map>

#include "engine/export/exportnames.h"
#include "engine/export/fbx/sceneexport.h"
#include "engine/export/materials.h"
#include "engine/util/error.h"
#include "engine/wind/windelements.h"

namespace sylva::exporter {

namespace fs = std::filesystem;

namespace {

glm::quat treeRotation(float rotationY) {
    return glm::angleAxis(rotationY, glm::vec3(0, 1, 0));
}

} // namespace

std::vector<fs::path> WindExporter::writeFbx() {
    SceneDesc desc;
    std::vector<Prepared> prepared;
    for (const WindExportTree& tree : mTrees) {
        mProgress.checkCancelled();
        prepared.push_back(prepare(tree, windMesh(tree), mOptions));
        // One scene mesh per tree: a bone belongs to one mesh, so skinned meshes are not shared.
        desc.meshes.push_back({tree.name, prepared.back().mesh.get()});
        addMaterialsOf(*tree.mesh, desc.materials);
        SceneInstance inst;
        inst.name = tree.name;
        inst.mesh = desc.meshes.size() - 1;
        inst.position = tree.position;
        inst.rotation = treeRotation(tree.rotationY);
        inst.scale = glm::vec3(tree.scale);
        desc.instances.push_back(inst);
    }
    const fs::path res = resourcesDir();
    desc.textureSource = res.empty() ? fs::path() : res / "textures";
    const float fps = mOptions.rig.fps;
    desc.decorate = [&](aiScene& scene) {
        std::vector<aiNodeAnim*> channels;
        for (std::size_t i = 0; i < prepared.size(); ++i) {
            const Prepared& p = prepared[i];
            const mesh::Mesh& m = *p.mesh;
            aiNode* node = scene.mRootNode->mChildren[i];
            const std::string& treeName = mTrees[i].name;
            // Bone nodes under the tree's node, beside its meshes.
            const std::size_t nj = p.rig.joints.size();
            std::vector<aiNode*> boneNodes(nj);
            std::vector<std::vector<aiNode*>> kids(nj + 1);
            for (std::size_t j = 0; j < nj; ++j) {
                const wind::RigJoint& joint = p.rig.joints[j];
                boneNodes[j] = new aiNode(treeName + "_" + joint.name);
                const glm::vec3 t =
                    joint.parent < 0
                        ? joint.rest
                        : joint.rest - p.rig.joints[static_cast<std::size_t>(joint.parent)].rest;
                boneNodes[j]->mTransformation = aiMatrix4x4(
                    aiVector3D(1, 1, 1), aiQuaternion(1, 0, 0, 0), aiVector3D(t.x, t.y, t.z));
                kids[joint.parent < 0 ? nj : static_cast<std::size_t>(joint.parent)].push_back(
                    boneNodes[j]);
            }
            auto attach = [](aiNode* parent, const std::vector<aiNode*>& children) {
                if (children.empty()) return;
                auto** list = new aiNode*[parent->mNumChildren + children.size()];
                std::copy_n(parent->mChildren, parent->mNumChildren, list);
                std::copy(children.begin(), children.end(), list + parent->mNumChildren);
                delete[] parent->mChildren;
                parent->mChildren = list;
                parent->mNumChildren += static_cast<unsigned>(children.size());
                for (aiNode* c : children)
                    c->mParent = parent;
            };
            // The bones hang under an armature node of their own beside the tree's meshes (FBX
            // readers take a node that holds both a mesh and bones for a bone).
            auto* armature = new aiNode(treeName + "_armature");
            attach(armature, kids[nj]);
            // The meshes move to a node of their own beside the armature: Assimp writes a node
            // with one mesh as that mesh's Model, and a mesh Model above the bones that deform
            // it makes Blender parent each to the other (half a forest's trees went missing).
            auto* meshes = new aiNode(treeName + "_mesh");
            meshes->mNumMeshes = node->mNumMeshes;
            meshes->mMeshes = node->mMeshes;
            node->mNumMeshes = 0;
            node->mMeshes = nullptr;
            attach(node, {meshes, armature});
            node = meshes;
            for (std::size_t j = 0; j < nj; ++j)
                attach(boneNodes[j], kids[j]);
            // Bones of each of the tree's meshes (one per non-empty submesh).
            std::vector<mesh::Submesh> parts = m.submeshes;
            if (parts.empty())
                parts.push_back({"bark", 0, static_cast<std::uint32_t>(m.indices.size())});
            std::erase_if(parts, [](const mesh::Submesh& s) { return s.indexCount == 0; });
            // Every joint is a bone of some mesh, weighted or not: Assimp writes only bones as
            // LimbNodes, and a plain node between two bones splits Blender's armature (its
            // FBX importer then fails with KeyError 'armature_setup').
            std::vector<bool> boned(nj, false);
            for (std::size_t k = 0; k < parts.size() && k < node->mNumMeshes; ++k) {
                aiMesh* am = scene.mMeshes[node->mMeshes[k]];
                std::vector<std::uint32_t> remap(m.positions.size(), UINT32_MAX), used;
                for (std::uint32_t x = parts[k].firstIndex;
                     x < parts[k].firstIndex + parts[k].indexCount; ++x) {
                    const std::uint32_t v = m.indices[x];
                    if (remap[v] == UINT32_MAX) {
                        remap[v] = static_cast<std::uint32_t>(used.size());
                        used.push_back(v);
                    }
                }
                // Pivot Painter's element index as UV channel 1 (FBX's v points up; Unreal's
                // importer flips it back to the v-down pixel centre).
                if (!am->mTextureCoords[0]) {
                    am->mTextureCoords[0] = new aiVector3D[am->mNumVertices]();
                    am->mNumUVComponents[0] = 2;
                }
                am->mTextureCoords[1] = new aiVector3D[am->mNumVertices];
                am->mNumUVComponents[1] = 2;
                for (std::uint32_t local = 0; local < used.size() && local < am->mNumVertices;
                     ++local) {
                    const glm::vec2 uv = p.pivotPainter.vertexUv[used[local]];
                    am->mTextureCoords[1][local] = aiVector3D(uv.x, 1.0f - uv.y, 0.0f);
                }
                std::vector<std::vector<aiVertexWeight>> perJoint(nj);
                for (std::uint32_t local = 0; local < used.size(); ++local)
                    for (int c = 0; c < 4; ++c) {
                        const float w = p.weights.weights[used[local]][c];
                        if (w > 0.0f)
                            perJoint[p.weights.joints[used[local]][c]].push_back({local, w});
                    }
                if (k + 1 == std::min<std::size_t>(parts.size(), node->mNumMeshes))
                    for (std::size_t j = 0; j < nj; ++j)
                        if (!boned[j] && perJoint[j].empty())
                            perJoint[j].push_back({0, 0.0f}); // a cluster that moves nothing
                std::vector<aiBone*> bones;
                for (std::size_t j = 0; j < nj; ++j) {
                    if (perJoint[j].empty()) continue;
                    boned[j] = true;
                    auto* bone = new aiBone();
                    bone->mName = aiString(boneNodes[j]->mName);
                    const glm::vec3& r = p.rig.joints[j].rest;
                    bone->mOffsetMatrix = aiMatrix4x4(aiVector3D(1, 1, 1), aiQuaternion(1, 0, 0, 0),
                                                      aiVector3D(-r.x, -r.y, -r.z));
                    bone->mNumWeights = static_cast<unsigned>(perJoint[j].size());
                    bone->mWeights = new aiVertexWeight[bone->mNumWeights];
                    std::copy(perJoint[j].begin(), perJoint[j].end(), bone->mWeights);
                    bones.push_back(bone);
                }
                am->mNumBones = static_cast<unsigned>(bones.size());
                am->mBones = new aiBone*[std::max<std::size_t>(bones.size(), 1)];
                std::copy(bones.begin(), bones.end(), am->mBones);
            }
            const std::size_t nf = p.clip.frameCount();
            for (std::size_t j = 0; j < nj; ++j) {
                auto* ch = new aiNodeAnim();
                ch->mNodeName = boneNodes[j]->mName;
                ch->mNumPositionKeys = static_cast<unsigned>(nf);
                ch->mPositionKeys = new aiVectorKey[nf];
                ch->mNumRotationKeys = static_cast<unsigned>(nf);
                ch->mRotationKeys = new aiQuatKey[nf];
                ch->mNumScalingKeys = 1;
                ch->mScalingKeys = new aiVectorKey[1];
                ch->mScalingKeys[0] = aiVectorKey(0.0, aiVector3D(1, 1, 1));
                for (std::size_t f = 0; f < nf; ++f) {
                    // Assimp 5.2.5's FBX exporter writes a key's mTime as seconds (KeyTime =
                    // mTime × 46186158000), not as ticks; the stack's length comes from
                    // mDuration / mTicksPerSecond and is set exactly by the repair.
                    const double tick = static_cast<double>(p.clip.times[f]);
                    const glm::vec3& t = p.clip.translation[f * nj + j];
                    const glm::quat& q = p.clip.rotation[f * nj + j];
                    ch->mPositionKeys[f] = aiVectorKey(tick, aiVector3D(t.x, t.y, t.z));
                    ch->mRotationKeys[f] = aiQuatKey(tick, aiQuaternion(q.w, q.x, q.y, q.z));
                }
                channels.push_back(ch);
            }
        }
        auto* anim = new aiAnimation();
        anim->mName = aiString("wind");
        anim->mTicksPerSecond = fps;
        anim->mDuration = static_cast<double>(mOptions.wind.period) * fps;
        anim->mNumChannels = static_cast<unsigned>(channels.size());
        anim->mChannels = new aiNodeAnim*[std::max<std::size_t>(channels.size(), 1)];
        std::copy(channels.begin(), channels.end(), anim->mChannels);
        scene.mNumAnimations = 1;
        scene.mAnimations = new aiAnimation*[1];
        scene.mAnimations[0] = anim;
    };
    desc.animationFrameRate = fps;
    desc.animationSeconds = mOptions.wind.period;
    writeScene(mPath, desc, SceneFormat::Fbx, mProgress);
    std::vector<std::pair<std::string, const Prepared*>> ppTrees;
    std::map<const mesh::Mesh*, std::size_t> firstOf;
    for (std::size_t i = 0; i < mTrees.size(); ++i)
        if (firstOf.emplace(mTrees[i].mesh.get(), i).second)
            ppTrees.emplace_back(mTrees[i].name, &prepared[i]);
    std::vector<fs::path> written{mPath};
    for (const fs::path& f : writePivotPainterFiles(ppTrees))
        written.push_back(f);
    return written;
}

} // namespace sylva::exporter
