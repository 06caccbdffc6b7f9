#include "ui/viewport/viewport.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <set>

#include <QElapsedTimer>
#include <QKeyEvent>
#include <QMouseEvent>
#include <QOpenGLContext>
#include <QOpenGLFunctions>
#include <QOpenGLShaderProgram>
#include <QTimer>
#include <QWheelEvent>

#include <glm/gtc/matrix_transform.hpp>

#include "engine/mesh/mesh.h"
#include "ui/viewport/impostorlighting.h"
#include "ui/viewport/shaderprogram.h"
#include "ui/viewport/viewportsurface.h"

namespace sylva::ui {

void Viewport::installDefaultSurfaceFormat() {
    ViewportSurface::installDefaultSurfaceFormat();
}

int Viewport::samplesPreference() {
    return ViewportSurface::samplesPreference();
}

void Viewport::setSamplesPreference(int samples) {
    ViewportSurface::setSamplesPreference(samples);
}

int Viewport::applySamplesPreference() {
    return ViewportSurface::applySamplesPreference();
}

Viewport::Viewport(QWidget* parent) : QWidget(parent) {
    QSurfaceFormat format = QSurfaceFormat::defaultFormat();
    format.setVersion(3, 3);
    format.setProfile(QSurfaceFormat::CoreProfile);
    format.setDepthBufferSize(24);
    if (format.samples() < 0) format.setSamples(QSurfaceFormat::defaultFormat().samples());
    // format() reports the context's format once it exists, whose samples are not the FBO's.
    mSamples = format.samples();
    mSurface =
        ViewportSurface::embed(*this, format,
                               {[this] { initializeGL(); },
                                [this](int w, int h) { resizeGL(w, h); }, [this] { paintGL(); }});
    // The present: from the end of paintGL to the swap done (recorded before frameSwapped is
    // passed on, so that a slot on it reads this frame's).
    connect(mSurface, &QOpenGLWindow::frameSwapped, this,
            [this] { mLastPresentMs = double(mPaintStart.nsecsElapsed()) * 1e-6 - mLastPaintMs; });
    connect(mSurface, &QOpenGLWindow::frameSwapped, this, &Viewport::frameSwapped);
    setFocusPolicy(Qt::StrongFocus);
    setMouseTracking(false);
    setMinimumSize(160, 120);
    // The eye stays above the ground plane the grid draws (y = 0); the main window adds the
    // terrain and obstacles under the eye.
    mCamera.setGround([](float, float) { return 0.0f; });
    mSharpTimer = new QTimer(this);
    mSharpTimer->setSingleShot(true);
    mSharpTimer->setInterval(kSharpAfterMs);
    connect(mSharpTimer, &QTimer::timeout, this, [this] {
        mSharpNext = true;
        update();
    });
    // While atlases bake on the worker, a frame now and then uploads the finished ones.
    mImpostors.setWake([this] { update(); });
    mWind = new WindClock(this);
    connect(mWind, &WindClock::frameDue, this, [this] { update(); });
    mLod = new ViewLod(this);
    connect(mLod, &ViewLod::levelsReady, this, [this] {
        // The new levels' buffers go up with the next frame; a frame now only where they change
        // what the view shows (a tree seen near draws its full mesh either way: repainting it
        // doubled the work of every edit and drag under a software renderer).
        mTreesDirty = true;
        if (levelsChangeView()) update();
    });
}

Viewport::~Viewport() {
    if (mGlReady && context()) {
        makeCurrent();
        releaseGl();
        doneCurrent();
    }
}

void Viewport::update() {
    mSurface->update();
}

void Viewport::makeCurrent() {
    mSurface->makeCurrent();
}

void Viewport::doneCurrent() {
    mSurface->doneCurrent();
}

QOpenGLContext* Viewport::context() const {
    return mSurface->context();
}

GLuint Viewport::defaultFramebufferObject() const {
    return mSurface->defaultFramebufferObject();
}

QSurfaceFormat Viewport::format() const {
    return mSurface->format();
}

void Viewport::setFormat(const QSurfaceFormat& format) {
    mSurface->setFormat(format);
    mSamples = format.samples();
}

QWindow* Viewport::surface() const {
    return mSurface;
}

QImage Viewport::grabFramebuffer() {
    return mSurface->grabFrame();
}

bool Viewport::event(QEvent* event) {
    // The cursor a tool sets on the widget is the window's too.
    if (event->type() == QEvent::CursorChange) mSurface->setCursor(cursor());
    return QWidget::event(event);
}

void Viewport::setMesh(std::shared_ptr<const mesh::Mesh> mesh, bool frame,
                       std::shared_ptr<const std::vector<ViewVertex>> vertices,
                       std::shared_ptr<const skel::Skeleton> skeleton) {
    mMesh = std::move(mesh);
    mMeshVertices = std::move(vertices);
    mMeshSkeleton = std::move(skeleton);
    mVertexColors.clear();
    mMeshDirty = true;
    updateBounds();
    if (frame) {
        applyFrame();
        Q_EMIT cameraChanged();
    }
    update();
}

std::size_t Viewport::vertexCount() const {
    return mMesh ? mMesh->positions.size() : 0;
}

void Viewport::setVertexColors(std::vector<glm::vec3> colors) {
    mVertexColors = std::move(colors);
    mMeshDirty = true;
    update();
}

void Viewport::frameScene() {
    mViewFrom = false;
    applyFrame();
    update();
    Q_EMIT cameraChanged();
}

void Viewport::applyFrame() {
    if (mMesh && !mMesh->empty() && mTrees.empty())
        mCamera.framePoints(mMesh->positions, aspect());
    else
        mCamera.frame(mBoundsLo, mBoundsHi, aspect());
    if (mViewFrom) mCamera.lookFrom(mViewEye, mViewTarget);
    mAutoFramed = true;
    mGrid.invalidate(); // rebuilt for the new scene size at the next paint
}

void Viewport::setViewFrom(const glm::vec3& eye, const glm::vec3& target) {
    mViewFrom = true;
    mViewEye = eye;
    mViewTarget = target;
}

void Viewport::setGridVisible(bool visible) {
    mGridVisible = visible;
    update();
}

void Viewport::setWindEnabled(bool on) {
    if (on == mWind->enabled()) return;
    mWind->setEnabled(on);
    if (on && mMeshSkeleton) mMeshDirty = true; // its wind data, left out while off
    update();
}

void Viewport::setWind(const wind::WindSettings& settings) {
    mWind->setSettings(settings);
    update();
}

void Viewport::setWindTime(std::optional<double> seconds) {
    mWind->setFixedTime(seconds);
    update();
}

float Viewport::aspect() const {
    return height() > 0 ? float(width()) / float(height()) : 1.0f;
}

void Viewport::initializeGL() {
    if (!initializeOpenGLFunctions()) {
        mGlError = tr("OpenGL 3.3 core profile is not available (got %1.%2).")
                       .arg(context()->format().majorVersion())
                       .arg(context()->format().minorVersion());
        return;
    }
    mGlInfo = QStringLiteral("%1, OpenGL %2")
                  .arg(reinterpret_cast<const char*>(glGetString(GL_RENDERER)),
                       reinterpret_cast<const char*>(glGetString(GL_VERSION)));
    // A software rasteriser's frame time grows with the pixels drawn; a GPU's hardly does.
    mSoftware = ViewportSurface::isSoftwareRenderer(
        QString::fromLatin1(reinterpret_cast<const char*>(glGetString(GL_RENDERER))));
    mMotionScale = mSoftware && mSamples <= 1 ? kSoftwareMotionScale : 1.0f;
    if (qEnvironmentVariableIsSet("SYLVA_MOTION_SCALE"))
        mMotionScale =
            std::clamp(qEnvironmentVariable("SYLVA_MOTION_SCALE").toFloat(), 0.25f, 1.0f);
    if (mSamples > 1) mMotionScale = 1.0f; // no blit into a multisampled framebuffer

    // The passes' shaders, in the order of the error reported when one fails.
    if (!mTreePass.initialize(this, &mBuffers, mLod, &mImpostors, mWind, mSoftware, mGlError))
        return;
    mLineProgram =
        buildShaderProgram(QStringLiteral("line.vert"), QStringLiteral("line.frag"), mGlError);
    if (!mLineProgram || !mBackground.initialize(this, mGlError)) return;
    if (!mImpostors.initialize(this, mGlError)) return;

    mBuffers.initialize(this, [this](const QString& problem) {
        // Not from inside a frame: the status bar repaints.
        QMetaObject::invokeMethod(
            this, [this, problem] { Q_EMIT warning(problem); }, Qt::QueuedConnection);
    });
    mGrid.initialize(this);
    mOverlays.initialize(this);
    mGlReady = true;
    mMeshDirty = true;
    mTreesDirty = true;
}

void Viewport::releaseGl() {
    mBuffers.release();
    mReduced.release();
    mOverlays.release();
    mImpostors.release();
    mGrid.release();
    mTreePass.release();
    mBackground.release();
    mLineProgram.reset();
    mGlReady = false;
}

void Viewport::uploadMesh() {
    QElapsedTimer timer;
    timer.start();
    mMeshDirty = false;
    const std::vector<ViewVertex>* prepared = mMeshVertices ? mMeshVertices.get() : nullptr;
    // The mesh's wind data (sway elements, per-vertex channels) only while View ▸ Wind is on:
    // a species preview that does not sway needs the one mesh (setWindEnabled() uploads again).
    const std::shared_ptr<const skel::Skeleton> windSkeleton =
        mWind->enabled() ? mMeshSkeleton : std::shared_ptr<const skel::Skeleton>();
    // A bad index would make the driver read out of bounds; refuse the mesh instead.
    if (!mBuffers.uploadScene(mMesh.get(), mVertexColors, prepared, windSkeleton))
        mGlError = tr("The mesh has an index out of range; it is not drawn.");
    mLastUploadMs = double(timer.nsecsElapsed()) * 1e-6;
}

void Viewport::setTrees(std::vector<ViewTree> trees, bool frame) {
    mTrees = std::move(trees);
    mTreesDirty = true;
    std::vector<std::pair<std::shared_ptr<const mesh::Mesh>, TreeLodSource>> sources;
    sources.reserve(mTrees.size());
    for (const ViewTree& t : mTrees)
        sources.emplace_back(t.mesh, t.lod);
    mLod->setTrees(sources);
    updateBounds();
    if (frame) {
        applyFrame();
        Q_EMIT cameraChanged();
    }
    update();
}

void Viewport::setPreviewTrees(std::vector<ViewTree> trees) {
    mPreview = std::move(trees);
    mTreesDirty = true;
    update();
}

void Viewport::setTreeTransform(std::size_t index, const glm::mat4& transform) {
    if (index >= mTrees.size()) return;
    mTrees[index].transform = transform;
    mTransformsMoved = true;
    if (index < mTreeBounds.size() && mTrees[index].mesh)
        mTreeBounds[index] = worldBounds(*mTrees[index].mesh, transform);
    update();
}

Ray Viewport::rayAt(const QPointF& pos) const {
    const float w = float(std::max(width(), 1)), h = float(std::max(height(), 1));
    const glm::vec2 ndc(2.0f * float(pos.x()) / w - 1.0f, 1.0f - 2.0f * float(pos.y()) / h);
    const glm::mat4 inverse =
        glm::inverse(mCamera.projectionMatrix(aspect()) * mCamera.viewMatrix());
    glm::vec4 nearPoint = inverse * glm::vec4(ndc, -1.0f, 1.0f);
    glm::vec4 farPoint = inverse * glm::vec4(ndc, 1.0f, 1.0f);
    nearPoint /= nearPoint.w;
    farPoint /= farPoint.w;
    const glm::vec3 origin = mCamera.eye();
    return {origin, glm::normalize(glm::vec3(farPoint) - glm::vec3(nearPoint))};
}

std::optional<QPointF> Viewport::project(const glm::vec3& world) const {
    const glm::vec4 clip =
        mCamera.projectionMatrix(aspect()) * mCamera.viewMatrix() * glm::vec4(world, 1.0f);
    if (clip.w <= 1e-6f) return std::nullopt;
    const glm::vec3 ndc = glm::vec3(clip) / clip.w;
    if (std::abs(ndc.x) > 1.0f || std::abs(ndc.y) > 1.0f || ndc.z < -1.0f || ndc.z > 1.0f)
        return std::nullopt;
    return QPointF((ndc.x + 1.0f) * 0.5f * float(width()), (1.0f - ndc.y) * 0.5f * float(height()));
}

bool Viewport::levelsChangeView() const {
    // After a frame drawn while the view moved, the sharp frame its timer asks for draws the
    // new levels: no frame of its own.
    if (mLastReduced) return false;
    for (const TreeDraw& d : mLastDrawList) {
        if (d.level <= 0 || d.index >= mTrees.size()) continue;
        const ViewTree& t = mTrees[d.index];
        // An impostor is baked from the levels; an instance draws its variant's levels.
        if (d.level >= ViewLod::kImpostorLevel) return true;
        if (t.lod.instance && t.lod.variant) continue;
        if (mLod->meshFor(t.mesh.get(), d.level) != t.mesh.get()) return true;
    }
    return false;
}

TreeHit Viewport::pickAt(const QPointF& pos) const {
    std::vector<bool> hidden(mTrees.size(), false);
    for (std::size_t i = 0; i < mTrees.size(); ++i)
        hidden[i] = isHidden(i);
    // What the last frame drew: a tree at a coarse level or as an impostor is picked by its
    // box, not by the full mesh's triangles it no longer shows.
    std::vector<bool> coarse(mTrees.size(), false);
    for (const TreeDraw& d : mLastDrawList)
        if (d.index < coarse.size()) coarse[d.index] = d.level > 0 || d.variantLevel > 0;
    return pickTree(rayAt(pos), mTrees, mTreeBounds, hidden, coarse);
}

void Viewport::frameBox(const glm::vec3& lo, const glm::vec3& hi) {
    mViewFrom = false;
    mCamera.frame(lo, hi, aspect());
    mAutoFramed = false;
    mGrid.invalidate();
    update();
    Q_EMIT cameraChanged();
}

void Viewport::setHighlightedTrees(const QSet<std::uint32_t>& ids) {
    mHighlighted = ids;
    update();
}

void Viewport::setHiddenTrees(const QSet<std::uint32_t>& ids) {
    mHidden = ids;
    update();
}

void Viewport::updateBounds() {
    glm::vec3 lo(std::numeric_limits<float>::max());
    glm::vec3 hi(std::numeric_limits<float>::lowest());
    auto add = [&](const glm::vec3& p) {
        lo = glm::min(lo, p);
        hi = glm::max(hi, p);
    };
    if (mMesh)
        for (const glm::vec3& p : mMesh->positions)
            add(p);
    mTreeBounds.clear();
    for (const ViewTree& t : mTrees) {
        mTreeBounds.push_back(t.mesh ? worldBounds(*t.mesh, t.transform) : Bounds{});
        if (!mTreeBounds.back().empty()) {
            add(mTreeBounds.back().lo);
            add(mTreeBounds.back().hi);
        }
    }
    if (lo.x > hi.x) {
        mBoundsLo = {-0.5f, 0.0f, -0.5f};
        mBoundsHi = {0.5f, 1.0f, 0.5f};
    } else {
        mBoundsLo = lo;
        mBoundsHi = hi;
    }
}

void Viewport::syncTreeBuffers() {
    mTreesDirty = false;
    // Each mesh with the skeleton it was made from (its wind data); a tree's levels share it.
    std::vector<TreeBuffers::Source> all;
    for (const ViewTree& t : mTrees)
        all.push_back({t.mesh, t.lod.skeleton});
    for (const ViewTree& t : mPreview)
        all.push_back({t.mesh, t.lod.skeleton});
    const std::size_t treeMeshes = all.size();
    for (const ViewTree& t : mTrees)
        for (std::shared_ptr<const mesh::Mesh>& level : mLod->levelMeshesOf(t.mesh.get()))
            all.push_back({std::move(level), t.lod.skeleton});
    for (std::shared_ptr<const mesh::Mesh>& level : mLod->allLevelMeshes())
        all.push_back({std::move(level), nullptr}); // listed above unless its tree is gone
    // Every level of every variant drawn: one buffer set each, whatever its instances.
    std::set<const ViewVariant*> variants;
    for (const ViewTree& t : mTrees)
        if (t.lod.instance && t.lod.variant && variants.insert(t.lod.variant.get()).second)
            for (const mesh::DistanceLevel& level : t.lod.variant->levels)
                all.push_back({level.mesh, t.lod.skeleton});
    mBuffers.sync(all, treeMeshes, mUploads, mLevelUploads);
    std::set<Impostors::Key> keys;
    for (const ViewTree& t : mTrees)
        keys.insert(Impostors::keyOf(t));
    mImpostors.retain([&keys](Impostors::Key k) { return keys.count(k) > 0; });
}

void Viewport::resizeGL(int width, int height) {
    (void)width;
    (void)height;
    // Until the user moves the camera, keep the scene framed for the new aspect ratio.
    if (mAutoFramed) applyFrame();
}

void Viewport::paintGL() {
    mPaintStart.start();
    struct FrameTime { // the frame's time, however paintGL returns
        QElapsedTimer& timer;
        double& ms;
        ~FrameTime() { ms = double(timer.nsecsElapsed()) * 1e-6; }
    } frameTime{mPaintStart, mLastPaintMs};
    ++mFramesPainted;
    if (!mGlReady) {
        // Without our functions, fall back to the context's basic ones to show a neutral grey.
        QOpenGLFunctions* f = context()->functions();
        f->glClearColor(0.25f, 0.25f, 0.25f, 1.0f);
        f->glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
        return;
    }
    if (mMeshDirty) uploadMesh();
    if (mTreesDirty) syncTreeBuffers();
    if (!mGrid.isBuilt()) mGrid.build(mCamera.sceneRadius(), mBoundsLo, mBoundsHi);

    const glm::mat4 viewProj = mCamera.projectionMatrix(aspect()) * mCamera.viewMatrix();
    // A key light that follows the camera keeps the tree readable from every side (the
    // impostors' atlases have it baked in: ui/viewport/impostorlighting.h).
    const glm::vec3 light = cameraKeyLight(mCamera.forward(), mCamera.up(), mCamera.right());
    // While the view moves, a software renderer draws fewer pixels (motionScale()); the sharp
    // frame follows when it rests.
    const bool moving = viewProj != mLastViewProj || mTransformsMoved;
    mLastViewProj = viewProj;
    mTransformsMoved = false;
    const QSize full(int(std::lround(width() * devicePixelRatioF())),
                     int(std::lround(height() * devicePixelRatioF())));
    glBindFramebuffer(GL_FRAMEBUFFER, defaultFramebufferObject());
    glViewport(0, 0, full.width(), full.height());
    mLastReduced = false;
    if (mMotionScale < 1.0f && moving && !mSharpNext) {
        mLastReduced = mReduced.bind(this, full, mMotionScale, defaultFramebufferObject());
        if (!mLastReduced) mMotionScale = 1.0f; // the driver refused it: not again
        mSharpTimer->start();
    }
    mSharpNext = false;
    mLastDrawList = treesToDraw(viewProj);
    if (mImpostors.schedule(mLastDrawList, mTrees, *mLod)) mTreesDirty = true;

    mBackground.draw();
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LEQUAL);
    if (mGridVisible) mGrid.draw(*mLineProgram, viewProj);
    glDepthMask(GL_TRUE);

