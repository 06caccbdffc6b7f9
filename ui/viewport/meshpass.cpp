#include "ui/viewport/meshpass.h"

#include <algorithm>
#include <cstdint>

#include <QOpenGLShaderProgram>

#include "ui/viewport/shaderprogram.h"
#include "ui/viewport/windshader.h"

namespace sylva::ui {

QByteArray MeshPass::defines(int v) {
    QByteArray out;
    if (v & kTextured) out += "#define TEXTURED 1\n";
    if (v & kCutout) out += "#define CUTOUT 1\n";
    if (v & kInstanced) out += "#define INSTANCED 1\n";
    if (v & kWind) out += "#define WIND 1\n";
    return out;
}

bool MeshPass::initialize(QOpenGLFunctions_3_3_Core* gl, const TreeBuffers* buffers,
                          const WindClock* wind, bool software, QString& error) {
    mGl = gl;
    mBuffers = buffers;
    mWind = wind;
    mSoftware = software;
    // The mesh shader's variants: shaders/mesh.frag with TEXTURED and CUTOUT defined or not.
    for (int v = 0; v < kVariants; ++v) {
        if (!isUsed(v)) continue; // never drawn (drawInstanced())
        mPrograms[std::size_t(v)] = buildShaderProgram(
            QStringLiteral("mesh.vert"), QStringLiteral("mesh.frag"), error, defines(v));
        if (!mPrograms[std::size_t(v)]) return false;
    }
    mGl->glGenBuffers(1, &mInstanceVbo);
    return true;
}

void MeshPass::release() {
    if (mGl) mGl->glDeleteBuffers(1, &mInstanceVbo);
    mInstanceVbo = 0;
    for (auto& program : mPrograms)
        program.reset();
}

void MeshPass::beginFrame() {
    mUnflushed = 0;
    mCounts = {};
}

void MeshPass::setUniforms(const Uniforms& uniforms) {
    mUniforms = uniforms;
    ++mUniformsStamp;
}

QOpenGLShaderProgram& MeshPass::useProgram(int variant) {
    QOpenGLShaderProgram& program = *mPrograms[std::size_t(variant)];
    program.bind();
    std::uint64_t& stamp = mProgramStamps[std::size_t(variant)];
    if (stamp != mUniformsStamp) {
        // Only what changed since this variant was last used is stale; setting all is cheap.
        const Uniforms& u = mUniforms;
        setUniform(program, "uViewProj", u.viewProj);
        setUniform(program, "uModel", u.model);
        setUniform(program, "uEye", u.eye);
        setUniform(program, "uLightDir", u.light);
        program.setUniformValue("uVertexColor", u.vertexColor);
        program.setUniformValue("uHighlight", u.highlight);
        program.setUniformValue("uTexture", 0);
        program.setUniformValue("uNormalMap", 1);
        if (variant & kWind) setWindUniforms(program, u.wind, u.windBase);
        stamp = mUniformsStamp;
    }
    return program;
}

void MeshPass::countRanges(const std::vector<DrawRange>& ranges) {
    for (const DrawRange& r : ranges) {
        mCounts.triangles += r.indexCount / 3;
        if (mDrawWind) mCounts.windTriangles += r.indexCount / 3;
    }
}

void MeshPass::drawScene(const std::vector<DrawRange>& ranges, GLuint windElements) {
    mDrawWind = windElements != 0;
    if (mDrawWind) bindWindElements(windElements);
    drawRanges(ranges);
    countRanges(ranges);
    mDrawWind = false;
}

void MeshPass::drawMesh(const mesh::Mesh& m, const glm::mat4& transform, float highlight,
                        float windPhase, int windBase) {
    const TreeBuffers::GpuMesh* gpu = mBuffers->find(&m);
    if (!gpu) return;
    Uniforms u = mUniforms;
    u.model = transform;
    u.highlight = highlight;
    mDrawWind = windBase >= 0 && gpu->windElements != 0;
    if (mDrawWind) {
        u.wind = mWind->frameAt(windPhase);
        u.windBase = windBase;
        bindWindElements(gpu->windElements);
    }
    setUniforms(u);
    mGl->glBindVertexArray(gpu->vao);
    drawRanges(gpu->ranges);
    countRanges(gpu->ranges);
    mDrawWind = false;
}

void MeshPass::bindWindElements(GLuint texture) {
    mGl->glActiveTexture(GL_TEXTURE0 + kWindElementsUnit);
    mGl->glBindTexture(GL_TEXTURE_BUFFER, texture);
    mGl->glActiveTexture(GL_TEXTURE0);
}

void MeshPass::drawInstanced(
    const std::vector<std::pair<const mesh::Mesh*, std::vector<glm::mat4>>>& groups) {
    if (groups.empty()) return;
    QOpenGLFunctions_3_3_Core& gl = *mGl;
    // Every instance's transform in one buffer, each level's instances one run of it.
    std::vector<glm::mat4> all;
    for (const auto& [m, list] : groups)
        all.insert(all.end(), list.begin(), list.end());
    gl.glBindBuffer(GL_ARRAY_BUFFER, mInstanceVbo);
    gl.glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(all.size() * sizeof(glm::mat4)), all.data(),
                    GL_STREAM_DRAW);
    Uniforms u = mUniforms;
    u.model = glm::mat4(1.0f);
    u.highlight = 0.0f;
    setUniforms(u);
    std::size_t first = 0;
    for (const auto& [m, list] : groups) {
        const TreeBuffers::GpuMesh* gpu = mBuffers->find(m);
        gl.glBindVertexArray(gpu->vao);
        std::size_t triangles = 0;
        for (const DrawRange& r : gpu->ranges)
            triangles += r.indexCount / 3;
        mCounts.triangles += triangles * list.size();
        // Under a software renderer, runs of about kFlushTriangles, each flushed (drawRanges),
        // so the rasteriser's threads start on the nearer instances while this one bins on.
        const std::size_t run =
            mSoftware
                ? std::max<std::size_t>(1, kFlushTriangles / std::max<std::size_t>(1, triangles))
                : list.size();
        for (std::size_t done = 0; done < list.size(); done += run) {
            // The instance transform (shaders/mesh.vert, INSTANCED): locations 12-15, a column
            // each, one step per instance.
            for (GLuint c = 0; c < 4; ++c) {
                gl.glEnableVertexAttribArray(kInstanceAttribute + c);
                gl.glVertexAttribPointer(
                    kInstanceAttribute + c, 4, GL_FLOAT, GL_FALSE, sizeof(glm::mat4),
                    reinterpret_cast<const void*>(((first + done) * 4 + c) * sizeof(glm::vec4)));
                gl.glVertexAttribDivisor(kInstanceAttribute + c, 1);
            }
            drawRanges(gpu->ranges, GLsizei(std::min(run, list.size() - done)));
        }
        first += list.size();
    }
    gl.glBindBuffer(GL_ARRAY_BUFFER, 0);
}

