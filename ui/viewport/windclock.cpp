#include "ui/viewport/windclock.h"

#include <QTimer>

namespace sylva::ui {

WindClock::WindClock(QObject* parent) : QObject(parent) {
    mTimer = new QTimer(this);
    // About 60 frames a second at most while the clock runs.
    mTimer->setInterval(16);
    connect(mTimer, &QTimer::timeout, this, &WindClock::frameDue);
    mClock.start();
}

void WindClock::setEnabled(bool on) {
    mOn = on;
    updateTimer();
}

void WindClock::setSettings(const wind::WindSettings& settings) {
    mSettings = settings;
    updateTimer();
}

void WindClock::setFixedTime(std::optional<double> seconds) {
    if (!seconds) {
        if (mFixed) {
            mClockStart = *mFixed;
            mClock.restart();
        }
        mFixed.reset();
    } else {
        mFixed = *seconds;
    }
    updateTimer();
}

double WindClock::time() const {
    return mFixed ? *mFixed : mClockStart + double(mClock.nsecsElapsed()) * 1e-9;
}

wind::WindFrame WindClock::frameAt(float phase) const {
    return wind::windFrame(mSettings, mFrameTime + double(phase) * double(mSettings.period));
}

void WindClock::updateTimer() {
    const bool run = mOn && !mFixed && mSettings.strength > 0.0f;
    if (run && !mTimer->isActive())
        mTimer->start();
    else if (!run)
        mTimer->stop();
}

} // namespace sylva::ui
