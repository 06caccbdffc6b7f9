#pragma once

#include <cstddef>
#include <vector>

namespace sylva::ui {

class Viewport;

/// What FrameMeter::measure() saw: frames per second, wall and CPU milliseconds per frame (the
/// whole process, which includes a software renderer's threads, and the GUI thread alone), and
/// what the viewport drew.
struct FrameStats {
    double fps = 0, msPerFrame = 0, cpuMsPerFrame = 0, guiCpuMsPerFrame = 0;
    std::size_t treesDrawn = 0, triangles = 0;  ///< triangles: the shown result's (the caller's)
    std::size_t trianglesDrawn = 0;             ///< in the last frame, at its LOD
    std::vector<std::size_t> treesPerLevel;     ///< in the last frame, level 0 = full
    std::vector<std::size_t> trianglesPerLevel; ///< the triangles those trees drew
    std::size_t motionTrees = 0;                ///< in the last frame, drawn at their motion level
};

/// The frame benchmark of a viewport (`win.measure_frames` in Python, the performance notes):
/// it orbits the view by a small step per frame and waits for each frame on screen.
class FrameMeter {
public:
    explicit FrameMeter(Viewport& viewport) : mViewport(viewport) {}

    /// Orbits the view by \p orbitDegrees per frame for \p frames frames (running the event
    /// loop; a frame not shown within 10 s ends its wait) and measures them. Zeros for
    /// \p frames <= 0. 0 degrees: a still camera, each frame drawn again (what View ▸ Wind
    /// asks for while the view rests).
    FrameStats measure(int frames, float orbitDegrees = 4.0f);

private:
    Viewport& mViewport;
};

} // namespace sylva::ui
