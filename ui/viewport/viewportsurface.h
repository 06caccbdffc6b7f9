#pragma once

#include <functional>

#include <QImage>
#include <QOpenGLWindow>
#include <QSurfaceFormat>

class QWidget;

namespace sylva::ui {

/// The native OpenGL window a Viewport draws into (a QOpenGLWindow in a window container that
/// fills the viewport widget): paints with the viewport's GL code and hands its input to the
/// widget, which the rest of the editor talks to. Also the surface format every view asks for
/// and the multisampling preference.
///
/// A native window rather than a QOpenGLWidget: a QOpenGLWidget makes Qt compose the whole
/// main window with OpenGL on every repaint of any widget in it, which under a software
/// renderer costs more than drawing an empty view (docs/perf/editor.md).
class ViewportSurface : public QOpenGLWindow {
public:
    /// The viewport's GL code, called with the context current.
    struct Painter {
        std::function<void()> initialize;
        std::function<void(int width, int height)> resize;
        std::function<void()> paint;
    };

    /// Makes the surface with \p format and embeds it in \p view (a container filling it, no
    /// margins); \p view receives the window's input events.
    static ViewportSurface* embed(QWidget& view, const QSurfaceFormat& format, Painter painter);

    /// Draws a frame into the back buffer and reads it back without swapping (what is on screen
    /// is left as it is), at the view's size in device pixels; null when the view is hidden or
    /// has no context.
    QImage grabFrame();

    /// See Viewport::installDefaultSurfaceFormat() and the samples preference beside it.
    static void installDefaultSurfaceFormat();
    static constexpr int kAutoSamples = -1;
    static int samplesPreference();
    static void setSamplesPreference(int samples);
    static int applySamplesPreference();
    /// Whether \p renderer (GL_RENDERER) names a software rasteriser (Mesa llvmpipe …).
    static bool isSoftwareRenderer(const QString& renderer);

protected:
    ViewportSurface(QWidget& view, Painter painter);
    void initializeGL() override { mPainter.initialize(); }
    void resizeGL(int w, int h) override { mPainter.resize(w, h); }
    void paintGL() override { mPainter.paint(); }
    bool event(QEvent* event) override;

private:
    /// A click in the view makes its main window the active one (the one keys go to), as a
    /// click in a widget does: without that, an X server without a window manager (Xvfb)
    /// sends keys to the window under the pointer, this one, and Qt matches no shortcut.
    void activateMainWindow();

    QWidget& mView;
    Painter mPainter;
};

} // namespace sylva::ui
