#pragma once

#include <vector>

#include <QOpenGLFunctions_3_3_Core>
#include <QRect>
#include <QSize>

#include <glm/glm.hpp>

class QOpenGLShaderProgram;

namespace sylva::ui {

/// A line a tool draws over the scene (its handles), world space, not hidden by the scene.
struct OverlayLine {
    glm::vec3 a{0.0f}, b{0.0f};
    glm::vec4 color{1.0f};
};

/// What the viewport draws over the scene, blended and without the depth test so that it stays
/// visible through the trees and the ground they stand in: a tool's handles and the rubber band.
class Overlays {
public:
    void initialize(QOpenGLFunctions_3_3_Core* gl);
    void release();

    /// \p lines in world space, with the line program \p program (shaders/line.*).
    void drawLines(QOpenGLShaderProgram& program, const std::vector<OverlayLine>& lines,
                   const glm::mat4& viewProj);
    /// The rubber band \p band (widget pixels, y down, in a widget of \p widget logical pixels):
    /// a translucent fill inside a sharp outline; nothing when it is empty.
    void drawBand(QOpenGLShaderProgram& program, const QRect& band, const QSize& widget);

private:
    /// Draws position + colour vertices (7 floats each): the first \p triangleVertices as
    /// triangles, the rest as lines.
    void drawOnTop(QOpenGLShaderProgram& program, const std::vector<float>& data,
                   const glm::mat4& viewProj, int triangleVertices);

    QOpenGLFunctions_3_3_Core* mGl = nullptr;
    GLuint mVao = 0, mVbo = 0;
};

} // namespace sylva::ui
