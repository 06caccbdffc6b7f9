// Every GLSL program the viewport builds (ui/viewport/shaderlist.h: the mesh shader's used
// variants, lines, background, the impostor cards marched and FLAT) and the reference impostor
// sampler docs/lods.md points to, compiled and linked with a real OpenGL 3.3 core context
// (Mesa llvmpipe under xvfb-run): a shader that does not compile, an `#include` of a file that
// is not there, or a program that does not link fails here rather than in the editor's
// viewport, which would only show its error text. Every file in ui/viewport/shaders/ must be
// part of a program, so that a new one cannot stay uncompiled.

#include <QDir>
#include <QOffscreenSurface>
#include <QOpenGLContext>
#include <QOpenGLFunctions_3_3_Core>
#include <QOpenGLShaderProgram>
#include <QOpenGLVersionFunctionsFactory>
#include <QSet>
#include <QTest>

#include "ui/viewport/shaderlist.h"
#include "ui/viewport/shaderprogram.h"

using namespace sylva::ui;

class TestViewportShaders : public QObject {
    Q_OBJECT

private Q_SLOTS:
    void everyProgramCompilesAndLinks() {
        QOffscreenSurface surface;
        surface.setFormat(QSurfaceFormat::defaultFormat());
        surface.create();
        QOpenGLContext context;
        QSurfaceFormat format;
        format.setVersion(3, 3);
        format.setProfile(QSurfaceFormat::CoreProfile);
        context.setFormat(format);
        QVERIFY(context.create());
        QVERIFY(context.makeCurrent(&surface));
        auto* gl = QOpenGLVersionFunctionsFactory::get<QOpenGLFunctions_3_3_Core>(&context);
        QVERIFY2(gl && gl->initializeOpenGLFunctions(), "no OpenGL 3.3 core context");

        const std::vector<ShaderProgramSource> programs = viewportShaderPrograms();
        // 12 mesh variants (16 less the 4 with both WIND and INSTANCED), lines, background,
        // two impostor programs, the reference sampler.
        QCOMPARE(programs.size(), std::size_t(17));
        QStringList failed;
        for (const ShaderProgramSource& p : programs) {
            QString error;
            const std::unique_ptr<QOpenGLShaderProgram> program =
                buildShaderProgram(p.vertex, p.fragment, error, p.defines);
            if (!program) failed << p.name + QStringLiteral(": ") + error;
        }
        QVERIFY2(failed.isEmpty(), qPrintable(failed.join(QLatin1Char('\n'))));
        context.doneCurrent();
    }

    void everyShaderFileIsInAProgram() {
        QSet<QString> used;
        for (const ShaderProgramSource& p : viewportShaderPrograms()) {
            for (const QString& file : {p.vertex, p.fragment}) {
                used.insert(file);
                // The files it includes (one level, as expandIncludes() expands them).
                for (const QByteArray& line : shaderSource(file).split('\n')) {
                    const QByteArray t = line.trimmed();
                    if (t.startsWith("#include \"") && t.endsWith('"'))
                        used.insert(QString::fromLatin1(t.mid(10, t.size() - 11)));
                }
            }
        }
        (void)shaderSource(QStringLiteral("mesh.vert")); // registers the resources
        const QStringList files = QDir(QStringLiteral(":/sylva/shaders")).entryList(QDir::Files);
        QVERIFY(files.size() >= 10);
        for (const QString& file : files)
            QVERIFY2(used.contains(file), qPrintable(file + QStringLiteral(" is in no program")));
    }

    void aMissingIncludeIsReported() {
        // buildShaderProgram() refuses a program whose #include names no resource (its error
        // names the file) rather than compiling the shader without it.
        QString missing;
        const QByteArray source = "#version 330 core\n#include \"nothing.glsl\"\nvoid main() {}";
        QVERIFY(!expandIncludes(source, &missing).contains("#include"));
        QCOMPARE(missing, QStringLiteral("nothing.glsl"));
        missing.clear();
        QVERIFY(expandIncludes("#include \"impostoratlas.glsl\"", &missing)
                    .contains("vec3 decodeDir("));
        QVERIFY(missing.isEmpty());
    }
};

QTEST_MAIN(TestViewportShaders)
#include "test_viewportshaders.moc"