    mWind->startFrame();
    TreeFrame frame;
    frame.viewProj = viewProj;
    frame.eye = mCamera.eye();
    frame.light = light;
    // The target's height: the reduced one while the view moves.
    const float targetHeight = float(full.height()) * (mLastReduced ? mMotionScale : 1.0f);
    frame.pixelsPerUnit = targetHeight / (2.0f * std::tan(0.5f * mCamera.fovY()));
    frame.reduced = mLastReduced;
    mStats = mTreePass.draw(frame, mTrees, mPreview, mLastDrawList, mHighlighted);

    if (mOverlay) mOverlays.drawLines(*mLineProgram, mOverlay(), viewProj);
    mOverlays.drawBand(*mLineProgram, mBand, size());
    glBindVertexArray(0);
    if (mLastReduced) mReduced.blit(full, defaultFramebufferObject());
}

QImage Viewport::grabSharp() {
    mSharpNext = true;
    return grabFramebuffer();
}

void Viewport::setBand(const QRect& band) {
    if (band == mBand) return;
    mBand = band;
    update();
}

std::vector<TreeDraw> Viewport::treesToDraw(const glm::mat4& viewProj) const {
    std::vector<bool> drawn(mTrees.size());
    for (std::size_t i = 0; i < mTrees.size(); ++i)
        drawn[i] = mTrees[i].mesh && !isHidden(i);
    DrawListView view;
    view.viewProj = viewProj;
    view.eye = mCamera.eye();
    view.fovY = mCamera.fovY();
    // A frame drawn at reduced resolution while the view moves (a software renderer): each
    // tree's level, and where the impostor takes over, follow the pixels it spans on the
    // target drawn into, as at rest on the window: a tree half as many pixels high there is
    // drawn as if twice as far (an impostor then spans no more target pixels than at rest),
    // and kMotionLodBias times farther still.
    const double target = mLastReduced ? double(mMotionScale) : 1.0;
    view.viewportHeightPx = double(height()) * devicePixelRatioF() * target;
    view.motionBias = mLastReduced ? kMotionLodBias : 1.0;
    view.maxImpostorPx = mLastReduced ? kMaxMovingImpostorPx : 0.0;
    // Impostors do not sway: with View ▸ Wind on, a moving frame draws no tree as one that the
    // sharp frame draws as a swaying mesh (the levels below still follow motionBias).
    if (mLastReduced && mWind->active())
        view.maxImpostorPx = std::min(kMaxMovingImpostorPx, ViewLod::impostorHeightPx() * target);
    view.levels = mLod->isEnabled();
    // Variant levels while the view moves: ViewLod::kMotionFactor times as far as at rest on
    // the window (the target's scale above is part of it, not on top), and motionBias more.
    static const double bias = qEnvironmentVariableIsSet("SYLVA_LOD_BIAS")
                                   ? qEnvironmentVariable("SYLVA_LOD_BIAS").toDouble()
                                   : 1.0;
    view.variantFactor = (mLastReduced ? ViewLod::kMotionFactor * target : 1.0) * bias;
    std::vector<InstanceOf> instances(mTrees.size());
    for (std::size_t i = 0; i < mTrees.size(); ++i)
        if (mTrees[i].lod.instance && mTrees[i].lod.variant)
            instances[i] = {mTrees[i].lod.variant.get(),
                            glm::length(glm::vec3(mTrees[i].transform[0]))};
    // Where each baked impostor matches its tree (Impostors::switchHeightPx()).
    std::vector<double> impostorPx(mTrees.size(), -1.0);
    for (std::size_t i = 0; i < mTrees.size(); ++i)
        impostorPx[i] = mImpostors.switchHeightPx(Impostors::keyOf(mTrees[i]));
    // Picking keeps the full mesh; only drawing follows the level of detail.
    if (!mWind->active()) return buildDrawList(view, drawn, mTreeBounds, instances, impostorPx);
    // Swaying trees reach beyond their rest boxes: widened across by half their height (the
    // model bends a trunk at most 0.3 rad and its limbs 0.6 rad more) so that a tree at the
    // view's edge is not culled while its crown sways into view. Heights stay as they are, and
    // with them the level each tree is drawn at.
    std::vector<Bounds> swaying = mTreeBounds;
    for (Bounds& b : swaying) {
        if (b.empty()) continue;
        const float reach = 0.5f * (b.hi.y - b.lo.y);
        b.lo -= glm::vec3(reach, 0.0f, reach);
        b.hi += glm::vec3(reach, 0.0f, reach);
    }
    return buildDrawList(view, drawn, swaying, instances, impostorPx);
}

