// Textures as the views read them: the size from the file's header, a limit checked before
// anything is decoded, and large textures scaled down for the GPU.

#include <QImage>
#include <QTemporaryDir>
#include <QTest>

#include "ui/viewport/textureimage.h"

using namespace sylva::ui;

class TestTextureImage : public QObject {
    Q_OBJECT

private Q_SLOTS:
    void initTestCase() { QVERIFY(mDir.isValid()); }

    /// A small texture is read as it is, pixel for pixel.
    void smallTextureIsReadAsItIs() {
        QImage source(64, 32, QImage::Format_RGB32);
        for (int y = 0; y < 32; ++y)
            for (int x = 0; x < 64; ++x)
                source.setPixel(x, y, qRgb(x * 4, y * 8, 100));
        const QString path = mDir.filePath(QStringLiteral("small.png"));
        QVERIFY(source.save(path));
        const TextureImage read = readTextureImage(path, 4096);
        QVERIFY2(read.problem.isEmpty(), qPrintable(read.problem));
        QCOMPARE(read.image.size(), QSize(64, 32));
        QCOMPARE(read.image.pixel(63, 31), qRgb(252, 248, 100));
    }

    /// Wider than the largest side: scaled down, keeping its aspect (5000 × 100 → 1000 × 20).
    void largeTextureIsScaledToTheLargestSide() {
        QImage source(5000, 100, QImage::Format_RGB32);
        source.fill(qRgb(30, 140, 60));
        const QString path = mDir.filePath(QStringLiteral("wide.png"));
        QVERIFY(source.save(path));
        const TextureImage read = readTextureImage(path, 1000);
        QVERIFY2(read.problem.isEmpty(), qPrintable(read.problem));
        QCOMPARE(read.image.size(), QSize(1000, 20));
        QCOMPARE(read.image.pixel(500, 10), qRgb(30, 140, 60));
    }

    /// A header declaring 20000 × 20000 pixels (400 million, 1.6 GB decoded) in a file of a few
    /// bytes: refused from the header with the limit named, nothing decoded.
    void textureOverTheLimitIsRefusedFromItsHeader() {
        const QString path = mDir.filePath(QStringLiteral("huge.ppm"));
        QFile file(path);
        QVERIFY(file.open(QIODevice::WriteOnly));
        file.write("P6\n20000 20000\n255\n");
        file.write(QByteArray(30, '\x7f'));
        file.close();
        const TextureImage read = readTextureImage(path, 4096);
        QVERIFY(read.image.isNull());
        QVERIFY2(read.problem.contains(QStringLiteral("is 20000 × 20000 pixels, more than the "
                                                      "268,435,456 pixels (16384 × 16384) the "
                                                      "editor decodes; drawn without it")),
                 qPrintable(read.problem));
        QVERIFY(read.problem.contains(QStringLiteral("huge.ppm")));
    }

    /// A file that is no image, and one that is missing: the message names the file.
    void unreadableTextureIsReported() {
        const QString path = mDir.filePath(QStringLiteral("leaf.png"));
        QFile file(path);
        QVERIFY(file.open(QIODevice::WriteOnly));
        file.write("not a png at all");
        file.close();
        for (const QString& p : {path, mDir.filePath(QStringLiteral("missing.png"))}) {
            const TextureImage read = readTextureImage(p, 4096);
            QVERIFY(read.image.isNull());
            QVERIFY2(read.problem.startsWith(QStringLiteral("Texture ")) &&
                         read.problem.contains(QStringLiteral("cannot be read")),
                     qPrintable(read.problem));
        }
    }

private:
    QTemporaryDir mDir;
};

QTEST_GUILESS_MAIN(TestTextureImage)

#include "test_textureimage.moc"
