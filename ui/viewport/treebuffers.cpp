#include "ui/viewport/treebuffers.h"

#include <algorithm>
#include <cstddef>
#include <cstring>
#include <filesystem>

#include <QImage>

#include "engine/export/materials.h"
#include "engine/export/treeexport.h"
#include "engine/mesh/mesh.h"
#include "engine/util/alphamips.h"
#include "engine/wind/windelements.h"
#include "ui/generation/windvertexdata.h"
#include "ui/viewport/textureimage.h"

namespace sylva::ui {

namespace {

std::vector<DrawRange> rangesOf(const mesh::Mesh& m) {
    std::vector<DrawRange> ranges;
    const auto total = static_cast<std::uint32_t>(m.indices.size());
    if (m.submeshes.empty()) {
        ranges.push_back({TreeBuffers::materialColor("bark"), 0, total});
        return ranges;
    }
    for (const mesh::Submesh& s : m.submeshes) {
        if (s.firstIndex >= total) continue;
        const std::uint32_t count = std::min(s.indexCount, total - s.firstIndex);
        DrawRange r{TreeBuffers::materialColor(s.material), s.firstIndex, count - count % 3};
        // Sylva's bark tubes are closed and wound counter-clockwise seen from outside, so their
        // back faces are never seen: culling them spares the rasteriser half the triangles
        // (a third of a software renderer's frame). Ribbons made for one camera are not.
        r.twoSided = s.material != "bark" || m.cameraRibbons;
        ranges.push_back(r);
    }
    return ranges;
}

} // namespace

glm::vec3 TreeBuffers::materialColor(const std::string& material) {
    if (material == "leaf" || material == "leaves" || material == "foliage")
        return {0.11f, 0.30f, 0.06f};
    if (material == "bark" || material.empty()) return {0.17f, 0.10f, 0.055f};
    if (material == "ground") return {0.10f, 0.09f, 0.05f}; // a project's terrain
    // Obstacles: stone, mottled by the scene mesh's per-vertex colours (scenegenerator's
    // stoneColor, 0.6..1), so about the grey of before on average.
    return {0.45f, 0.44f, 0.42f};
}

bool TreeBuffers::indicesInRange(const mesh::Mesh& m) {
    for (std::uint32_t index : m.indices)
        if (index >= m.positions.size()) return false;
    return true;
}

void TreeBuffers::initialize(QOpenGLFunctions_3_3_Core* gl,
                             std::function<void(const QString&)> problem) {
    mGl = gl;
    mProblem = std::move(problem);
    mGl->glGenVertexArrays(1, &mSceneVao);
    mGl->glGenBuffers(1, &mSceneVbo);
    mGl->glGenBuffers(1, &mSceneIbo);
    mGl->glBindVertexArray(mSceneVao);
    mGl->glBindBuffer(GL_ARRAY_BUFFER, mSceneVbo);
    mGl->glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, mSceneIbo);
    // Position, normal, attribute colour (zero unless the view colours by an attribute), uv,
    // occlusion.
    setMeshAttributes();
    mGl->glBindVertexArray(0);
}

void TreeBuffers::release() {
    if (!mGl) return;
    releaseTrees();
    if (mSceneWindVbo) mGl->glDeleteBuffers(1, &mSceneWindVbo);
    mSceneWindVbo = mSceneWindElements = 0;
    mSceneSkeleton.reset();
    mSceneElements.reset();
    if (mRotationsTexture) mGl->glDeleteTextures(1, &mRotationsTexture);
    if (mRotationsBuffer) mGl->glDeleteBuffers(1, &mRotationsBuffer);
    mRotationsTexture = mRotationsBuffer = 0;
    releaseWindTables(true);
    mGl->glDeleteVertexArrays(1, &mSceneVao);
    mGl->glDeleteBuffers(1, &mSceneVbo);
    mGl->glDeleteBuffers(1, &mSceneIbo);
    mSceneVao = mSceneVbo = mSceneIbo = 0;
    mSceneRanges.clear();
    for (const auto& [path, id] : mTextures)
        if (id) mGl->glDeleteTextures(1, &id);
    mTextures.clear();
    if (mFlatNormal) mGl->glDeleteTextures(1, &mFlatNormal);
    mFlatNormal = 0;
    mGl = nullptr;
}