void Viewport::mousePressEvent(QMouseEvent* event) {
    mLastMouse = event->position().toPoint();
    mPressPos = mLastMouse;
    mMovedSincePress = false;
    setFocus(Qt::MouseFocusReason);
    mToolDrag = mTool && event->button() == Qt::LeftButton && mTool->press(event);
    if (mToolDrag) {
        event->accept();
        return;
    }
    if (event->button() == Qt::LeftButton && !(event->modifiers() & Qt::ShiftModifier))
        mDrag = DragMode::Orbit;
    else if (event->button() == Qt::LeftButton || event->button() == Qt::RightButton ||
             event->button() == Qt::MiddleButton)
        mDrag = DragMode::Pan;
    event->accept();
}

void Viewport::mouseMoveEvent(QMouseEvent* event) {
    const QPoint pos = event->position().toPoint();
    if ((pos - mPressPos).manhattanLength() > 4) mMovedSincePress = true;
    if (mToolDrag) {
        mLastMouse = pos;
        mTool->move(event);
        return;
    }
    const QPoint delta = pos - mLastMouse;
    mLastMouse = pos;
    if (mDrag == DragMode::None || delta.isNull()) return;
    mAutoFramed = false;
    if (mDrag == DragMode::Orbit)
        mCamera.orbit(float(delta.x()), float(delta.y()));
    else
        mCamera.pan(float(delta.x()), float(delta.y()), float(std::max(height(), 1)));
    update();
    Q_EMIT cameraChanged();
}

