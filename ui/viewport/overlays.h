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
    /// Pixels across: a line wider than 1 is drawn as a band facing the screen (square ends,
    /// so that a polyline has no gaps at its joints); core OpenGL draws no line wider than 1.
    float width = 1.0f;
};

/// The bands of the \p lines wider than a pixel as triangles in normalised device coordinates
/// (7 floats a vertex: x, y, z, colour; six vertices a line), for a view of \p pixels (width,
/// height): each band is width pixels across on screen whatever its distance. A line is cut
/// where it crosses the near plane; one wholly behind it gives nothing. Pure, for tests.
std::vector<float> screenBands(const std::vector<OverlayLine>& lines, const glm::mat4& viewProj,
                               const glm::vec2& pixels);

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
