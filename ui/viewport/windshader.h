#pragma once

#include "engine/wind/windmodel.h"

class QOpenGLShaderProgram;

namespace sylva::ui {

/// The texture units the mesh shader's WIND variant (shaders/wind.glsl) reads a tree's sway
/// elements and the frame's rotations from (buffer textures).
inline constexpr int kWindElementsUnit = 2;
inline constexpr int kWindRotationsUnit = 3;

/// Sets wind.glsl's uniforms on the bound \p program: the two texture units above, \p base
/// (the tree's first rotation in the frame's rotation table) and the wind of \p frame. The one
/// place they are named, for the viewport and the test that holds the shader against the
/// engine's model.
void setWindUniforms(QOpenGLShaderProgram& program, const wind::WindFrame& frame, int base);

} // namespace sylva::ui
