#pragma once

#include <memory>

#include <QOpenGLFunctions_3_3_Core>
#include <QString>

class QOpenGLShaderProgram;

namespace sylva::ui {

/// The first pass of a viewport frame: clears colour and depth and fills the target with the
/// sky's vertical gradient (shaders/background.*: one triangle made from the vertex ids, no
/// depth written, so everything after draws over it).
class BackgroundPass {
public:
    /// Builds the shader; false (and \p error) when it does not compile.
    bool initialize(QOpenGLFunctions_3_3_Core* gl, QString& error);
    void release();
    /// Leaves the depth test off and depth writes off.
    void draw();

private:
    QOpenGLFunctions_3_3_Core* mGl = nullptr;
    std::unique_ptr<QOpenGLShaderProgram> mProgram;
    GLuint mEmptyVao = 0; ///< its triangle comes from the vertex ids
};

} // namespace sylva::ui
