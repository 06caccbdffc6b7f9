#include "ui/viewport/impostors.h"

#include <algorithm>

#include <QMatrix4x4>
#include <QOpenGLShaderProgram>

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/type_ptr.hpp>

#include "engine/mesh/mesh.h"

namespace sylva::ui {

namespace {

// Two crossed cards from the vertex id alone: card 0 in the tree's xy plane (the front
// picture, left half of the texture), card 1 in its zy plane (the side picture, right half).
const char* const kCardVertexShader = R"(#version 330 core
uniform mat4 uViewProj;
uniform mat4 uModel;
uniform vec3 uLo;
uniform vec3 uHi;
out vec2 vUv;
void main() {
    const vec2 corners[6] = vec2[6](vec2(0, 0), vec2(1, 0), vec2(1, 1),
                                    vec2(0, 0), vec2(1, 1), vec2(0, 1));
    int card = gl_VertexID / 6;
    vec2 st = corners[gl_VertexID % 6];
    vec3 c = 0.5 * (uLo + uHi);
    float y = mix(uLo.y, uHi.y, st.y);
    vec3 p = card == 0 ? vec3(mix(uLo.x, uHi.x, st.x), y, c.z)
                       : vec3(c.x, y, mix(uLo.z, uHi.z, st.x));
    vUv = vec2(0.5 * float(card) + 0.5 * st.x, st.y);
    gl_Position = uViewProj * uModel * vec4(p, 1.0);
}
)";

// The pictures are already shaded and sRGB-encoded; the selection blends towards orange in
// linear space as the mesh shader does.
const char* const kCardFragmentShader = R"(#version 330 core
in vec2 vUv;
uniform sampler2D uPicture;
uniform float uHighlight;
out vec4 fragColor;
void main() {
    // Coverage averages down the mipmaps: one level finer than the screen asks for and a
    // threshold under a half keep sparse crowns about as dense as the meshes look at that size
    // (without multisampling any leaf over a pixel's centre fills it) and bare branches open.
    vec4 t = texture(uPicture, vUv, -1.0);
    if (t.a < 0.35) discard;
    vec3 linear = pow(t.rgb / t.a, vec3(2.2)); // the pictures are premultiplied (clear: 0)
    linear = mix(linear, vec3(1.0, 0.45, 0.05), uHighlight);
    fragColor = vec4(pow(linear, vec3(1.0 / 2.2)), 1.0);
}
)";

void setMatrix(QOpenGLShaderProgram& program, const char* name, const glm::mat4& m) {
    program.setUniformValue(program.uniformLocation(name),
                            QMatrix4x4(glm::value_ptr(m)).transposed());
}

} // namespace

bool Impostors::initialize(QOpenGLFunctions_3_3_Core* gl, QString& error) {
    mGl = gl;
    mProgram = std::make_unique<QOpenGLShaderProgram>();
    if (!mProgram->addShaderFromSourceCode(QOpenGLShader::Vertex, kCardVertexShader) ||
        !mProgram->addShaderFromSourceCode(QOpenGLShader::Fragment, kCardFragmentShader) ||
        !mProgram->link()) {
        error = QStringLiteral("shader error: ") + mProgram->log();
        mProgram.reset();
        return false;
    }
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
    setMatrix(*mProgram, "uViewProj", viewProj);
    mProgram->setUniformValue("uPicture", 0);
    mGl->glActiveTexture(GL_TEXTURE0);
    mGl->glBindVertexArray(mVao);
    // Both faces of a card are drawn.
    mGl->glDisable(GL_CULL_FACE);
}

void Impostors::draw(const mesh::Mesh* m, const glm::mat4& transform, float highlight) {
    auto it = mCards.find(m);
    if (it == mCards.end()) return;
    setMatrix(*mProgram, "uModel", transform);
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
