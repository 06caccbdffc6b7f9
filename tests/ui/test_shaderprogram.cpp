// The viewport's GLSL files are found as resources of the static sylva_ui library from a test
// binary, each a GLSL 3.30 core shader. Compiling them needs a GL context: ui_smoke and
// ui_species draw with them.

#include <QTest>

#include "ui/viewport/shaderprogram.h"

class TestShaderProgram : public QObject {
    Q_OBJECT

private Q_SLOTS:
    void everyShaderIsAResource() {
        for (const char* name :
             {"mesh.vert", "mesh.frag", "line.vert", "line.frag", "background.vert",
              "background.frag", "impostor.vert", "impostor.frag"}) {
            const QByteArray source = sylva::ui::shaderSource(QString::fromLatin1(name));
            QVERIFY2(source.startsWith("#version 330 core\n"), name);
            QVERIFY2(source.contains("void main()"), name);
        }
    }

    void aMissingShaderIsEmpty() {
        QVERIFY(sylva::ui::shaderSource(QStringLiteral("nothing.frag")).isEmpty());
    }
};

QTEST_APPLESS_MAIN(TestShaderProgram)
#include "test_shaderprogram.moc"
