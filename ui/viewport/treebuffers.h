#pragma once

#include <cstddef>
#include <cstdint>
#include <functional>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include <QOpenGLFunctions_3_3_Core>
#include <QString>
#include <QStringList>

#include <glm/glm.hpp>

#include "ui/generation/vertexdata.h"

namespace sylva::mesh {
struct Mesh;
}
namespace sylva::skel {
struct Skeleton;
}
namespace sylva::wind {
struct WindElements;
}

namespace sylva::ui {

/// A run of triangles drawn in one material: its colour, or its texture when it has one.
struct DrawRange {
    glm::vec3 color;
    std::uint32_t firstIndex = 0;
    std::uint32_t indexCount = 0;
    GLuint texture = 0; ///< 0: the plain colour
    /// The texture's tangent-space normal map ("<texture>_normal.png"), or a flat one: never 0
    /// where texture is set.
    GLuint normalMap = 0;
    bool alphaTest = false; ///< a leaf card cut out by the texture's alpha
    /// Drawn from both sides: everything but Sylva's closed bark tubes (leaf cards, camera
    /// ribbons, obstacles, foreign meshes); the tubes' back faces are culled.
    bool twoSided = true;
};

/// The viewport's meshes on the GPU: the scene mesh (Viewport::setMesh(): a species' tree, or a
/// project's obstacles and terrain), one buffer per distinct tree mesh (trees sharing a mesh
/// share it; a mesh already uploaded is not uploaded again), and the textures their materials
/// name, each file read once. Every call needs the viewport's context current.
class TreeBuffers {
public:
    /// One tree mesh on the GPU, kept while some tree draws it.
    struct GpuMesh {
        std::shared_ptr<const mesh::Mesh> mesh;
        GLuint vao = 0, vbo = 0, ibo = 0;
        std::vector<DrawRange> ranges;
        /// The wind data (ui/generation/windvertexdata.h): the per-vertex buffer (attributes
        /// 5..7 of the vao) and the buffer texture of its skeleton's sway elements; 0 when the
        /// mesh has no node ids or no skeleton came with it (it then stands still).
        GLuint windVbo = 0;
        GLuint windElements = 0;
        std::shared_ptr<const skel::Skeleton> skeleton;     ///< the element table's key
        std::shared_ptr<const wind::WindElements> elements; ///< its elements, for each frame
    };
    /// A mesh to keep on the GPU and the skeleton it was made from (null: no wind data).
    struct Source {
        std::shared_ptr<const mesh::Mesh> mesh;
        std::shared_ptr<const skel::Skeleton> skeleton;
    };

    /// Linear-space albedo of the materials; the fragment shader outputs sRGB.
    static glm::vec3 materialColor(const std::string& material);
    /// Whether every index of \p m names a vertex (a bad one would make the driver read out of
    /// bounds).
    static bool indicesInRange(const mesh::Mesh& m);

    /// Makes the scene mesh's buffers. \p problem hears of each texture file drawn without its
    /// texture (unreadable, or too large), once per file, from inside a frame.
    void initialize(QOpenGLFunctions_3_3_Core* gl, std::function<void(const QString&)> problem);
    /// Frees every buffer and texture.
    void release();

    /// Uploads the scene mesh (none when \p m is null or empty), coloured per vertex by
    /// \p colors when they match its vertices; \p prepared: its vertices made on a worker, used
    /// when they fit and no colours replace theirs. False (nothing uploaded) when an index is
    /// out of range.
    /// \p skeleton: what the mesh was made from, for its wind data (null: none).
    bool uploadScene(const mesh::Mesh* m, const std::vector<glm::vec3>& colors,
                     const std::vector<ViewVertex>* prepared,
                     const std::shared_ptr<const skel::Skeleton>& skeleton = nullptr);
    GLuint sceneVao() const { return mSceneVao; }
    /// The scene mesh's sway elements (a buffer texture), 0 when it has no wind data.
    GLuint sceneWindElements() const { return mSceneWindElements; }
    const std::shared_ptr<const wind::WindElements>& sceneElements() const {
        return mSceneElements;
    }
    /// Uploads the frame's element rotations (appendWindRotations of every swaying tree, one
    /// after the other) into one buffer texture, and returns it (0 when \p rotations is empty
    /// or larger than a buffer texture holds).
    GLuint uploadWindRotations(const std::vector<glm::vec4>& rotations);
    const std::vector<DrawRange>& sceneRanges() const { return mSceneRanges; }
    /// Whether the uploaded scene mesh holds attribute colours.
    bool sceneVertexColors() const { return mSceneVertexColors; }