void Viewport::mouseReleaseEvent(QMouseEvent* event) {
    if (mToolDrag) {
        mToolDrag = false;
        mTool->release(event);
        event->accept();
        return;
    }
    const bool click =
        mDrag != DragMode::None && !mMovedSincePress && event->button() == Qt::LeftButton;
    mDrag = DragMode::None;
    if (click && mTool) mTool->click(event);
    event->accept();
}

void Viewport::wheelEvent(QWheelEvent* event) {
    const float steps = float(event->angleDelta().y()) / 120.0f;
    if (steps == 0.0f) return;
    mAutoFramed = false;
    mCamera.zoom(steps);
    update();
    Q_EMIT cameraChanged();
    event->accept();
}

void Viewport::keyPressEvent(QKeyEvent* event) {
    if (mTool && mTool->key(event)) {
        event->accept();
        return;
    }
    // WASD flies the camera as in the reference implementation: forward and back along the
    // view on the ground plane, left and right across it; a twentieth of the distance a press.
    if (event->modifiers() == Qt::NoModifier &&
        (event->key() == Qt::Key_W || event->key() == Qt::Key_S || event->key() == Qt::Key_A ||
         event->key() == Qt::Key_D)) {
        glm::vec3 forward = mCamera.forward();
        forward.y = 0.0f;
        forward = glm::length(forward) > 1e-6f ? glm::normalize(forward) : glm::vec3(0, 0, -1);
        const glm::vec3 right = glm::normalize(glm::cross(forward, glm::vec3(0, 1, 0)));
        const float step = 0.05f * mCamera.distance();
        glm::vec3 delta(0.0f);
        if (event->key() == Qt::Key_W) delta = step * forward;
        if (event->key() == Qt::Key_S) delta = -step * forward;
        if (event->key() == Qt::Key_A) delta = -step * right;
        if (event->key() == Qt::Key_D) delta = step * right;
        mCamera.setTarget(mCamera.target() + delta);
        mAutoFramed = false;
        mViewFrom = false;
        update();
        Q_EMIT cameraChanged();
        event->accept();
        return;
    }
    if (event->key() == Qt::Key_F || event->key() == Qt::Key_Home) {
        frameScene();
        event->accept();
        return;
    }
    QWidget::keyPressEvent(event);
}

} // namespace sylva::ui
