#include "ui/viewport/impostors.h"

#include <algorithm>

#include <QOpenGLShaderProgram>

#include <glm/gtc/matrix_transform.hpp>

#include "engine/mesh/mesh.h"
#include "ui/viewport/shaderprogram.h"

namespace sylva::ui {

bool Impostors::initialize(QOpenGLFunctions_3_3_Core* gl, QString& error) {
    mGl = gl;
    // Two crossed cards drawn from the vertex id alone (shaders/card.vert).
    mProgram = buildShaderProgram(QStringLiteral("card.vert"), QStringLiteral("card.frag"), error);
    if (!mProgram) return false;
    gl->glGenVertexArrays(1, &mVao);
    return true;
}

void Impostors::release() {
    if (!mGl) return;
    for (auto& [key, card] : mCards)
        mGl->glDeleteTextures(1, &card.texture);
    mCards.clear();
    if (mFbo) mGl->glDeleteFramebuffers(1, &mFbo);
    if (mDepth) mGl->glDeleteRenderbuffers(1, &mDepth);
    if (mVao) mGl->glDeleteVertexArrays(1, &mVao);
    mFbo = mDepth = mVao = 0;
    mProgram.reset();
    mGl = nullptr;
}

void Impostors::bake(const std::shared_ptr<const mesh::Mesh>& m, const DrawMesh& draw, GLuint fbo,
                     const glm::ivec4& viewport) {
    if (!mGl || !mProgram || !m || m->empty() || has(m.get())) return;
    QOpenGLFunctions_3_3_Core& gl = *mGl;
    Card card;
    card.mesh = m;
    card.lo = glm::vec3(std::numeric_limits<float>::max());
    card.hi = glm::vec3(std::numeric_limits<float>::lowest());
    for (const glm::vec3& p : m->positions) {
        card.lo = glm::min(card.lo, p);
        card.hi = glm::max(card.hi, p);
    }
    if (!mFbo) {
        gl.glGenFramebuffers(1, &mFbo);
        gl.glGenRenderbuffers(1, &mDepth);
        gl.glBindRenderbuffer(GL_RENDERBUFFER, mDepth);
        gl.glRenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH_COMPONENT24, 2 * kSize, kSize);
    }
    gl.glGenTextures(1, &card.texture);
    gl.glBindTexture(GL_TEXTURE_2D, card.texture);
    gl.glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, 2 * kSize, kSize, 0, GL_RGBA, GL_UNSIGNED_BYTE,
                    nullptr);
    gl.glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
    gl.glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    gl.glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    gl.glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    gl.glBindFramebuffer(GL_FRAMEBUFFER, mFbo);
    gl.glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, card.texture, 0);
    gl.glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, mDepth);
    // Transparent black: the picture is premultiplied by its coverage, so that mipmaps average
    // the tree's colours without the background's (the shader divides by alpha).
    gl.glClearColor(0.0f, 0.0f, 0.0f, 0.0f);
    gl.glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    gl.glEnable(GL_DEPTH_TEST);
    gl.glDepthMask(GL_TRUE);
    const glm::vec3 c = 0.5f * (card.lo + card.hi);
    const glm::vec3 half = glm::max(0.5f * (card.hi - card.lo), glm::vec3(1e-3f));
    const float reach = 2.0f * glm::length(half) + 1.0f;
    const glm::vec3 up(0.0f, 1.0f, 0.0f);
    // Front: from +z looking along -z (screen right = +x); side: from -x along +x (right = +z).
    for (int view = 0; view < 2; ++view) {
        const glm::vec3 forward = view == 0 ? glm::vec3(0, 0, -1) : glm::vec3(1, 0, 0);
        const glm::vec3 right = glm::cross(forward, up);
        const glm::vec3 eye = c - reach * forward;
        const float across = view == 0 ? half.x : half.z;
        const glm::mat4 viewProj =
            glm::ortho(-across, across, -half.y, half.y, 0.0f, 2.0f * reach) *
            glm::lookAt(eye, c, up);
        // The viewport's key light, placed as it is for a camera looking this way.
        const glm::vec3 light = glm::normalize(-0.5f * forward + 0.8f * up - 0.6f * right);
        gl.glViewport(view * kSize, 0, kSize, kSize);
        draw(*m, viewProj, eye, light);
    }
    gl.glBindTexture(GL_TEXTURE_2D, card.texture);
    gl.glGenerateMipmap(GL_TEXTURE_2D);
    gl.glBindTexture(GL_TEXTURE_2D, 0);
    gl.glBindFramebuffer(GL_FRAMEBUFFER, fbo);
    gl.glViewport(viewport.x, viewport.y, viewport.z, viewport.w);
    mCards.emplace(m.get(), std::move(card));
}

void Impostors::retain(const std::function<bool(const mesh::Mesh*)>& keep) {
    for (auto it = mCards.begin(); it != mCards.end();) {
        if (keep(it->first)) {
            ++it;
            continue;
        }
        if (mGl) mGl->glDeleteTextures(1, &it->second.texture);
        it = mCards.erase(it);
    }
}

void Impostors::begin(const glm::mat4& viewProj) {
    mProgram->bind();
    setUniform(*mProgram, "uViewProj", viewProj);
    mProgram->setUniformValue("uPicture", 0);
    mGl->glActiveTexture(GL_TEXTURE0);
    mGl->glBindVertexArray(mVao);
    // Both faces of a card are drawn.
    mGl->glDisable(GL_CULL_FACE);
}

void Impostors::draw(const mesh::Mesh* m, const glm::mat4& transform, float highlight) {
    auto it = mCards.find(m);
    if (it == mCards.end()) return;
    setUniform(*mProgram, "uModel", transform);
    mProgram->setUniformValue("uLo", it->second.lo.x, it->second.lo.y, it->second.lo.z);
    mProgram->setUniformValue("uHi", it->second.hi.x, it->second.hi.y, it->second.hi.z);
    mProgram->setUniformValue("uHighlight", highlight);
    mGl->glBindTexture(GL_TEXTURE_2D, it->second.texture);
    mGl->glDrawArrays(GL_TRIANGLES, 0, 12);
}

void Impostors::end() {
    mGl->glBindTexture(GL_TEXTURE_2D, 0);
    mGl->glBindVertexArray(0);
}

} // namespace sylva::ui
