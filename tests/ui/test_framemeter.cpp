// FrameMeter: frames measured on a shown viewport while the view orbits.
#include <QDir>
#include <QSignalSpy>
#include <QTest>

#include "engine/mesh/mesh.h"
#include "ui/generation/treegenerator.h"
#include "ui/viewport/framemeter.h"
#include "ui/viewport/viewport.h"

using namespace sylva;
using namespace sylva::ui;

class TestFrameMeter : public QObject {
    Q_OBJECT

private Q_SLOTS:
    void measuresFramesWhileOrbiting() {
        const GenerationResult tree =
            generateTree(QDir(QStringLiteral(SYLVA_TEST_DATA_DIR))
                             .filePath(QStringLiteral("lsystem/bush.lsys")));
        QVERIFY2(tree.ok(), qPrintable(tree.error));
        Viewport view;
        view.resize(320, 240);
        view.show();
        QVERIFY(QTest::qWaitForWindowExposed(&view));
        view.setMesh(tree.mesh, true);
        const glm::vec3 eye = view.camera().eye();

        FrameMeter meter(view);
        const FrameStats none = meter.measure(0);
        QCOMPARE(none.fps, 0.0);
        QCOMPARE(view.camera().eye(), eye); // no frame, no orbit

        // Each measured frame is a real one: the view swapped at least three frames (the meter's
        // 10 s guard would otherwise end each wait with nothing drawn).
        QSignalSpy swapped(&view, &Viewport::frameSwapped);
        const FrameStats stats = meter.measure(3);
        QVERIFY2(swapped.count() >= 3, qPrintable(QString::number(swapped.count())));
        QVERIFY(stats.msPerFrame > 0.0 && stats.msPerFrame < 10000.0);
        QVERIFY(stats.cpuMsPerFrame >= stats.guiCpuMsPerFrame * 0.99);
        QCOMPARE(stats.triangles, std::size_t(0)); // the shown result's: the caller's to fill
        QVERIFY(view.camera().eye() != eye);       // it orbited
    }
};

QTEST_MAIN(TestFrameMeter)
#include "test_framemeter.moc"
