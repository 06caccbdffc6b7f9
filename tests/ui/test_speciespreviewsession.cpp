// SpeciesPreviewSession: a species file generated on a worker, the mode it puts the window in,
// the newest run winning, a failed run keeping the last good tree, cancelling.
#include <QDir>
#include <QSignalSpy>
#include <QTest>

#include "engine/mesh/mesh.h"
#include "ui/generation/speciespreviewsession.h"

using namespace sylva::ui;

namespace {
QString dataFile(const char* name) {
    return QDir(QStringLiteral(SYLVA_TEST_DATA_DIR)).filePath(QLatin1String(name));
}
} // namespace

class TestSpeciesPreviewSession : public QObject {
    Q_OBJECT

private Q_SLOTS:
    void generatesTheFileOnAWorker() {
        SpeciesPreviewSession session;
        QVERIFY(!session.isActive());
        QSignalSpy generated(&session, &SpeciesPreviewSession::generated);
        session.start(dataFile("lsystem/bush.lsys"));
        QVERIFY(session.isActive());
        QVERIFY(session.isRunning());
        QCOMPARE(session.path(), dataFile("lsystem/bush.lsys"));
        QVERIFY(generated.wait(60000));
        QVERIFY(!session.isRunning());
        QVERIFY2(session.result().ok(), qPrintable(session.result().error));
        QVERIFY(session.result().mesh->triangleCount() > 0);
        // The sources the window watches: the grammar itself.
        QVERIFY(session.result().sources.contains(
            QFileInfo(dataFile("lsystem/bush.lsys")).absoluteFilePath()));
        session.leave();
        QVERIFY(!session.isActive());
        QVERIFY(session.result().ok()); // the last tree stays for the next preview
    }

    void aFailedRunKeepsTheLastGoodTree() {
        SpeciesPreviewSession session;
        QSignalSpy generated(&session, &SpeciesPreviewSession::generated);
        QString lastError;
        connect(&session, &SpeciesPreviewSession::generated, this,
                [&lastError](const GenerationResult& run) { lastError = run.error; });
        session.start(dataFile("lsystem/bush.lsys"));
        QVERIFY(generated.wait(60000));
        QVERIFY(lastError.isEmpty());
        const auto good = session.result().mesh;
        session.start(dataFile("lsystem/bad-syntax.lsys"));
        QVERIFY(generated.wait(60000));
        QVERIFY(!lastError.isEmpty());
        QCOMPARE(session.result().mesh, good);
        QCOMPARE(session.path(), dataFile("lsystem/bad-syntax.lsys"));
    }

    void theNewestRunWins() {
        SpeciesPreviewSession session;
        QSignalSpy generated(&session, &SpeciesPreviewSession::generated);
        session.start(dataFile("lsystem/slow.lsys"));
        session.start(dataFile("lsystem/bush.lsys")); // supersedes the first
        QTRY_VERIFY_WITH_TIMEOUT(!session.isRunning(), 60000);
        QCOMPARE(generated.size(), 1);
        QCOMPARE(session.path(), dataFile("lsystem/bush.lsys"));
        QVERIFY(session.result().ok());
        QVERIFY(session.result().sources.contains(
            QFileInfo(dataFile("lsystem/bush.lsys")).absoluteFilePath()));
    }

    void cancelDropsTheRun() {
        SpeciesPreviewSession session;
        QSignalSpy generated(&session, &SpeciesPreviewSession::generated);
        QSignalSpy dropped(&session, &SpeciesPreviewSession::dropped);
        session.start(dataFile("lsystem/slow.lsys"));
        session.cancel();
        QTRY_VERIFY_WITH_TIMEOUT(!session.isRunning(), 60000);
        QCOMPARE(dropped.size() + generated.size(), 1);
        QVERIFY(!session.result().ok()); // nothing good was made yet
    }
};

QTEST_GUILESS_MAIN(TestSpeciesPreviewSession)
#include "test_speciespreviewsession.moc"