void MeshPass::drawRanges(const std::vector<DrawRange>& ranges, GLsizei instances) {
    QOpenGLFunctions_3_3_Core& gl = *mGl;
    // Leaf cards cut out by alpha to coverage where the target is multisampled (issue #33);
    // the written alpha is then 1 (ALPHA_TO_ONE), as every other draw's.
    GLint samples = 0;
    gl.glGetIntegerv(GL_SAMPLES, &samples);
    for (const DrawRange& r : ranges) {
        QOpenGLShaderProgram& program =
            useProgram((r.texture != 0 ? kTextured : 0) | (r.alphaTest ? kCutout : 0) |
                       (mDrawWind ? kWind : 0) | (instances > 0 ? kInstanced : 0));
        setUniform(program, "uAlbedo", r.color);
        const bool toCoverage = r.alphaTest && r.texture != 0 && samples > 1;
        if (r.alphaTest && r.texture != 0) program.setUniformValue("uAlphaToCoverage", toCoverage);
        if (toCoverage) {
            gl.glEnable(GL_SAMPLE_ALPHA_TO_COVERAGE);
            gl.glEnable(GL_SAMPLE_ALPHA_TO_ONE);
        } else {
            gl.glDisable(GL_SAMPLE_ALPHA_TO_COVERAGE);
            gl.glDisable(GL_SAMPLE_ALPHA_TO_ONE);
        }
        if (r.texture != 0) {
            gl.glActiveTexture(GL_TEXTURE1);
            gl.glBindTexture(GL_TEXTURE_2D, r.normalMap);
            gl.glActiveTexture(GL_TEXTURE0);
        }
        gl.glBindTexture(GL_TEXTURE_2D, r.texture);
        if (r.twoSided || !mCullBackFaces)
            gl.glDisable(GL_CULL_FACE);
        else
            gl.glEnable(GL_CULL_FACE);
        if (instances > 0) {
            // One call for every instance; under a software renderer a flush after it hands
            // the rasteriser's threads what is binned so far (see below).
            gl.glDrawElementsInstanced(GL_TRIANGLES, GLsizei(r.indexCount), GL_UNSIGNED_INT,
                                       reinterpret_cast<void*>(std::uintptr_t(r.firstIndex) * 4u),
                                       instances);
            ++mCounts.instancedDrawCalls;
            mUnflushed += std::size_t(r.indexCount / 3) * std::size_t(instances);
            if (mSoftware && mUnflushed >= kFlushTriangles) {
                gl.glFlush();
                mUnflushed = 0;
            }
            continue;
        }
        if (!mSoftware) {
            gl.glDrawElements(GL_TRIANGLES, GLsizei(r.indexCount), GL_UNSIGNED_INT,
                              reinterpret_cast<void*>(std::uintptr_t(r.firstIndex) * 4u));
            continue;
        }
        // Mesa llvmpipe transforms and bins on this thread and rasterises on its own threads
        // only when the frame is flushed, so a frame used one core at a time: a flush every
        // kFlushTriangles hands them what is drawn so far (the nearer trees, or the first
        // part of one large mesh) while this thread goes on with the rest.
        std::size_t first = r.firstIndex, left = r.indexCount / 3;
        while (left > 0) {
            const std::size_t n = std::min(left, kFlushTriangles - mUnflushed);
            gl.glDrawElements(GL_TRIANGLES, GLsizei(3 * n), GL_UNSIGNED_INT,
                              reinterpret_cast<void*>(std::uintptr_t(first) * 4u));
            first += 3 * n;
            left -= n;
            mUnflushed += n;
            if (mUnflushed >= kFlushTriangles) {
                gl.glFlush();
                mUnflushed = 0;
            }
        }
    }
    gl.glBindTexture(GL_TEXTURE_2D, 0);
    gl.glDisable(GL_CULL_FACE);
    gl.glDisable(GL_SAMPLE_ALPHA_TO_COVERAGE);
    gl.glDisable(GL_SAMPLE_ALPHA_TO_ONE);
}

} // namespace sylva::ui
