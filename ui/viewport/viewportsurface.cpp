#include "ui/viewport/viewportsurface.h"

#include <algorithm>
#include <cmath>

#include <QApplication>
#include <QOffscreenSurface>
#include <QOpenGLContext>
#include <QOpenGLFunctions>
#include <QSettings>
#include <QVBoxLayout>
#include <QWidget>

namespace sylva::ui {

void ViewportSurface::installDefaultSurfaceFormat() {
    QSurfaceFormat format = QSurfaceFormat::defaultFormat();
    format.setRenderableType(QSurfaceFormat::OpenGL);
    format.setVersion(3, 3);
    format.setProfile(QSurfaceFormat::CoreProfile);
    format.setDepthBufferSize(24);
    // SYLVA_MSAA=0 turns multisampling off: a software renderer (Mesa llvmpipe) draws a
    // frame about twice as fast without it (docs/perf/editor.md).
    format.setSamples(qEnvironmentVariableIsSet("SYLVA_MSAA")
                          ? std::max(0, qEnvironmentVariableIntValue("SYLVA_MSAA"))
                          : 4);
    QSurfaceFormat::setDefaultFormat(format);
    // Without a window manager that paces frames (_NET_WM_FRAME_DRAWN), Qt waits 5 ms after
    // each QWindow::requestUpdate() before it paints: at 30 fps that is a sixth of a frame.
    // The view draws as soon as the event loop is idle instead (updates asked for meanwhile
    // still make one frame). Set QT_QPA_UPDATE_IDLE_TIME to choose otherwise.
    if (!qEnvironmentVariableIsSet("QT_QPA_UPDATE_IDLE_TIME"))
        qputenv("QT_QPA_UPDATE_IDLE_TIME", "0");
}

int ViewportSurface::samplesPreference() {
    const int samples = QSettings().value(QStringLiteral("viewport/samples"), kAutoSamples).toInt();
    return samples == 0 || samples == 2 || samples == 4 || samples == 8 ? samples : kAutoSamples;
}

void ViewportSurface::setSamplesPreference(int samples) {
    QSettings().setValue(QStringLiteral("viewport/samples"), samples);
}

bool ViewportSurface::isSoftwareRenderer(const QString& renderer) {
    const QString name = renderer.toLower();
    for (const char* software : {"llvmpipe", "softpipe", "swrast", "swiftshader"})
        if (name.contains(QLatin1String(software))) return true;
    return false;
}

int ViewportSurface::applySamplesPreference() {
    int samples = samplesPreference();
    if (qEnvironmentVariableIsSet("SYLVA_MSAA"))
        samples = std::max(0, qEnvironmentVariableIntValue("SYLVA_MSAA"));
    if (samples == kAutoSamples) {
        samples = 4;
        QOpenGLContext probe;
        QOffscreenSurface surface;
        surface.create();
        if (probe.create() && probe.makeCurrent(&surface)) {
            const auto* renderer =
                reinterpret_cast<const char*>(probe.functions()->glGetString(GL_RENDERER));
            if (isSoftwareRenderer(QString::fromLatin1(renderer ? renderer : ""))) samples = 0;
            probe.doneCurrent();
        }
    }
    QSurfaceFormat format = QSurfaceFormat::defaultFormat();
    format.setSamples(samples);
    QSurfaceFormat::setDefaultFormat(format);
    return samples;
}

ViewportSurface::ViewportSurface(QWidget& view, Painter painter)
    : QOpenGLWindow(NoPartialUpdate), mView(view), mPainter(std::move(painter)) {}

ViewportSurface* ViewportSurface::embed(QWidget& view, const QSurfaceFormat& format,
                                        Painter painter) {
    auto* surface = new ViewportSurface(view, std::move(painter));
    surface->setFormat(format);
    QWidget* container = QWidget::createWindowContainer(surface, &view);
    container->setFocusPolicy(Qt::NoFocus);
    // Keyboard focus stays with the widget: shortcuts and the widget's key handling work as
    // for any widget, and a click does not take focus from the main window. Set once
    // embedded: the container sets the window's flags.
    surface->setFlag(Qt::WindowDoesNotAcceptFocus);
    auto* layout = new QVBoxLayout(&view);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->addWidget(container);
    return surface;
}

QImage ViewportSurface::grabFrame() {
    // A window's back buffer holds nothing defined after a swap: draw a frame into it and
    // read it back without swapping (what is on screen is left as it is).
    if (!mView.isVisible() || !isExposed()) return {};
    makeCurrent();
    if (!context()) return {};
    mPainter.paint();
    const int w = int(std::lround(mView.width() * mView.devicePixelRatioF()));
    const int h = int(std::lround(mView.height() * mView.devicePixelRatioF()));
    QImage image(w, h, QImage::Format_RGBA8888);
    QOpenGLFunctions* f = context()->functions();
    f->glBindFramebuffer(GL_FRAMEBUFFER, defaultFramebufferObject());
    f->glPixelStorei(GL_PACK_ALIGNMENT, 4);
    f->glReadPixels(0, 0, w, h, GL_RGBA, GL_UNSIGNED_BYTE, image.bits());
    doneCurrent();
    image = image.mirrored().convertToFormat(QImage::Format_RGB32);
    image.setDevicePixelRatio(mView.devicePixelRatioF());
    return image;
}

bool ViewportSurface::event(QEvent* event) {
    switch (event->type()) {
    case QEvent::MouseMove: // QApplication drops hover moves the widget does not track,
                            // after starting its tooltip's timer
    case QEvent::MouseButtonPress:
    case QEvent::MouseButtonRelease:
    case QEvent::MouseButtonDblClick:
    case QEvent::Wheel:
    case QEvent::KeyPress:
    case QEvent::KeyRelease:
    case QEvent::Enter:
    case QEvent::Leave:
        // The window fills the widget from its top left corner: the positions hold.
        if (event->type() == QEvent::MouseButtonPress || event->type() == QEvent::KeyPress)
            activateMainWindow();
        QCoreApplication::sendEvent(&mView, event);
        return true;
    case QEvent::FocusIn:
        // Should the window get the keyboard anyway, give it back to the main window and
        // the view's widget: with a window that is not a widget's as the focus window,
        // Qt matches no widget's shortcut (Delete, Ctrl+Z did nothing).
        activateMainWindow();
        mView.setFocus(Qt::MouseFocusReason);
        return true;
    default:
        return QOpenGLWindow::event(event);
    }
}

void ViewportSurface::activateMainWindow() {
    QWidget* top = mView.window();
    if (top && QApplication::activeWindow() != top) top->activateWindow();
}

} // namespace sylva::ui
