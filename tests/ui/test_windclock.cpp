// View ▸ Wind's clock (ui/viewport/windclock.h) on its own: frozen and resumed where it stood,
// frames asked for only while it runs, and a tree's frame its phase of the period later.

#include <QSignalSpy>
#include <QTest>

#include "ui/viewport/windclock.h"

using sylva::ui::WindClock;

class TestWindClock : public QObject {
    Q_OBJECT

private Q_SLOTS:
    void aFrozenClockStandsAndResumesFromThere() {
        WindClock clock;
        clock.setFixedTime(12.5);
        QCOMPARE(clock.time(), 12.5);
        QTest::qWait(30);
        QCOMPARE(clock.time(), 12.5);
        clock.setFixedTime(std::nullopt);
        const double resumed = clock.time();
        QVERIFY(resumed >= 12.5 && resumed < 12.5 + 5.0);
        QTest::qWait(30);
        QVERIFY(clock.time() > resumed);
    }

    void framesAreAskedForOnlyWhileItRuns() {
        WindClock clock;
        QSignalSpy due(&clock, &WindClock::frameDue);
        sylva::wind::WindSettings calm;
        calm.strength = 0.0f;
        clock.setSettings(calm);
        clock.setEnabled(true);
        QVERIFY(!clock.active()); // no wind blows
        QTest::qWait(80);
        QCOMPARE(due.count(), 0);
        sylva::wind::WindSettings breeze;
        breeze.strength = 1.0f;
        clock.setSettings(breeze);
        QVERIFY(clock.active());
        QTRY_VERIFY(due.count() >= 2);
        clock.setFixedTime(3.0); // frozen: the same frame, nothing to redraw
        QTest::qWait(40);
        const int frozen = int(due.count());
        QTest::qWait(80);
        QCOMPARE(int(due.count()), frozen);
        QVERIFY(clock.active()); // frozen trees still sway (at the frozen time)
        clock.setEnabled(false);
        QVERIFY(!clock.active());
    }

    void aTreesFrameIsItsPhaseOfThePeriodLater() {
        WindClock clock;
        sylva::wind::WindSettings w;
        w.strength = 1.2f;
        w.gustiness = 0.5f;
        w.period = 4.0f; // 2 s and 7 s are then at other places of the loop
        clock.setSettings(w);
        clock.setFixedTime(2.0);
        clock.startFrame();
        const sylva::wind::WindFrame half = clock.frameAt(0.5f);
        const sylva::wind::WindFrame expected =
            sylva::wind::windFrame(w, 2.0 + 0.5 * double(w.period));
        QCOMPARE(half.time, expected.time);
        // The frame's time is taken once: a later clock does not move this frame's trees.
        clock.setFixedTime(7.0);
        QCOMPARE(clock.frameAt(0.5f).time, expected.time);
        clock.startFrame();
        QVERIFY(clock.frameAt(0.5f).time != expected.time);
    }
};

QTEST_MAIN(TestWindClock)
#include "test_windclock.moc"
