#include "ui/viewport/grid.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include <QOpenGLShaderProgram>

#include "ui/viewport/shaderprogram.h"

namespace sylva::ui {

void Grid::initialize(QOpenGLFunctions_3_3_Core* gl) {
    mGl = gl;
    createLineBuffers(*mGl, mVao, mVbo);
    mExtent = 0.0f;
}

void Grid::release() {
    if (!mGl) return;
    deleteBuffers(*mGl, mVao, mVbo);
    mGl = nullptr;
}

void Grid::build(float radius, const glm::vec3& lo, const glm::vec3& hi) {
    // A power-of-ten spacing that gives a few dozen lines across the framed scene.
    const float step = std::pow(10.0f, std::floor(std::log10(std::max(radius, 1e-3f) * 0.5f)));
    const int half = std::max(5, int(std::ceil(2.0f * radius / step)));
    mExtent = float(half) * step;
    const glm::vec3 centre = 0.5f * (lo + hi);
    const float cx = std::round(centre.x / step) * step;
    const float cz = std::round(centre.z / step) * step;
    const float y = std::min(0.0f, lo.y);
    mCenter = glm::vec3(cx, y, cz);

    std::vector<float> data;
    data.reserve(std::size_t(4 * half + 2) * 2 * 7);
    auto line = [&](glm::vec3 a, glm::vec3 b, glm::vec4 c) {
        for (const glm::vec3& p : {a, b})
            data.insert(data.end(), {p.x, p.y, p.z, c.x, c.y, c.z, c.w});
    };
    const glm::vec4 minor(0.30f, 0.33f, 0.37f, 0.30f);
    const glm::vec4 major(0.25f, 0.27f, 0.31f, 0.60f);
    for (int i = -half; i <= half; ++i) {
        const float x = cx + float(i) * step;
        const float z = cz + float(i) * step;
        const long long gx = std::llround(x / step);
        const long long gz = std::llround(z / step);
        const glm::vec4 cX =
            gx == 0 ? glm::vec4(0.30f, 0.42f, 0.75f, 0.85f) : (gx % 10 == 0 ? major : minor);
        const glm::vec4 cZ =
            gz == 0 ? glm::vec4(0.75f, 0.30f, 0.28f, 0.85f) : (gz % 10 == 0 ? major : minor);
        // Line of constant x runs along z (the z axis when x == 0), and vice versa.
        line({x, y, cz - mExtent}, {x, y, cz + mExtent}, cX);
        line({cx - mExtent, y, z}, {cx + mExtent, y, z}, cZ);
    }
    mGl->glBindBuffer(GL_ARRAY_BUFFER, mVbo);
    mGl->glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(data.size() * sizeof(float)), data.data(),
                      GL_STATIC_DRAW);
    mGl->glBindBuffer(GL_ARRAY_BUFFER, 0);
    mVertexCount = GLsizei(data.size() / 7);
}

void Grid::draw(QOpenGLShaderProgram& lines, const glm::mat4& viewProj) {
    if (mVertexCount <= 0) return;
    mGl->glEnable(GL_BLEND);
    mGl->glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    lines.bind();
    setUniform(lines, "uViewProj", viewProj);
    setUniform(lines, "uCenter", mCenter);
    lines.setUniformValue("uExtent", mExtent);
    mGl->glBindVertexArray(mVao);
    mGl->glDrawArrays(GL_LINES, 0, mVertexCount);
    mGl->glDisable(GL_BLEND);
}

} // namespace sylva::ui
