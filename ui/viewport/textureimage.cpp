#include "ui/viewport/textureimage.h"

#include <QCoreApplication>
#include <QDir>
#include <QImageReader>
#include <QLocale>
#include <QSize>

#include <algorithm>

namespace sylva::ui {

TextureImage readTextureImage(const QString& path, int maxSide) {
    const QString shown = QDir::toNativeSeparators(path);
    QImageReader reader(path);
    const QSize size = reader.size(); // the header only
    if (!size.isValid() || size.isEmpty())
        return {{},
                QCoreApplication::translate("TextureImage",
                                            "Texture %1 cannot be read (%2); drawn without it")
                    .arg(shown, reader.errorString())};
    const long long pixels = static_cast<long long>(size.width()) * size.height();
    if (pixels > kMaxTexturePixels)
        return {
            {},
            QCoreApplication::translate(
                "TextureImage", "Texture %1 is %2 × %3 pixels, more than the %4 pixels (16384 × "
                                "16384) the editor decodes; drawn without it (exports copy it "
                                "unchanged). Use a smaller texture.")
                .arg(shown)
                .arg(size.width())
                .arg(size.height())
                .arg(QLocale(QLocale::English, QLocale::UnitedStates).toString(kMaxTexturePixels))};
    // Qt refuses images over 256 MB by default; up to the limit above (1 GiB as RGBA) is read.
    reader.setAllocationLimit(static_cast<int>(kMaxTexturePixels * 4 / (1024 * 1024)));
    const int side = std::max(1, maxSide);
    if (size.width() > side || size.height() > side) {
        QSize scaled = size.scaled(side, side, Qt::KeepAspectRatio);
        scaled = scaled.expandedTo(QSize(1, 1));
        reader.setScaledSize(scaled);
    }
    QImage image = reader.read();
    if (image.isNull())
        return {{},
                QCoreApplication::translate("TextureImage",
                                            "Texture %1 cannot be read (%2); drawn without it")
                    .arg(shown, reader.errorString())};
    return {std::move(image), {}};
}

} // namespace sylva::ui
