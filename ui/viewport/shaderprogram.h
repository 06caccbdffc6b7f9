#pragma once

#include <memory>

#include <QByteArray>
#include <QString>
#include <qopengl.h>

#include <glm/glm.hpp>

class QOpenGLShaderProgram;
class QOpenGLFunctions_3_3_Core;

namespace sylva::ui {

/// The text of one of the viewport's GLSL files (ui/viewport/shaders/, compiled into sylva_ui
/// as the Qt resources :/sylva/shaders/<name>); empty when there is no such file.
QByteArray shaderSource(const QString& name);

/// \p source with each line `#include "name"` replaced by the resource shaderSource(name).
/// \p missing (when given) hears the first name that is no resource (its line is left out).
QByteArray expandIncludes(const QByteArray& source, QString* missing = nullptr);

/// A linked program of the shader files \p vertex and \p fragment (names in
/// ui/viewport/shaders/, their `#include "name"` lines expanded). \p defines (lines such as
/// "#define CUTOUT 1\n") go right after each shader's #version line. Null, with \p error set, when
/// a file or an included file is missing or GLSL does not compile or link. Needs a current
/// OpenGL context.
std::unique_ptr<QOpenGLShaderProgram> buildShaderProgram(const QString& vertex,
                                                         const QString& fragment, QString& error,
                                                         const QByteArray& defines = {});

void setUniform(QOpenGLShaderProgram& program, const char* name, const glm::vec3& v);
void setUniform(QOpenGLShaderProgram& program, const char* name, const glm::mat4& m);

/// Points the bound vertex array's attributes 0 (position) and 1 (colour) at the bound buffer's
/// interleaved 7 floats per vertex, as shaders/line.vert reads them.
void setLineVertexAttributes(QOpenGLFunctions_3_3_Core& gl);

/// A vertex array and its buffer of line vertices in that layout (the grid's, the overlays').
/// \p vao and \p vbo are made by createLineBuffers and deleted (and zeroed) by deleteBuffers.
void createLineBuffers(QOpenGLFunctions_3_3_Core& gl, GLuint& vao, GLuint& vbo);
void deleteBuffers(QOpenGLFunctions_3_3_Core& gl, GLuint& vao, GLuint& vbo);

} // namespace sylva::ui
