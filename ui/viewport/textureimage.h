#pragma once

#include <QImage>
#include <QString>

namespace sylva::ui {

/// The most pixels of a texture the editor decodes for its views: 2^28 (16384 × 16384, 1 GiB
/// as 8-bit RGBA). A larger one is drawn without its texture, with a message; exports copy
/// texture files byte for byte and never decode them.
inline constexpr long long kMaxTexturePixels = 1LL << 28;
/// The largest side of a texture in the views: a larger texture is scaled down, keeping its
/// aspect, to this or the GPU's GL_MAX_TEXTURE_SIZE, whichever is smaller (a preview needs no
/// more; an 8K leaf texture would take 256 MB of graphics memory before its mipmaps).
inline constexpr int kMaxViewTextureSide = 4096;

/// What the views make of a texture file.
struct TextureImage {
    QImage image;    ///< null when the file is not drawn
    QString problem; ///< why it is not drawn, for the status bar; empty when it is
};

/// Reads the image file \p path for the views: its size from the file's header first, refused
/// when it holds more than kMaxTexturePixels (nothing is decoded), scaled down to at most
/// \p maxSide pixels a side. Any thread may call it.
TextureImage readTextureImage(const QString& path, int maxSide);

} // namespace sylva::ui
