#include "ui/viewport/windshader.h"

#include <QOpenGLShaderProgram>

namespace sylva::ui {

void setWindUniforms(QOpenGLShaderProgram& program, const wind::WindFrame& frame, int base) {
    program.setUniformValue("uWindElements", kWindElementsUnit);
    program.setUniformValue("uWindRotations", kWindRotationsUnit);
    program.setUniformValue("uWindBase", base);
    program.setUniformValue("uWindStrength", frame.strength);
    program.setUniformValue("uWindGustiness", frame.gustiness);
    program.setUniformValue("uWindTime", frame.time);
    program.setUniformValue("uWindOmega", frame.omega);
    program.setUniformValue("uWindBaseCycles", frame.baseCycles);
}

} // namespace sylva::ui
