#pragma once

#include <QOpenGLFunctions_3_3_Core>
#include <QSize>

namespace sylva::ui {

/// The framebuffer a software renderer draws a moving view into at a fraction of the
/// resolution (Viewport::motionScale()), scaled up into the window's framebuffer after.
class ReducedTarget {
public:
    /// Binds the target for a frame of \p full device pixels at \p scale (made or resized as
    /// needed) and sets the GL viewport to it. False, with \p defaultFbo bound again, when the
    /// driver refuses the framebuffer: then draw at full resolution.
    bool bind(QOpenGLFunctions_3_3_Core* gl, const QSize& full, float scale, GLuint defaultFbo);
    /// Scales the frame up into \p defaultFbo (\p full pixels), which stays bound.
    void blit(const QSize& full, GLuint defaultFbo);
    void release();

private:
    QOpenGLFunctions_3_3_Core* mGl = nullptr;
    GLuint mFbo = 0, mColor = 0, mDepth = 0;
    QSize mSize;
};

} // namespace sylva::ui
