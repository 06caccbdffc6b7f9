#include "ui/viewport/framemeter.h"

#include <ctime>

#include <QElapsedTimer>
#include <QEventLoop>
#include <QTimer>

#include "ui/viewport/viewport.h"

namespace sylva::ui {

namespace {
double cpuMs(clockid_t clock) {
    timespec ts{};
    clock_gettime(clock, &ts);
    return double(ts.tv_sec) * 1e3 + double(ts.tv_nsec) * 1e-6;
}
} // namespace

FrameStats FrameMeter::measure(int frames, float orbitDegrees) {
    FrameStats stats;
    if (frames <= 0) return stats;
    QElapsedTimer wall;
    const double process0 = cpuMs(CLOCK_PROCESS_CPUTIME_ID);
    const double gui0 = cpuMs(CLOCK_THREAD_CPUTIME_ID);
    wall.start();
    for (int i = 0; i < frames; ++i) {
        QEventLoop loop;
        QTimer guard;
        guard.setSingleShot(true);
        QObject::connect(&guard, &QTimer::timeout, &loop, &QEventLoop::quit);
        QObject::connect(&mViewport, &Viewport::frameSwapped, &loop, &QEventLoop::quit);
        if (orbitDegrees != 0.0f) mViewport.camera().orbit(orbitDegrees, 0.0f);
        mViewport.update();
        guard.start(10000);
        loop.exec();
    }
    const double ms = double(wall.nsecsElapsed()) * 1e-6;
    stats.msPerFrame = ms / frames;
    stats.fps = 1000.0 / stats.msPerFrame;
    stats.cpuMsPerFrame = (cpuMs(CLOCK_PROCESS_CPUTIME_ID) - process0) / frames;
    stats.guiCpuMsPerFrame = (cpuMs(CLOCK_THREAD_CPUTIME_ID) - gui0) / frames;
    stats.treesDrawn = mViewport.drawnTrees();
    stats.trianglesDrawn = mViewport.drawnTriangles();
    const auto& levels = mViewport.drawnPerLevel();
    stats.treesPerLevel.assign(levels.begin(), levels.end());
    const auto& triangles = mViewport.drawnTrianglesPerLevel();
    stats.trianglesPerLevel.assign(triangles.begin(), triangles.end());
    stats.motionTrees = mViewport.drawnMotion();
    return stats;
}

} // namespace sylva::ui
