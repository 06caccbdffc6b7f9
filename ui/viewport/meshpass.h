#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <utility>
#include <vector>

#include <QByteArray>
#include <QOpenGLFunctions_3_3_Core>
#include <QString>

#include <glm/glm.hpp>

#include "engine/wind/windmodel.h"
#include "ui/viewport/treebuffers.h"
#include "ui/viewport/windclock.h"

class QOpenGLShaderProgram;

namespace sylva::mesh {
struct Mesh;
}

namespace sylva::ui {

/// Draws meshes that are on the GPU (treebuffers) with shaders/mesh.*: one mesh at a place,
/// a variant level's instances in instanced calls, the scene mesh's ranges. It holds the mesh
/// shader's variants, the uniforms they share and the instance buffer, and under a software
/// renderer flushes every kFlushTriangles so that the rasteriser's threads start early.
class MeshPass {
public:
    /// The mesh shader's variants (a bit set): compiled apart so that bark does not pay for
    /// the leaves' texture and cut-out, and keeps the early depth test.
    /// WIND sways the vertices (wind.glsl) and is drawn only for meshes with wind data;
    /// INSTANCED takes the transform per instance (never with WIND: swaying instances are drawn
    /// one by one, each with its own place in the wind's loop).
    static constexpr int kTextured = 1, kCutout = 2, kWind = 4, kInstanced = 8, kVariants = 16;
    /// Whether variant \p v is ever drawn (WIND and INSTANCED never together).
    static bool isUsed(int v) { return !((v & kWind) && (v & kInstanced)); }
    /// The lines put after the #version line of shaders/mesh.* for variant \p v.
    static QByteArray defines(int v);
    /// Triangles between the flushes of a frame under a software renderer (drawRanges()).
    static constexpr std::size_t kFlushTriangles = 40000;
    /// shaders/mesh.vert's per-instance transform (INSTANCED), four locations from here.
    static constexpr GLuint kInstanceAttribute = 12;

    /// What every mesh variant shares in a draw; a variant is brought up to date when used.
    struct Uniforms {
        glm::mat4 viewProj{1.0f};
        glm::mat4 model{1.0f};
        glm::vec3 eye{0.0f};
        glm::vec3 light{0.0f, 1.0f, 0.0f};
        bool vertexColor = false;
        float highlight = 0.0f;
        wind::WindFrame wind; ///< its time is the drawn tree's
        int windBase = 0;     ///< the drawn tree's first element in the frame's rotations
    };
    /// Triangles and calls since beginFrame().
    struct Counts {
        std::size_t triangles = 0;
        std::size_t windTriangles = 0;
        std::size_t instancedDrawCalls = 0;
    };

    /// Builds every used variant; false (and \p error) when one does not compile.
    /// \p buffers: the meshes drawn; \p wind: the clock a swaying mesh's frame comes from;
    /// \p software: a software renderer (flushes as above).
    bool initialize(QOpenGLFunctions_3_3_Core* gl, const TreeBuffers* buffers,
                    const WindClock* wind, bool software, QString& error);
    void release();

    void setBackFaceCulling(bool on) { mCullBackFaces = on; }
    bool backFaceCulling() const { return mCullBackFaces; }

    void beginFrame();
    const Counts& counts() const { return mCounts; }
    void setUniforms(const Uniforms& uniforms);
    const Uniforms& uniforms() const { return mUniforms; }

    /// The scene mesh (treebuffers' scene vao bound by the caller) in its ranges; with
    /// \p windElements its sway elements (a buffer texture, 0: it stands still).
    void drawScene(const std::vector<DrawRange>& ranges, GLuint windElements);
    /// Mesh \p m at \p transform; \p windBase: where its element rotations start in the
    /// frame's rotations (-1: drawn without wind), swaying \p windPhase into the wind's loop.
    void drawMesh(const mesh::Mesh& m, const glm::mat4& transform, float highlight, float windPhase,
                  int windBase);
    /// Each variant level's instances (nearest level first) with instanced draw calls.
    void
    drawInstanced(const std::vector<std::pair<const mesh::Mesh*, std::vector<glm::mat4>>>& groups);

private:
    QOpenGLShaderProgram& useProgram(int variant);
    /// \p instances > 0: each range drawn once per instance of the instance buffer's bound run
    /// (drawInstanced()), with the instanced mesh program.
    void drawRanges(const std::vector<DrawRange>& ranges, GLsizei instances = 0);
    void bindWindElements(GLuint texture);
    void countRanges(const std::vector<DrawRange>& ranges);

    QOpenGLFunctions_3_3_Core* mGl = nullptr;
    const TreeBuffers* mBuffers = nullptr;
    const WindClock* mWind = nullptr;
    bool mSoftware = false;
    bool mCullBackFaces = true; ///< of the bark (Viewport::setBackFaceCulling())
    std::size_t mUnflushed = 0; ///< triangles drawn since the last flush
    bool mDrawWind = false;     ///< drawRanges() takes the WIND variant
    GLuint mInstanceVbo = 0;
    std::array<std::unique_ptr<QOpenGLShaderProgram>, kVariants> mPrograms;
    std::array<std::uint64_t, kVariants> mProgramStamps{};
    Uniforms mUniforms;
    std::uint64_t mUniformsStamp = 1;
    Counts mCounts;
};

} // namespace sylva::ui
