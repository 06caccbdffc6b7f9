#include "ui/viewport/shaderlist.h"

#include "ui/viewport/impostors.h"
#include "ui/viewport/meshpass.h"

namespace sylva::ui {

std::vector<ShaderProgramSource> viewportShaderPrograms() {
    std::vector<ShaderProgramSource> out;
    for (int v = 0; v < MeshPass::kVariants; ++v) {
        if (!MeshPass::isUsed(v)) continue;
        const QByteArray defines = MeshPass::defines(v);
        QString name = QStringLiteral("mesh");
        for (const QByteArray& line : defines.split('\n'))
            if (!line.isEmpty()) name += QLatin1Char(' ') + QString::fromLatin1(line.split(' ')[1]);
        out.push_back({name, QStringLiteral("mesh.vert"), QStringLiteral("mesh.frag"), defines});
    }
    out.push_back(
        {QStringLiteral("line"), QStringLiteral("line.vert"), QStringLiteral("line.frag"), {}});
    out.push_back({QStringLiteral("background"),
                   QStringLiteral("background.vert"),
                   QStringLiteral("background.frag"),
                   {}});
    out.push_back({QStringLiteral("impostor"),
                   QStringLiteral("impostor.vert"),
                   QStringLiteral("impostor.frag"),
                   {}});
    out.push_back({QStringLiteral("impostor FLAT"), QStringLiteral("impostor.vert"),
                   QStringLiteral("impostor.frag"), Impostors::kFlatDefines});
    out.push_back({QStringLiteral("impostor reference"),
                   QStringLiteral("impostorreference.vert"),
                   QStringLiteral("impostorreference.frag"),
                   {}});
    return out;
}

} // namespace sylva::ui
