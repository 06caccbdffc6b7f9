#include "engine/export/windexport.h"

#include <assimp/scene.h>

#include <algorithm>
#include <cstring>
#include <map>

#include "engine/export/exportnames.h"
#include "engine/export/fbx/sceneexport.h"
#include "engine/export/formats.h"
#include "engine/export/gltf/gltfbuilder.h"
#include "engine/export/gltf/gltfmesh.h"
#include "engine/export/materials.h"
#include "engine/export/obj/objwriter.h"
#include "engine/export/treeexport.h"
#include "engine/util/atomicfile.h"
#include "engine/util/error.h"
#include "engine/wind/windelements.h"

namespace sylva::exporter {

namespace fs = std::filesystem;

namespace {

template <class T> std::span<const std::byte> bytesOf(const std::vector<T>& v) {
    return std::as_bytes(std::span(v.data(), v.size()));
}

constexpr const char* kWindAttributes[8] = {"_WIND_PIVOT0",  "_WIND_PIVOT1",  "_WIND_PIVOT2",
                                            "_WIND_BRANCH0", "_WIND_BRANCH1", "_WIND_BRANCH2",
                                            "_WIND_PHASE",   "_WIND_LEAF"};

glm::quat treeRotation(float rotationY) {
    return glm::angleAxis(rotationY, glm::vec3(0, 1, 0));
}

} // namespace

WindExporter::WindExporter(fs::path path, WindExportOptions options, Progress& progress)
    : mPath(std::move(path)), mOptions(options), mProgress(progress) {
    wind::validate(mOptions.wind);
    wind::validate(mOptions.rig);
    const FormatRow* format = findFormat(mPath);
    if (!format || format->wind == WindSupport::None)
        throw InvalidInput("wind export writes " + extensionList([](const FormatRow& r) {
                               return r.wind != WindSupport::None;
                           }) +
                           ", not '" + mPath.extension().string() + "'");
    mFormat = format->format;
}

WindExporter::~WindExporter() = default;

void WindExporter::add(const std::vector<WindExportTree>& trees) {
    for (const WindExportTree& t : trees) {
        if (!t.mesh || !t.skeleton)
            throw InvalidInput("wind export of '" + t.name + "' needs its mesh and skeleton");
        if (t.mesh->empty()) continue; // nothing to draw or rig (a tree pruned away)
        mTrees.push_back(t);
    }
}

namespace {

std::shared_ptr<const mesh::Mesh> withWindData(const WindExportTree& tree) {
    if (tree.mesh->wind.size() == tree.mesh->positions.size() && !tree.mesh->positions.empty())
        return tree.mesh;
    auto copy = std::make_shared<mesh::Mesh>(*tree.mesh);
    wind::addWindData(*copy, *tree.skeleton);
    return copy;
}

} // namespace

std::shared_ptr<const mesh::Mesh> WindExporter::windMesh(const WindExportTree& tree) {
    std::shared_ptr<const mesh::Mesh>& cached = mWindMeshes[tree.mesh.get()];
    if (!cached) cached = withWindData(tree);
    return cached;
}

WindExporter::Prepared WindExporter::prepare(const WindExportTree& tree,
                                             const WindExportOptions& options) {
    return prepare(tree, withWindData(tree), options);
}

WindExporter::Prepared WindExporter::prepare(const WindExportTree& tree,
                                             std::shared_ptr<const mesh::Mesh> withWind,
                                             const WindExportOptions& options) {
    const wind::WindElements elements = wind::buildWindElements(*tree.skeleton);
    Prepared p;
    p.mesh = std::move(withWind);
    p.rig = wind::buildRig(elements, *tree.skeleton, options.rig);
    p.weights = wind::skinWeights(p.rig, elements, *p.mesh);
    p.clip = wind::bakeClip(p.rig, elements, options.wind, options.rig);
    p.pivotPainter = buildPivotPainter(elements, *tree.skeleton, *p.mesh);
    return p;
}

std::vector<fs::path> WindExporter::commit() {
    std::vector<fs::path> written;
    // The rig's writers; a format with the table only (OBJ: its caller writes the geometry)
    // gets the table.
    switch (mFormat) {
    case Format::Glb:
    case Format::Gltf:
        written = writeGltf();
        break;
    case Format::Fbx:
        written = writeFbx();
        break;
    case Format::Obj:
    case Format::Usda:
        break;
    }
    writeTable();
    written.push_back(mPath.parent_path() / (mPath.stem().string() + ".wind.csv"));
    return written;
}

std::vector<fs::path> WindExporter::writeGltf() {
    using namespace gltf;
    const bool glb = mFormat == Format::Glb;
    GltfBuilder b(mPath, glb ? GltfFormat::Glb : GltfFormat::Gltf, mProgress);
    std::vector<Material> materials = defaultMaterials();
    for (const WindExportTree& t : mTrees)
        addMaterialsOf(*t.mesh, materials);
    const fs::path res = resourcesDir();
    MaterialTable table(b, materials, res.empty() ? fs::path() : res / "textures", glb);

    struct Unique {
        Prepared p;
        int mesh = -1, inverseBind = -1;
        std::vector<int> translation, rotation; ///< output accessor per joint
    };
    std::vector<Unique> uniques;
    std::map<const mesh::Mesh*, std::size_t> uniqueOf;
    int times = -1;
    Animation animation;
    animation.name = "wind";
    std::vector<int> roots;
    for (const WindExportTree& tree : mTrees) {
        mProgress.checkCancelled();
        auto found = uniqueOf.find(tree.mesh.get());
        if (found == uniqueOf.end()) {
            Unique u;
            u.p = prepare(tree, windMesh(tree), mOptions);
            const mesh::Mesh& m = *u.p.mesh;
            const std::size_t nv = m.positions.size();
            ExtraAttributes extra;
            const int view = b.addBufferView(bytesOf(m.wind), Target::ArrayBuffer,
                                             static_cast<int>(sizeof(mesh::WindVertex)));
            for (int k = 0; k < 8; ++k)
                extra.emplace_back(kWindAttributes[k],
                                   b.addAccessor(view, ComponentType::Float, nv,
                                                 k == 7 ? "VEC2" : "VEC4",
                                                 static_cast<std::size_t>(16 * k)));
            const std::size_t nj = u.p.rig.joints.size();
            if (nj <= 256) {
                std::vector<std::uint8_t> j8(4 * nv);
                for (std::size_t i = 0; i < nv; ++i)
                    for (int c = 0; c < 4; ++c)
                        j8[4 * i + static_cast<std::size_t>(c)] =
                            static_cast<std::uint8_t>(u.p.weights.joints[i][c]);
                extra.emplace_back("JOINTS_0", b.addUint8(j8, 4));
            } else {
                std::vector<std::uint16_t> j16(4 * nv);
                for (std::size_t i = 0; i < nv; ++i)
                    for (int c = 0; c < 4; ++c)
                        j16[4 * i + static_cast<std::size_t>(c)] = u.p.weights.joints[i][c];
                extra.emplace_back("JOINTS_0", b.addUint16(j16, 4));
            }
            extra.emplace_back("WEIGHTS_0", b.addVec4(u.p.weights.weights));
            extra.emplace_back("TEXCOORD_1", b.addVec2(u.p.pivotPainter.vertexUv));
            u.mesh = addTreeMesh(b, m, tree.name, table, extra);
            std::vector<glm::mat4> ibm(nj);
            for (std::size_t j = 0; j < nj; ++j)
                ibm[j] = glm::translate(glm::mat4(1.0f), -u.p.rig.joints[j].rest);
            u.inverseBind = b.addMat4(ibm);
            if (times < 0) times = b.addFloats(u.p.clip.times, Target::None, true);
            // Each joint's keys contiguous, one bufferView per path, one accessor per joint.
            const std::size_t nf = u.p.clip.frameCount();
            std::vector<float> tr(nj * nf * 3), rot(nj * nf * 4);
            for (std::size_t j = 0; j < nj; ++j)
                for (std::size_t f = 0; f < nf; ++f) {
                    const glm::vec3& t = u.p.clip.translation[f * nj + j];
                    const glm::quat& q = u.p.clip.rotation[f * nj + j];
                    float* o = &tr[(j * nf + f) * 3];
                    o[0] = t.x, o[1] = t.y, o[2] = t.z;
                    float* r = &rot[(j * nf + f) * 4];
                    r[0] = q.x, r[1] = q.y, r[2] = q.z, r[3] = q.w;
                }
            const int tv = b.addBufferView(bytesOf(tr));
            const int rv = b.addBufferView(bytesOf(rot));
            for (std::size_t j = 0; j < nj; ++j) {
                u.translation.push_back(
                    b.addAccessor(tv, ComponentType::Float, nf, "VEC3", j * nf * 12));
                u.rotation.push_back(
                    b.addAccessor(rv, ComponentType::Float, nf, "VEC4", j * nf * 16));
            }
            found = uniqueOf.emplace(tree.mesh.get(), uniques.size()).first;
            uniques.push_back(std::move(u));
        }
        const Unique& u = uniques[found->second];
        Node treeNode;
        treeNode.name = tree.name;
        treeNode.translation = tree.position;
        treeNode.rotation = treeRotation(tree.rotationY);
        treeNode.scale = glm::vec3(tree.scale);
        const int treeIndex = b.addNode(treeNode);
        roots.push_back(treeIndex);
        std::vector<int> jointNodes;
        for (const wind::RigJoint& joint : u.p.rig.joints) {
            Node n;
            n.name = tree.name + "_" + joint.name;
            n.translation =
                joint.parent < 0
                    ? joint.rest
                    : joint.rest - u.p.rig.joints[static_cast<std::size_t>(joint.parent)].rest;
            const int index = b.addNode(n);
            b.addChild(joint.parent < 0 ? treeIndex
                                        : jointNodes[static_cast<std::size_t>(joint.parent)],
                       index);
            jointNodes.push_back(index);
        }
        Skin skin;
        skin.name = tree.name + "_skin";
        skin.inverseBindMatrices = u.inverseBind;
        skin.joints = jointNodes;
        skin.skeleton = treeIndex;
        const int skinIndex = b.addSkin(skin);
        Node meshNode;
        meshNode.name = tree.name + "_mesh";
        meshNode.mesh = u.mesh;
        meshNode.skin = skinIndex;
        // A skinned mesh's own transform is ignored by glTF: the node stays at the root.
        roots.push_back(b.addNode(meshNode));
        for (std::size_t j = 0; j < jointNodes.size(); ++j) {
            const int s = static_cast<int>(animation.samplers.size());
            animation.samplers.push_back({times, u.translation[j], "LINEAR"});
            animation.samplers.push_back({times, u.rotation[j], "LINEAR"});
            animation.channels.push_back({s, jointNodes[j], "translation"});
            animation.channels.push_back({s + 1, jointNodes[j], "rotation"});
        }
    }
    std::vector<std::pair<std::string, const Prepared*>> ppTrees;
    for (const WindExportTree& tree : mTrees) {
        const Prepared* p = &uniques[uniqueOf.at(tree.mesh.get())].p;
        if (std::none_of(ppTrees.begin(), ppTrees.end(),
                         [&](const auto& e) { return e.second == p; }))
            ppTrees.emplace_back(tree.name, p);
    }
    const std::vector<fs::path> ppFiles = writePivotPainterFiles(ppTrees);
    if (!animation.channels.empty()) b.addAnimation(animation);
    b.addScene("wind", roots);
    Json& extras = b.root()["asset"]["extras"];
    extras["sylva_wind"] = {{"direction",
                             {tidy(mOptions.wind.direction.x), tidy(mOptions.wind.direction.y),
                              tidy(mOptions.wind.direction.z)}},
                            {"strength", tidy(mOptions.wind.strength)},
                            {"gustiness", tidy(mOptions.wind.gustiness)},
                            {"frequency", tidy(mOptions.wind.frequency)},
                            {"period", tidy(mOptions.wind.period)},
                            {"docs", "docs/wind.md"}};
    // Named after "<stem>" (this file's name without its extension), so that the same trees
    // give the same bytes whatever the file is called.
    Json textures = Json::array();
    for (const auto& [name, p] : ppTrees) {
        (void)p;
        const std::string stem =
            ppTrees.size() == 1 ? std::string("<stem>") : "<stem>_" + fileSafeName(name);
        textures.push_back(stem + "_pivot_index.exr");
        textures.push_back(stem + "_xaxis_extent.png");
    }
    extras["sylva_wind"]["pivot_painter"] = {{"texcoord", 1}, {"textures", textures}};
    std::vector<fs::path> written = b.finish();
    written.insert(written.end(), ppFiles.begin(), ppFiles.end());
    return written;
}

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

std::vector<fs::path> WindExporter::writePivotPainterFiles(
    const std::vector<std::pair<std::string, const Prepared*>>& prepared) {
    std::vector<fs::path> written;
    for (const auto& [name, p] : prepared) {
        mProgress.checkCancelled();
        // One tree: <stem>_pivot_index.exr; several unique meshes: <stem>_<tree>_pivot_index.exr.
        const std::string stem = prepared.size() == 1
                                     ? mPath.stem().string()
                                     : mPath.stem().string() + "_" + fileSafeName(name);
        for (const fs::path& f : writePivotPainter(mPath.parent_path() / stem, p->pivotPainter))
            written.push_back(f);
    }
    return written;
}

void WindExporter::writeTable() {
    // object,vertex,x,y,z then the 32 floats of mesh::WindVertex in their order.
    std::string out = "object,vertex,x,y,z";
    for (int k = 0; k < 3; ++k)
        out += ",pivot" + std::to_string(k) + "_x,pivot" + std::to_string(k) + "_y,pivot" +
               std::to_string(k) + "_z,pivot" + std::to_string(k) + "_u";
    for (int k = 0; k < 3; ++k)
        out += ",branch" + std::to_string(k) + "_x,branch" + std::to_string(k) + "_y,branch" +
               std::to_string(k) + "_z,branch" + std::to_string(k) + "_stiffness";
    out += ",phase0,phase1,phase2,phase_flutter,level,flutter_weight,reserved0,reserved1\n";
    // Streamed in blocks (the table of a 1,000-tree forest is gigabytes: held whole, it ran
    // out of memory).
    AtomicFile file(mPath.parent_path() / (mPath.stem().string() + ".wind.csv"),
                    Durability::Durable);
    constexpr std::size_t kBlock = std::size_t{4} << 20;
    char buf[48];
    for (const WindExportTree& tree : mTrees) {
        mProgress.checkCancelled();
        const std::shared_ptr<const mesh::Mesh> m = windMesh(tree);
        for (std::size_t i = 0; i < m->positions.size(); ++i) {
            out += tree.name;
            out += ',';
            out += std::to_string(i);
            auto put = [&](float v) {
                out += ',';
                out.append(buf, formatFixed(buf, v, 6));
            };
            for (int c = 0; c < 3; ++c)
                put(m->positions[i][c]);
            const float* w = &m->wind[i].pivot[0].x;
            for (int c = 0; c < 32; ++c)
                put(w[c]);
            out += '\n';
            if (out.size() >= kBlock) {
                file.write(out);
                out.clear();
            }
        }
    }
    file.write(out);
    file.commit();
}

} // namespace sylva::exporter
