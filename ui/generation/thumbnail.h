#pragma once

#include <QImage>
#include <QString>

namespace sylva::mesh {
struct Mesh;
}

namespace sylva::ui {

/// A mesh drawn into a square image without OpenGL (so any thread can make one): an orthographic
/// three-quarter view fitted to the image, triangles flat-shaded by a fixed light and painted
/// back to front, bark brown and leaves green (by submesh material), on a transparent
/// background. For preset thumbnails, not for judging detail.
QImage renderThumbnail(const mesh::Mesh& mesh, int size);

/// The thumbnail of a species file grown with seed 1, cached as a PNG in \p cacheDir under a
/// hash of the file's bytes and of the grammar files it names (a changed preset is drawn again).
/// A null image when the species cannot be grown (the error is in \p error).
QImage speciesThumbnail(const QString& speciesFile, int size, const QString& cacheDir,
                        QString* error = nullptr);

} // namespace sylva::ui
