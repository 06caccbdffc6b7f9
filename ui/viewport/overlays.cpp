#include "ui/viewport/overlays.h"

#include <algorithm>
#include <utility>

#include <QOpenGLShaderProgram>

#include <glm/gtc/matrix_transform.hpp>

#include "ui/viewport/shaderprogram.h"

namespace sylva::ui {

void Overlays::initialize(QOpenGLFunctions_3_3_Core* gl) {
    mGl = gl;
    createLineBuffers(*mGl, mVao, mVbo);
}

void Overlays::release() {
    if (!mGl) return;
    deleteBuffers(*mGl, mVao, mVbo);
    mGl = nullptr;
}

void Overlays::drawBand(QOpenGLShaderProgram& program, const QRect& band, const QSize& widget) {
    if (band.isEmpty()) return;
    // In widget pixels, y down; a translucent fill inside a sharp outline.
    const glm::mat4 pixels = glm::ortho(0.0f, float(std::max(1, widget.width())),
                                        float(std::max(1, widget.height())), 0.0f);
    const float x0 = float(band.left()), y0 = float(band.top());
    const float x1 = float(band.right() + 1), y1 = float(band.bottom() + 1);
    const glm::vec4 fill(0.25f, 0.55f, 0.95f, 0.18f), edge(0.25f, 0.55f, 0.95f, 0.95f);
    std::vector<float> data;
    auto vertex = [&data](float x, float y, const glm::vec4& c) {
        data.insert(data.end(), {x, y, 0.0f, c.x, c.y, c.z, c.w});
    };
    for (const auto& [x, y] : {std::pair{x0, y0}, {x1, y0}, {x1, y1}, {x0, y0}, {x1, y1}, {x0, y1}})
        vertex(x, y, fill);
    const std::pair<float, float> corners[] = {{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}};
    for (int k = 0; k < 4; ++k) {
        vertex(corners[k].first, corners[k].second, edge);
        vertex(corners[(k + 1) % 4].first, corners[(k + 1) % 4].second, edge);
    }
    drawOnTop(program, data, pixels, 6);
}

std::vector<float> screenBands(const std::vector<OverlayLine>& lines, const glm::mat4& viewProj,
                               const glm::vec2& pixels) {
    std::vector<float> out;
    if (pixels.x < 1.0f || pixels.y < 1.0f) return out;
    for (const OverlayLine& l : lines) {
        if (l.width <= 1.0f) continue;
        glm::vec4 ca = viewProj * glm::vec4(l.a, 1.0f), cb = viewProj * glm::vec4(l.b, 1.0f);
        // In front of the near plane where z > -w: cut what lies behind it.
        const float da = ca.z + ca.w, db = cb.z + cb.w;
        if (da <= 0.0f && db <= 0.0f) continue;
        if (da < 0.0f) ca += (cb - ca) * (da / (da - db));
        if (db < 0.0f) cb += (ca - cb) * (db / (db - da));
        if (ca.w <= 1e-9f || cb.w <= 1e-9f) continue;
        const glm::vec3 na = glm::vec3(ca) / ca.w, nb = glm::vec3(cb) / cb.w;
        const glm::vec2 sa = (glm::vec2(na) * 0.5f + 0.5f) * pixels;
        const glm::vec2 sb = (glm::vec2(nb) * 0.5f + 0.5f) * pixels;
        const glm::vec2 d = sb - sa;
        const float length = glm::length(d);
        const glm::vec2 along = length > 1e-6f ? d / length : glm::vec2(1.0f, 0.0f);
        const glm::vec2 half = along * (0.5f * l.width);
        const glm::vec2 across(-half.y, half.x);
        auto vertex = [&out, &pixels, &l](const glm::vec2& px, float z) {
            const glm::vec2 ndc = px / pixels * 2.0f - 1.0f;
            out.insert(out.end(), {ndc.x, ndc.y, z, l.color.x, l.color.y, l.color.z, l.color.w});
        };
        const glm::vec2 a0 = sa - half - across, a1 = sa - half + across;
        const glm::vec2 b0 = sb + half - across, b1 = sb + half + across;
        vertex(a0, na.z);
        vertex(b0, nb.z);
        vertex(b1, nb.z);
        vertex(a0, na.z);
        vertex(b1, nb.z);
        vertex(a1, na.z);
    }
    return out;
}

void Overlays::drawLines(QOpenGLShaderProgram& program, const std::vector<OverlayLine>& lines,
                         const glm::mat4& viewProj) {
    if (lines.empty()) return;
    std::vector<float> data;
    data.reserve(lines.size() * 14);
    for (const OverlayLine& l : lines)
        if (l.width <= 1.0f)
            for (const glm::vec3& p : {l.a, l.b})
                data.insert(data.end(),
                            {p.x, p.y, p.z, l.color.x, l.color.y, l.color.z, l.color.w});
    // Wide ones as bands in the size of what is drawn to (the reduced target while the view
    // moves), in device coordinates.
    GLint view[4] = {0, 0, 0, 0};
    mGl->glGetIntegerv(GL_VIEWPORT, view);
    const std::vector<float> bands =
        screenBands(lines, viewProj, glm::vec2(float(view[2]), float(view[3])));
    if (!bands.empty()) drawOnTop(program, bands, glm::mat4(1.0f), int(bands.size() / 7));
    if (!data.empty()) drawOnTop(program, data, viewProj, 0);
}

void Overlays::drawOnTop(QOpenGLShaderProgram& program, const std::vector<float>& data,
                         const glm::mat4& viewProj, int triangleVertices) {
    // Handles and the band stay visible through the trees and the ground they stand in.
    mGl->glDisable(GL_DEPTH_TEST);
    mGl->glEnable(GL_BLEND);
    mGl->glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    program.bind();
    setUniform(program, "uViewProj", viewProj);
    setUniform(program, "uCenter", glm::vec3(0.0f));
    program.setUniformValue("uExtent", 1e30f); // no fading
    mGl->glBindVertexArray(mVao);
    mGl->glBindBuffer(GL_ARRAY_BUFFER, mVbo);
    mGl->glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(data.size() * sizeof(float)), data.data(),
                      GL_STREAM_DRAW);
    const auto vertices = GLsizei(data.size() / 7);
    if (triangleVertices > 0) mGl->glDrawArrays(GL_TRIANGLES, 0, triangleVertices);
    if (vertices > triangleVertices)
        mGl->glDrawArrays(GL_LINES, triangleVertices, vertices - triangleVertices);
    mGl->glBindBuffer(GL_ARRAY_BUFFER, 0);
    mGl->glDisable(GL_BLEND);
    mGl->glEnable(GL_DEPTH_TEST);
}

} // namespace sylva::ui
