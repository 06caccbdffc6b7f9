#include "ui/viewport/shaderprogram.h"

#include <QFile>
#include <QMatrix4x4>
#include <QOpenGLFunctions_3_3_Core>
#include <QOpenGLShaderProgram>

#include <glm/gtc/type_ptr.hpp>

// The resources of a static library are registered by the objects Qt's CMake links into every
// executable; initialising them by name as well costs nothing and keeps the shaders found
// should a program link sylva_ui some other way. Outside any namespace, as Q_INIT_RESOURCE
// requires.
static void initShaderResources() {
    Q_INIT_RESOURCE(sylva_viewport_shaders);
}

namespace sylva::ui {

QByteArray shaderSource(const QString& name) {
    static const bool initialised = [] {
        initShaderResources();
        return true;
    }();
    (void)initialised;
    QFile file(QStringLiteral(":/sylva/shaders/") + name);
    if (!file.open(QIODevice::ReadOnly)) return {};
    return file.readAll();
}

QByteArray expandIncludes(const QByteArray& source, QString* missing) {
    // GLSL has no #include: a line `#include "name"` becomes that resource's text (one level,
    // which is all the shaders use).
    if (!source.contains("#include")) return source;
    QByteArray out;
    for (const QByteArray& line : source.split('\n')) {
        const QByteArray t = line.trimmed();
        if (t.startsWith("#include \"") && t.endsWith('"')) {
            const QString name = QString::fromLatin1(t.mid(10, t.size() - 11));
            const QByteArray text = shaderSource(name);
            if (text.isEmpty() && missing && missing->isEmpty()) *missing = name;
            out += text;
            out += '\n';
        } else {
            out += line;
            out += '\n';
        }
    }
    out.chop(1);
    return out;
}

std::unique_ptr<QOpenGLShaderProgram> buildShaderProgram(const QString& vertex,
                                                         const QString& fragment, QString& error,
                                                         const QByteArray& defines) {
    QString missing;
    QByteArray vertexSource = expandIncludes(shaderSource(vertex), &missing);
    QByteArray fragmentSource = expandIncludes(shaderSource(fragment), &missing);
    if (vertexSource.isEmpty() || fragmentSource.isEmpty()) {
        error =
            QStringLiteral("shader error: missing shader resource %1 or %2").arg(vertex, fragment);
        return nullptr;
    }
    if (!missing.isEmpty()) {
        error = QStringLiteral("shader error: %1 or %2 includes %3, which is no shader resource")
                    .arg(vertex, fragment, missing);
        return nullptr;
    }
    if (!defines.isEmpty()) {
        for (QByteArray* source : {&vertexSource, &fragmentSource}) {
            const qsizetype afterVersion = source->indexOf('\n') + 1;
            source->insert(afterVersion, defines);
        }
    }
    auto program = std::make_unique<QOpenGLShaderProgram>();
    if (!program->addShaderFromSourceCode(QOpenGLShader::Vertex, vertexSource) ||
        !program->addShaderFromSourceCode(QOpenGLShader::Fragment, fragmentSource) ||
        !program->link()) {
        error = QStringLiteral("shader error: ") + program->log();
        return nullptr;
    }
    return program;
}

void setUniform(QOpenGLShaderProgram& program, const char* name, const glm::vec3& v) {
    program.setUniformValue(name, v.x, v.y, v.z);
}

void setUniform(QOpenGLShaderProgram& program, const char* name, const glm::mat4& m) {
    // glm is column-major like OpenGL, so the raw array goes through unchanged.
    program.setUniformValue(program.uniformLocation(name),
                            QMatrix4x4(glm::value_ptr(m)).transposed());
}

void setLineVertexAttributes(QOpenGLFunctions_3_3_Core& gl) {
    gl.glEnableVertexAttribArray(0);
    gl.glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, 7 * sizeof(float), nullptr);
    gl.glEnableVertexAttribArray(1);
    gl.glVertexAttribPointer(1, 4, GL_FLOAT, GL_FALSE, 7 * sizeof(float),
                             reinterpret_cast<void*>(3 * sizeof(float)));
}

void createLineBuffers(QOpenGLFunctions_3_3_Core& gl, GLuint& vao, GLuint& vbo) {
    gl.glGenVertexArrays(1, &vao);
    gl.glGenBuffers(1, &vbo);
    gl.glBindVertexArray(vao);
    gl.glBindBuffer(GL_ARRAY_BUFFER, vbo);
    setLineVertexAttributes(gl);
    gl.glBindVertexArray(0);
}

void deleteBuffers(QOpenGLFunctions_3_3_Core& gl, GLuint& vao, GLuint& vbo) {
    gl.glDeleteVertexArrays(1, &vao);
    gl.glDeleteBuffers(1, &vbo);
    vao = vbo = 0;
}

} // namespace sylva::ui