bool TreeBuffers::uploadScene(const mesh::Mesh* mesh, const std::vector<glm::vec3>& colors,
                              const std::vector<ViewVertex>* prepared,
                              const std::shared_ptr<const skel::Skeleton>& skeleton) {
    mSceneRanges.clear();
    if (!mesh || mesh->empty() || mesh->indices.empty()) return true;
    const mesh::Mesh& m = *mesh;
    if (!indicesInRange(m)) return false;
    const bool colored = colors.size() == m.positions.size();
    // The vertices made beside the mesh on a worker, when they fit and no attribute colours
    // replace theirs; else made here.
    std::vector<ViewVertex> made;
    const bool usePrepared = !colored && prepared && prepared->size() == m.positions.size();
    if (!usePrepared) made = interleaveVertices(m, colors);
    const std::vector<ViewVertex>& interleaved = usePrepared ? *prepared : made;
    mSceneVertexColors = colored;
    mGl->glBindVertexArray(mSceneVao);
    mGl->glBindBuffer(GL_ARRAY_BUFFER, mSceneVbo);
    mGl->glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(interleaved.size() * sizeof(ViewVertex)),
                      interleaved.data(), GL_STATIC_DRAW);
    mGl->glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, mSceneIbo);
    mGl->glBufferData(GL_ELEMENT_ARRAY_BUFFER, GLsizeiptr(m.indices.size() * sizeof(std::uint32_t)),
                      m.indices.data(), GL_STATIC_DRAW);
    mSceneWindElements = 0;
    mSceneElements.reset();
    mSceneSkeleton = skeleton;
    const WindTable* table = skeleton ? windTableFor(skeleton) : nullptr;
    if (table && uploadWind(m, *table, mSceneWindVbo)) {
        mSceneWindElements = table->texture;
        mSceneElements = table->elements;
    } else {
        mSceneSkeleton.reset();
    }
    mGl->glBindVertexArray(0);
    releaseWindTables(false);

    mSceneRanges = rangesOf(m);
    bindTextures(m, mSceneRanges);
    return true;
}

void TreeBuffers::setMeshAttributes() {
    constexpr GLsizei kStride = sizeof(ViewVertex);
    auto at = [](std::size_t offset) { return reinterpret_cast<void*>(offset); };
    for (GLuint a = 0; a < 5; ++a)
        mGl->glEnableVertexAttribArray(a);
    mGl->glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, kStride,
                               at(offsetof(ViewVertex, position)));
    mGl->glVertexAttribPointer(1, 3, GL_FLOAT, GL_FALSE, kStride, at(offsetof(ViewVertex, normal)));
    mGl->glVertexAttribPointer(2, 3, GL_FLOAT, GL_FALSE, kStride, at(offsetof(ViewVertex, color)));
    mGl->glVertexAttribPointer(3, 2, GL_FLOAT, GL_FALSE, kStride, at(offsetof(ViewVertex, uv)));
    mGl->glVertexAttribPointer(4, 1, GL_FLOAT, GL_FALSE, kStride,
                               at(offsetof(ViewVertex, occlusion)));
}

