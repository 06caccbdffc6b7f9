// WindExporter's glTF: the rig, skin, clip and _WIND* data of .glb/.gltf (windexport.h).
#include "engine/export/windexport.h"

#include <map>
#include <span>

#include "engine/export/exportnames.h"
#include "engine/export/gltf/gltfbuilder.h"
#include "engine/export/gltf/gltfmesh.h"
#include "engine/export/materials.h"
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

} // namespace sylva::exporter