    /// Keeps the buffers of \p meshes (uploading those not on the GPU yet) and frees the rest.
    /// The first \p treeMeshes are the trees' own meshes, counted in \p uploads; the rest
    /// (coarser levels) in \p levelUploads.
    /// Each mesh's wind data is made from its skeleton when it is uploaded; meshes of one
    /// skeleton (a tree's levels) share its element table.
    void sync(const std::vector<Source>& meshes, std::size_t treeMeshes, std::size_t& uploads,
              std::size_t& levelUploads);
    const GpuMesh* find(const mesh::Mesh* m) const;
    bool hasTrees() const { return !mGpuTrees.empty(); }
    std::size_t treeMeshCount() const { return mGpuTrees.size(); }

    /// Texture files drawn without their texture, one line each, in the order met.
    const QStringList& textureProblems() const { return mTextureProblems; }

private:
    /// A skeleton's sway elements: on the CPU for the wind data of each of its meshes, on the
    /// GPU as a buffer texture for the shader.
    struct WindTable {
        std::shared_ptr<const skel::Skeleton> skeleton; ///< kept alive for the key
        std::shared_ptr<const wind::WindElements> elements;
        GLuint buffer = 0, texture = 0;
    };
    /// The table of \p skeleton, made when missing; null when it has too many elements for a
    /// buffer texture.
    const WindTable* windTableFor(const std::shared_ptr<const skel::Skeleton>& skeleton);
    /// Uploads the wind data of \p m into \p vbo and points the bound vao's attributes 5..7
    /// at it; false (attributes off) when \p m has no node ids.
    bool uploadWind(const mesh::Mesh& m, const WindTable& table, GLuint& vbo);
    void releaseWindTables(bool all);
    void setMeshAttributes();
    /// The textures of \p m's submeshes on \p ranges (rangesOf's order).
    void bindTextures(const mesh::Mesh& m, std::vector<DrawRange>& ranges);
    /// The GL texture of \p file (Sylva's shipped one for \p material when empty), loaded once;
    /// 0 when there is none or it cannot be read.
    GLuint textureFor(const std::string& material, const std::string& file);
    /// The GL texture of the normal map drawn for \p file (exporter::companionTexture), or a
    /// 1×1 flat normal when it has none, so the textured shader needs no branch.
    GLuint normalMapFor(const std::string& material, const std::string& file);
    void releaseTrees();

    QOpenGLFunctions_3_3_Core* mGl = nullptr;
    std::function<void(const QString&)> mProblem;
    GLuint mSceneVao = 0, mSceneVbo = 0, mSceneIbo = 0;
    GLuint mSceneWindVbo = 0, mSceneWindElements = 0;
    std::shared_ptr<const wind::WindElements> mSceneElements;
    GLuint mRotationsBuffer = 0, mRotationsTexture = 0;
    GLint mMaxBufferTexels = -1;
    std::shared_ptr<const skel::Skeleton> mSceneSkeleton;
    std::map<const skel::Skeleton*, WindTable> mWindTables;
    std::vector<DrawRange> mSceneRanges;
    bool mSceneVertexColors = false;
    std::map<const mesh::Mesh*, GpuMesh> mGpuTrees;
    std::map<std::string, GLuint> mTextures; ///< by file path; 0 for files that did not load
    GLuint mFlatNormal = 0;
    QStringList mTextureProblems;
};

} // namespace sylva::ui