const TreeBuffers::WindTable*
TreeBuffers::windTableFor(const std::shared_ptr<const skel::Skeleton>& skeleton) {
    if (auto it = mWindTables.find(skeleton.get()); it != mWindTables.end())
        return it->second.texture ? &it->second : nullptr;
    WindTable table;
    table.skeleton = skeleton;
    std::vector<glm::vec4> texels;
    try {
        table.elements =
            std::make_shared<const wind::WindElements>(wind::buildWindElements(*skeleton));
        texels = windElementTexels(*table.elements);
    } catch (...) {
        texels.clear(); // a skeleton the model refuses: its trees stand still
    }
    if (mMaxBufferTexels < 0) mGl->glGetIntegerv(GL_MAX_TEXTURE_BUFFER_SIZE, &mMaxBufferTexels);
    // Not made (the trees stand still) when there is nothing to sway or the table would not
    // fit a buffer texture (at least 65536 texels everywhere).
    if (!texels.empty() && texels.size() <= std::size_t(std::max(mMaxBufferTexels, 0))) {
        mGl->glGenBuffers(1, &table.buffer);
        mGl->glBindBuffer(GL_TEXTURE_BUFFER, table.buffer);
        mGl->glBufferData(GL_TEXTURE_BUFFER, GLsizeiptr(texels.size() * sizeof(glm::vec4)),
                          texels.data(), GL_STATIC_DRAW);
        mGl->glGenTextures(1, &table.texture);
        mGl->glBindTexture(GL_TEXTURE_BUFFER, table.texture);
        mGl->glTexBuffer(GL_TEXTURE_BUFFER, GL_RGBA32F, table.buffer);
        mGl->glBindTexture(GL_TEXTURE_BUFFER, 0);
        mGl->glBindBuffer(GL_TEXTURE_BUFFER, 0);
    }
    const WindTable& kept = mWindTables.emplace(skeleton.get(), std::move(table)).first->second;
    return kept.texture ? &kept : nullptr;
}

GLuint TreeBuffers::uploadWindRotations(const std::vector<glm::vec4>& rotations) {
    if (mMaxBufferTexels < 0) mGl->glGetIntegerv(GL_MAX_TEXTURE_BUFFER_SIZE, &mMaxBufferTexels);
    if (rotations.empty() || rotations.size() > std::size_t(std::max(mMaxBufferTexels, 0)))
        return 0;
    if (!mRotationsBuffer) {
        mGl->glGenBuffers(1, &mRotationsBuffer);
        mGl->glGenTextures(1, &mRotationsTexture);
    }
    mGl->glBindBuffer(GL_TEXTURE_BUFFER, mRotationsBuffer);
    // A new store each frame: the last frame's draws may still read the old one.
    mGl->glBufferData(GL_TEXTURE_BUFFER, GLsizeiptr(rotations.size() * sizeof(glm::vec4)),
                      rotations.data(), GL_STREAM_DRAW);
    mGl->glBindTexture(GL_TEXTURE_BUFFER, mRotationsTexture);
    mGl->glTexBuffer(GL_TEXTURE_BUFFER, GL_RGBA32F, mRotationsBuffer);
    mGl->glBindTexture(GL_TEXTURE_BUFFER, 0);
    mGl->glBindBuffer(GL_TEXTURE_BUFFER, 0);
    return mRotationsTexture;
}

bool TreeBuffers::uploadWind(const mesh::Mesh& m, const WindTable& table, GLuint& vbo) {
    const std::vector<ViewWindVertex> data = windVertices(m, *table.elements);
    if (data.empty()) {
        for (GLuint a = 5; a < 8; ++a)
            mGl->glDisableVertexAttribArray(a);
        return false;
    }
    if (!vbo) mGl->glGenBuffers(1, &vbo);
    mGl->glBindBuffer(GL_ARRAY_BUFFER, vbo);
    mGl->glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(data.size() * sizeof(ViewWindVertex)),
                      data.data(), GL_STATIC_DRAW);
    constexpr GLsizei kStride = sizeof(ViewWindVertex);
    auto at = [](std::size_t offset) { return reinterpret_cast<void*>(offset); };
    for (GLuint a = 5; a < 8; ++a)
        mGl->glEnableVertexAttribArray(a);
    mGl->glVertexAttribIPointer(5, 2, GL_UNSIGNED_INT, kStride,
                                at(offsetof(ViewWindVertex, element)));
    mGl->glVertexAttribPointer(6, 1, GL_UNSIGNED_SHORT, GL_TRUE, kStride,
                               at(offsetof(ViewWindVertex, u)));
    mGl->glVertexAttribPointer(7, 1, GL_HALF_FLOAT, GL_FALSE, kStride,
                               at(offsetof(ViewWindVertex, flutter)));
    return true;
}

