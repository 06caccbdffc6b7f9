#pragma once

#include <optional>

#include <QElapsedTimer>
#include <QObject>

#include "engine/wind/windmodel.h"

class QTimer;

namespace sylva::ui {

/// View ▸ Wind's clock: the wind the trees sway in, whether it is on, and the time the frames
/// are drawn at. While it runs (on, not frozen, a wind blowing) it asks for about 60 frames a
/// second (frameDue()); a slower renderer draws as fast as it can (updates coalesce). A frame
/// takes the clock's time once when it starts (startFrame()), and every tree's wind frame
/// follows from it and the tree's place in the loop (frameAt()).
class WindClock : public QObject {
    Q_OBJECT

public:
    explicit WindClock(QObject* parent = nullptr);

    void setEnabled(bool on);
    bool enabled() const { return mOn; }
    /// The wind (the project's; the engine's default until set). Keeps the clock where it is:
    /// the trees go on from their pose into the new wind.
    void setSettings(const wind::WindSettings& settings);
    const wind::WindSettings& settings() const { return mSettings; }
    /// Freezes the clock at \p seconds (scripts, tests and pictures: the same time gives the
    /// same frame), or lets it run with the wall clock again from there (nullopt).
    void setFixedTime(std::optional<double> seconds);
    /// The clock now, in seconds.
    double time() const;
    /// Whether trees sway: on, and a wind that blows.
    bool active() const { return mOn && mSettings.strength > 0.0f; }

    /// Takes the clock's time for the frame being drawn.
    void startFrame() { mFrameTime = time(); }
    /// The wind's frame for a tree \p phase of the period into the loop, at the frame's time.
    wind::WindFrame frameAt(float phase) const;

Q_SIGNALS:
    /// The next frame is due while the clock runs.
    void frameDue();

private:
    void updateTimer();

    bool mOn = false;
    wind::WindSettings mSettings;
    std::optional<double> mFixed; ///< the frozen clock
    QElapsedTimer mClock;
    double mClockStart = 0.0; ///< the clock's seconds when it was (re)started
    QTimer* mTimer = nullptr;
    double mFrameTime = 0.0; ///< the clock at the frame's start
};

} // namespace sylva::ui
