#pragma once

#include <QOpenGLFunctions_3_3_Core>

#include <glm/glm.hpp>

class QOpenGLShaderProgram;

namespace sylva::ui {

/// The viewport's ground grid: lines a power of ten apart, a few dozen across the framed scene,
/// every tenth darker, the x and z axes coloured, fading out towards the rim.
class Grid {
public:
    void initialize(QOpenGLFunctions_3_3_Core* gl);
    void release();

    /// Built again at the next paint (the framed scene changed).
    void invalidate() { mExtent = 0.0f; }
    bool isBuilt() const { return mExtent > 0.0f; }
    /// Lays the grid out for a scene of \p sceneRadius whose bounds are \p lo .. \p hi: centred
    /// under them, at y = 0 or below the lowest point.
    void build(float sceneRadius, const glm::vec3& lo, const glm::vec3& hi);
    /// Draws it blended with the line program \p lines (shaders/line.*).
    void draw(QOpenGLShaderProgram& lines, const glm::mat4& viewProj);

private:
    QOpenGLFunctions_3_3_Core* mGl = nullptr;
    GLuint mVao = 0, mVbo = 0;
    GLsizei mVertexCount = 0;
    float mExtent = 0.0f;
    glm::vec3 mCenter{0.0f};
};

} // namespace sylva::ui