void TreeBuffers::releaseWindTables(bool all) {
    for (auto it = mWindTables.begin(); it != mWindTables.end();) {
        bool used = !all && it->first == mSceneSkeleton.get();
        for (const auto& [key, gpu] : mGpuTrees)
            used = used || (!all && gpu.skeleton.get() == it->first);
        if (used) {
            ++it;
            continue;
        }
        if (it->second.texture) mGl->glDeleteTextures(1, &it->second.texture);
        if (it->second.buffer) mGl->glDeleteBuffers(1, &it->second.buffer);
        it = mWindTables.erase(it);
    }
}

void TreeBuffers::bindTextures(const mesh::Mesh& m, std::vector<DrawRange>& ranges) {
    // rangesOf() keeps the submeshes' order, skipping those that start past the indices.
    std::size_t r = 0;
    const auto total = static_cast<std::uint32_t>(m.indices.size());
    for (const mesh::Submesh& s : m.submeshes) {
        if (s.firstIndex >= total) continue;
        if (r >= ranges.size()) break;
        ranges[r].texture = textureFor(s.material, s.texture);
        if (ranges[r].texture) ranges[r].normalMap = normalMapFor(s.material, s.texture);
        ranges[r].alphaTest = s.material == "leaf" && ranges[r].texture != 0;
        ++r;
    }
    if (m.submeshes.empty() && !ranges.empty()) {
        ranges[0].texture = textureFor("bark", {});
        if (ranges[0].texture) ranges[0].normalMap = normalMapFor("bark", {});
    }
}

GLuint TreeBuffers::normalMapFor(const std::string& material, const std::string& file) {
    std::string path = file;
    if (path.empty() && (material == "bark" || material == "leaf")) {
        const std::filesystem::path dir = exporter::resourcesDir();
        if (!dir.empty()) path = (dir / "textures" / (material + ".png")).string();
    }
    const std::string normal = exporter::companionTexture(path, "normal");
    GLuint id = normal.empty() ? 0 : textureFor(material, normal);
    if (id) return id;
    if (!mFlatNormal) {
        const unsigned char flat[4] = {128, 128, 255, 255};
        mGl->glGenTextures(1, &mFlatNormal);
        mGl->glBindTexture(GL_TEXTURE_2D, mFlatNormal);
        mGl->glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, 1, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, flat);
        mGl->glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
        mGl->glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
        mGl->glBindTexture(GL_TEXTURE_2D, 0);
    }
    return mFlatNormal;
}

GLuint TreeBuffers::textureFor(const std::string& material, const std::string& file) {
    std::string path = file;
    if (path.empty()) {
        // Sylva's shipped textures for the two materials it makes; nothing for the rest.
        if (material != "bark" && material != "leaf") return 0;
        const std::filesystem::path dir = exporter::resourcesDir();
        if (dir.empty()) return 0;
        path = (dir / "textures" / (material + ".png")).string();
    }
    if (auto it = mTextures.find(path); it != mTextures.end()) return it->second;
    GLuint id = 0;
    GLint gpuSide = 0;
    mGl->glGetIntegerv(GL_MAX_TEXTURE_SIZE, &gpuSide);
    TextureImage read = readTextureImage(QString::fromStdString(path),
                                         gpuSide > 0 ? std::min(gpuSide, kMaxViewTextureSide)
                                                     : kMaxViewTextureSide);
    if (!read.problem.isEmpty()) {
        mTextureProblems << read.problem;
        if (mProblem) mProblem(read.problem);
    }
    QImage image = std::move(read.image);
    if (!image.isNull()) {
        // OpenGL's first row is v = 0, the image's bottom (a leaf's stem).
        image = image.convertToFormat(QImage::Format_RGBA8888).mirrored();
        mGl->glGenTextures(1, &id);
        mGl->glBindTexture(GL_TEXTURE_2D, id);
        mGl->glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, image.width(), image.height(), 0, GL_RGBA,
                          GL_UNSIGNED_BYTE, image.constBits());
        if (material == "leaf") {
            // Cut-out cards: mipmaps whose alpha keeps level 0's coverage, so that needles and
            // leaves neither thin away nor swell into wedges as they recede (issue #33).
            Image full(image.width(), image.height(), 4);
            std::memcpy(full.pixels.data(), image.constBits(), full.pixels.size());
            const std::vector<Image> mips = alphaTestedMips(full);
            for (std::size_t k = 0; k < mips.size(); ++k)
                mGl->glTexImage2D(GL_TEXTURE_2D, static_cast<GLint>(k + 1), GL_RGBA8, mips[k].width,
                                  mips[k].height, 0, GL_RGBA, GL_UNSIGNED_BYTE,
                                  mips[k].pixels.data());
        } else {
            mGl->glGenerateMipmap(GL_TEXTURE_2D);
        }
        mGl->glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
        mGl->glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
        const GLint wrap = material == "leaf" ? GL_CLAMP_TO_EDGE : GL_REPEAT;
        mGl->glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, wrap);
        mGl->glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, wrap);
        mGl->glBindTexture(GL_TEXTURE_2D, 0);
    }
    mTextures.emplace(path, id); // a file that cannot be read is not tried again
    return id;
}

