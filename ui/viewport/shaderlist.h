#pragma once

#include <vector>

#include <QByteArray>
#include <QString>

namespace sylva::ui {

/// One GLSL program built from ui/viewport/shaders/: its two files and the defines it is built
/// with (buildShaderProgram()).
struct ShaderProgramSource {
    QString name; ///< for messages: "mesh TEXTURED CUTOUT", "impostor FLAT" …
    QString vertex;
    QString fragment;
    QByteArray defines;
};

/// Every program the viewport builds (each used variant of the mesh shader as MeshPass makes
/// them, the lines, the background, the impostor cards marched and FLAT), and the reference
/// impostor sampler docs/lods.md points to. ui_viewportshaders compiles and links each with a
/// real OpenGL 3.3 core context, and checks that every file in shaders/ is part of one.
std::vector<ShaderProgramSource> viewportShaderPrograms();

} // namespace sylva::ui
