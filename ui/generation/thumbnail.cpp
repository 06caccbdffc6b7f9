#include "ui/generation/thumbnail.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <vector>

#include <QCryptographicHash>
#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QPainter>
#include <QPolygonF>

#include <glm/gtc/matrix_transform.hpp>

#include "document/errormessage.h"
#include "document/filerefs.h"
#include "document/speciesfile.h"
#include "engine/graph/graph.h"
#include "engine/mesh/mesh.h"
#include "engine/util/error.h"

namespace sylva::ui {

QImage renderThumbnail(const mesh::Mesh& mesh, int size) {
    QImage image(size, size, QImage::Format_ARGB32_Premultiplied);
    image.fill(Qt::transparent);
    if (mesh.empty() || mesh.indices.empty()) return image;
    // Three-quarter view: turned 30° about +Y and seen 12° from above.
    glm::mat4 view = glm::rotate(glm::mat4(1.0f), glm::radians(12.0f), glm::vec3(1, 0, 0));
    view = glm::rotate(view, glm::radians(30.0f), glm::vec3(0, 1, 0));
    std::vector<glm::vec3> p(mesh.positions.size());
    glm::vec3 lo(1e30f), hi(-1e30f);
    for (std::size_t i = 0; i < p.size(); ++i) {
        p[i] = glm::vec3(view * glm::vec4(mesh.positions[i], 1.0f));
        lo = glm::min(lo, p[i]);
        hi = glm::max(hi, p[i]);
    }
    const float extent = std::max({hi.x - lo.x, hi.y - lo.y, 1e-6f});
    const float scale = 0.92f * float(size) / extent;
    const glm::vec2 centre((lo.x + hi.x) * 0.5f, (lo.y + hi.y) * 0.5f);
    auto screen = [&](const glm::vec3& v) {
        return QPointF(size * 0.5 + (v.x - centre.x) * scale,
                       size * 0.5 - (v.y - centre.y) * scale);
    };
    // Material per triangle from the submeshes (none: all bark).
    const std::size_t triangles = mesh.triangleCount();
    std::vector<std::uint8_t> leaf(triangles, 0);
    for (const mesh::Submesh& s : mesh.submeshes)
        if (s.material.find("leaf") != std::string::npos)
            for (std::uint32_t t = s.firstIndex / 3; t < (s.firstIndex + s.indexCount) / 3; ++t)
                leaf[t] = 1;
    // Painter's algorithm: far triangles first (the camera looks down -Z in view space).
    std::vector<std::uint32_t> order(triangles);
    std::iota(order.begin(), order.end(), 0u);
    std::vector<float> depth(triangles);
    for (std::size_t t = 0; t < triangles; ++t)
        depth[t] =
            p[mesh.indices[3 * t]].z + p[mesh.indices[3 * t + 1]].z + p[mesh.indices[3 * t + 2]].z;
    std::sort(order.begin(), order.end(),
              [&](std::uint32_t a, std::uint32_t b) { return depth[a] < depth[b]; });
    const glm::vec3 light = glm::normalize(glm::vec3(-0.4f, 0.8f, 0.45f));
    QPainter painter(&image);
    painter.setRenderHint(QPainter::Antialiasing, size <= 256);
    for (std::uint32_t t : order) {
        const glm::vec3& a = p[mesh.indices[3 * t]];
        const glm::vec3& b = p[mesh.indices[3 * t + 1]];
        const glm::vec3& c = p[mesh.indices[3 * t + 2]];
        glm::vec3 n = glm::cross(b - a, c - a);
        const float len = glm::length(n);
        if (len < 1e-12f) continue;
        n /= len;
        float lambert = glm::dot(n, light);
        if (leaf[t]) lambert = std::abs(lambert); // two-sided cards
        const float shade = 0.35f + 0.65f * std::max(lambert, 0.0f);
        const QColor base = leaf[t] ? QColor(78, 140, 52) : QColor(112, 84, 60);
        const QColor colour =
            QColor::fromRgbF(base.redF() * shade, base.greenF() * shade, base.blueF() * shade);
        const QPointF poly[3] = {screen(a), screen(b), screen(c)};
        painter.setPen(QPen(colour, 0.6));
        painter.setBrush(colour);
        painter.drawPolygon(poly, 3);
    }
    return image;
}

QImage speciesThumbnail(const QString& speciesFile, int size, const QString& cacheDir,
                        QString* error) {
    try {
        graph::registerBuiltinNodeTypes();
        graph::SpeciesGraph species = doc::loadSpecies(speciesFile);
        QCryptographicHash hash(QCryptographicHash::Sha1);
        hash.addData(QByteArrayLiteral("sylva-thumbnail-1/") + QByteArray::number(size));
        QStringList files{QFileInfo(speciesFile).absoluteFilePath()};
        doc::addSpeciesSourceFiles(species, files);
        for (const QString& f : files) {
            QFile in(f);
            if (in.open(QIODevice::ReadOnly)) hash.addData(in.readAll());
        }
        const QString cached =
            QDir(cacheDir).filePath(QString::fromLatin1(hash.result().toHex()) + ".png");
        if (QImage image(cached); !image.isNull()) return image;
        graph::Evaluator evaluator(std::move(species));
        const graph::NodeOutput& out = evaluator.evaluate(1);
        if (!out.mesh) throw InvalidInput("the species' output node produced no mesh");
        const QImage image = renderThumbnail(*out.mesh, size);
        QDir().mkpath(cacheDir);
        image.save(cached);
        return image;
    } catch (...) {
        if (error)
            *error = QString::fromStdString(
                doc::describeError(std::current_exception(),
                                   QFileInfo(speciesFile).fileName().toStdString())
                    .message);
        return {};
    }
}

} // namespace sylva::ui