void TreeBuffers::sync(const std::vector<Source>& meshes, std::size_t treeMeshes,
                       std::size_t& uploads, std::size_t& levelUploads) {
    std::map<const mesh::Mesh*, GpuMesh> kept;
    for (std::size_t k = 0; k < meshes.size(); ++k) {
        const std::shared_ptr<const mesh::Mesh>& treeMesh = meshes[k].mesh;
        if (!treeMesh || treeMesh->empty() || kept.count(treeMesh.get())) continue;
        auto old = mGpuTrees.find(treeMesh.get());
        if (old != mGpuTrees.end()) {
            kept.insert(mGpuTrees.extract(old));
            continue;
        }
        if (!indicesInRange(*treeMesh)) continue;
        GpuMesh gpu;
        gpu.mesh = treeMesh;
        gpu.ranges = rangesOf(*treeMesh);
        bindTextures(*treeMesh, gpu.ranges);
        mGl->glGenVertexArrays(1, &gpu.vao);
        mGl->glGenBuffers(1, &gpu.vbo);
        mGl->glGenBuffers(1, &gpu.ibo);
        mGl->glBindVertexArray(gpu.vao);
        mGl->glBindBuffer(GL_ARRAY_BUFFER, gpu.vbo);
        const std::vector<ViewVertex> data = interleaveVertices(*treeMesh, {});
        mGl->glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(data.size() * sizeof(ViewVertex)),
                          data.data(), GL_STATIC_DRAW);
        mGl->glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, gpu.ibo);
        mGl->glBufferData(GL_ELEMENT_ARRAY_BUFFER,
                          GLsizeiptr(treeMesh->indices.size() * sizeof(std::uint32_t)),
                          treeMesh->indices.data(), GL_STATIC_DRAW);
        setMeshAttributes();
        if (const std::shared_ptr<const skel::Skeleton>& skeleton = meshes[k].skeleton) {
            const WindTable* table = windTableFor(skeleton);
            if (table && uploadWind(*treeMesh, *table, gpu.windVbo)) {
                gpu.windElements = table->texture;
                gpu.skeleton = skeleton;
                gpu.elements = table->elements;
            }
        }
        mGl->glBindVertexArray(0);
        ++(k < treeMeshes ? uploads : levelUploads);
        kept.emplace(treeMesh.get(), std::move(gpu));
    }
    releaseTrees(); // those no tree draws any more
    mGpuTrees = std::move(kept);
    releaseWindTables(false);
}

const TreeBuffers::GpuMesh* TreeBuffers::find(const mesh::Mesh* m) const {
    auto it = mGpuTrees.find(m);
    return it == mGpuTrees.end() ? nullptr : &it->second;
}

void TreeBuffers::releaseTrees() {
    for (auto& [key, gpu] : mGpuTrees) {
        mGl->glDeleteVertexArrays(1, &gpu.vao);
        mGl->glDeleteBuffers(1, &gpu.vbo);
        mGl->glDeleteBuffers(1, &gpu.ibo);
        if (gpu.windVbo) mGl->glDeleteBuffers(1, &gpu.windVbo);
    }
    mGpuTrees.clear();
}

} // namespace sylva::ui
