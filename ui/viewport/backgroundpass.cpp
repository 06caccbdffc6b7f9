#include "ui/viewport/backgroundpass.h"

#include <QOpenGLShaderProgram>

#include <glm/glm.hpp>

#include "ui/viewport/shaderprogram.h"

namespace sylva::ui {

namespace {

// sRGB colours of the background gradient.
constexpr glm::vec3 kBackgroundTop{0.42f, 0.53f, 0.68f};
constexpr glm::vec3 kBackgroundBottom{0.84f, 0.86f, 0.88f};

} // namespace

bool BackgroundPass::initialize(QOpenGLFunctions_3_3_Core* gl, QString& error) {
    mGl = gl;
    mProgram = buildShaderProgram(QStringLiteral("background.vert"),
                                  QStringLiteral("background.frag"), error);
    if (!mProgram) return false;
    mGl->glGenVertexArrays(1, &mEmptyVao);
    return true;
}

void BackgroundPass::release() {
    if (mGl) mGl->glDeleteVertexArrays(1, &mEmptyVao);
    mEmptyVao = 0;
    mProgram.reset();
}

void BackgroundPass::draw() {
    QOpenGLFunctions_3_3_Core& gl = *mGl;
    gl.glClearColor(kBackgroundBottom.x, kBackgroundBottom.y, kBackgroundBottom.z, 1.0f);
    gl.glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    gl.glDisable(GL_DEPTH_TEST);
    gl.glDepthMask(GL_FALSE);
    mProgram->bind();
    setUniform(*mProgram, "uTop", kBackgroundTop);
    setUniform(*mProgram, "uBottom", kBackgroundBottom);
    gl.glBindVertexArray(mEmptyVao);
    gl.glDrawArrays(GL_TRIANGLES, 0, 3);
}

} // namespace sylva::ui
