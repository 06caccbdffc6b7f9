// SourceWatcher: which watched files changed on disk, one report per burst of writes, a file
// changed since it was read reported at once, a save by rename seen, nothing while disabled.
#include <QDateTime>
#include <QDir>
#include <QFile>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QTest>

#include "ui/document/sourcewatcher.h"

using namespace sylva::ui;

namespace {

void write(const QString& path, const QByteArray& text) {
    QFile f(path);
    QVERIFY(f.open(QIODevice::WriteOnly | QIODevice::Truncate));
    f.write(text);
}

// File systems keep coarse times on some machines: every write here gets a distinct time.
void touch(const QString& path, int secondsAhead) {
    QFile f(path);
    QVERIFY(f.open(QIODevice::ReadWrite));
    QVERIFY(f.setFileTime(QDateTime::currentDateTime().addSecs(secondsAhead),
                          QFileDevice::FileModificationTime));
}

QDateTime stampOf(const QString& path) {
    return QFileInfo(path).lastModified();
}

} // namespace

class TestSourceWatcher : public QObject {
    Q_OBJECT

private:
    QTemporaryDir mDir;
    QString file(const char* name) const { return mDir.filePath(QLatin1String(name)); }

private Q_SLOTS:
    void init() {
        write(file("species.json"), "{}");
        write(file("grammar.lsys"), "axiom: F");
        write(file("other.txt"), "not ours");
    }

    void listsEachFileOnce() {
        SourceWatcher watcher;
        watcher.watch({file("species.json"), file("grammar.lsys"), file("species.json"), {}}, {});
        QCOMPARE(watcher.files(), QStringList({file("species.json"), file("grammar.lsys")}));
    }

    void reportsTheChangedFilesOnceAfterABurst() {
        SourceWatcher watcher;
        watcher.watch({file("species.json"), file("grammar.lsys")},
                      {stampOf(file("species.json")), stampOf(file("grammar.lsys"))});
        QSignalSpy changed(&watcher, &SourceWatcher::changed);
        for (int i = 1; i <= 3; ++i) { // an editor's several writes of one save
            write(file("grammar.lsys"), "axiom: FF");
            touch(file("grammar.lsys"), 10 + i);
        }
        QTRY_COMPARE_WITH_TIMEOUT(changed.size(), 1, 5000);
        QCOMPARE(changed.front().front().toStringList(), QStringList{file("grammar.lsys")});
        QTest::qWait(600);
        QCOMPARE(changed.size(), 1); // seen: no second report of the same change
    }

    void ignoresOtherFilesInTheFolder() {
        SourceWatcher watcher;
        watcher.watch({file("species.json")}, {stampOf(file("species.json"))});
        QSignalSpy changed(&watcher, &SourceWatcher::changed);
        write(file("other.txt"), "still not ours");
        write(file("new.txt"), "a new file");
        QTest::qWait(800);
        QCOMPARE(changed.size(), 0);
    }

    void reportsAFileChangedSinceItWasRead() {
        SourceWatcher watcher;
        const QDateTime readAt = stampOf(file("species.json")).addSecs(-60);
        watcher.watch({file("species.json")}, {readAt});
        QSignalSpy changed(&watcher, &SourceWatcher::changed);
        QVERIFY(changed.wait(5000));
        QCOMPARE(changed.front().front().toStringList(), QStringList{file("species.json")});
    }

    void seesASaveByRename() {
        SourceWatcher watcher;
        watcher.watch({file("species.json")}, {stampOf(file("species.json"))});
        QSignalSpy changed(&watcher, &SourceWatcher::changed);
        write(file("species.json.tmp"), "{\"new\": 1}");
        touch(file("species.json.tmp"), 30);
        QVERIFY(QFile::remove(file("species.json")));
        QVERIFY(QFile::rename(file("species.json.tmp"), file("species.json")));
        QTRY_COMPARE_WITH_TIMEOUT(changed.size(), 1, 5000);
        // The new file is watched again: a later edit in place is seen too.
        touch(file("species.json"), 60);
        QTRY_COMPARE_WITH_TIMEOUT(changed.size(), 2, 5000);
    }

    void theProjectFileGoesLastWithItsOwnStamp() {
        const QDateTime opened = stampOf(file("species.json")).addSecs(-5);
        QStringList sources{file("grammar.lsys"), file("species.json"), file("other.txt")};
        QList<QDateTime> stamps = modificationTimes(sources);
        QCOMPARE(stamps.size(), 3);
        QCOMPARE(stamps[0], stampOf(file("grammar.lsys")));
        QCOMPARE(modificationTimes({file("missing")}), QList<QDateTime>{QDateTime()});
        listProjectFileLast(sources, stamps, file("species.json"), opened);
        QCOMPARE(sources,
                 QStringList({file("grammar.lsys"), file("other.txt"), file("species.json")}));
        QCOMPARE(stamps.back(), opened);
        QCOMPARE(stamps[1], stampOf(file("other.txt")));
        listProjectFileLast(sources, stamps, file("new.sylva"), opened); // not listed yet
        QCOMPARE(sources.size(), 4);
        QCOMPARE(sources.back(), file("new.sylva"));
    }

    void disabledItLooksAtNothing() {
        SourceWatcher watcher;
        watcher.setSettleMs(50);
        watcher.watch({file("species.json")}, {stampOf(file("species.json"))});
        watcher.setEnabled(false);
        QSignalSpy changed(&watcher, &SourceWatcher::changed);
        touch(file("species.json"), 90);
        QTest::qWait(500);
        QCOMPARE(changed.size(), 0);
        // Enabled again, the next touch reports what changed meanwhile.
        watcher.setEnabled(true);
        touch(file("species.json"), 120);
        QTRY_COMPARE_WITH_TIMEOUT(changed.size(), 1, 5000);
    }
};

QTEST_GUILESS_MAIN(TestSourceWatcher)
#include "test_sourcewatcher.moc"
