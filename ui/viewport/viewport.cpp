#include "ui/viewport/viewport.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <set>

#include <QKeyEvent>
#include <QMouseEvent>
#include <QOpenGLContext>
#include <QOpenGLFunctions>
#include <QOpenGLShaderProgram>
#include <QTimer>
#include <QWheelEvent>

#include <glm/gtc/matrix_transform.hpp>

#include "engine/export/treeexport.h"
#include "engine/mesh/mesh.h"
#include "ui/generation/windvertexdata.h"
#include "ui/viewport/impostorlighting.h"
#include "ui/viewport/shaderprogram.h"
#include "ui/viewport/viewportsurface.h"
#include "ui/viewport/windshader.h"

namespace sylva::ui {

namespace {

// sRGB colours of the background gradient.
constexpr glm::vec3 kBackgroundTop{0.42f, 0.53f, 0.68f};
constexpr glm::vec3 kBackgroundBottom{0.84f, 0.86f, 0.88f};

} // namespace

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
    mBakeTimer = new QTimer(this);
    mBakeTimer->setSingleShot(true);
    mBakeTimer->setInterval(100);
    connect(mBakeTimer, &QTimer::timeout, this, [this] { update(); });
    mWindTimer = new QTimer(this);
    // About 60 frames a second at most while the wind clock runs; a slower renderer draws
    // as fast as it can (updates coalesce).
    mWindTimer->setInterval(16);
    connect(mWindTimer, &QTimer::timeout, this, [this] { update(); });
    mWindClock.start();
    mLod = new ViewLod(this);
    connect(mLod, &ViewLod::levelsReady, this, [this] {
        mTreesDirty = true;
        update();
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
    if (on == mWindOn) return;
    mWindOn = on;
    if (on && mMeshSkeleton) mMeshDirty = true; // its wind data, left out while off
    updateWindTimer();
    update();
}

void Viewport::setWind(const wind::WindSettings& settings) {
    // Keeps the clock where it is: the trees go on from their pose into the new wind.
    mWind = settings;
    updateWindTimer();
    update();
}

void Viewport::setWindTime(std::optional<double> seconds) {
    if (!seconds) {
        if (mWindFixed) {
            mWindClockStart = *mWindFixed;
            mWindClock.restart();
        }
        mWindFixed.reset();
    } else {
        mWindFixed = *seconds;
    }
    updateWindTimer();
    update();
}

double Viewport::windTime() const {
    return mWindFixed ? *mWindFixed : mWindClockStart + double(mWindClock.nsecsElapsed()) * 1e-9;
}

void Viewport::updateWindTimer() {
    const bool run = mWindOn && !mWindFixed && mWind.strength > 0.0f;
    if (run && !mWindTimer->isActive())
        mWindTimer->start();
    else if (!run)
        mWindTimer->stop();
}

wind::WindFrame Viewport::windFrameAt(float phase) const {
    return wind::windFrame(mWind, mPaintWindTime + double(phase) * double(mWind.period));
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

    // The mesh shader's variants: shaders/mesh.frag with TEXTURED and CUTOUT defined or not.
    bool meshOk = true;
    for (int v = 0; v < kMeshVariants && meshOk; ++v) {
        if ((v & kMeshWind) && (v & kMeshInstanced)) continue; // never drawn (drawInstanced())
        QByteArray defines;
        if (v & kMeshTextured) defines += "#define TEXTURED 1\n";
        if (v & kMeshCutout) defines += "#define CUTOUT 1\n";
        if (v & kMeshInstanced) defines += "#define INSTANCED 1\n";
        if (v & kMeshWind) defines += "#define WIND 1\n";
        mMeshPrograms[v] = buildShaderProgram(QStringLiteral("mesh.vert"),
                                              QStringLiteral("mesh.frag"), mGlError, defines);
        meshOk = mMeshPrograms[v] != nullptr;
    }
    if (meshOk)
        mLineProgram =
            buildShaderProgram(QStringLiteral("line.vert"), QStringLiteral("line.frag"), mGlError);
    if (mLineProgram)
        mBackgroundProgram = buildShaderProgram(QStringLiteral("background.vert"),
                                                QStringLiteral("background.frag"), mGlError);
    if (!mBackgroundProgram) return;
    if (!mImpostors.initialize(this, mGlError)) return;

    mBuffers.initialize(this, [this](const QString& problem) {
        // Not from inside a frame: the status bar repaints.
        QMetaObject::invokeMethod(
            this, [this, problem] { Q_EMIT warning(problem); }, Qt::QueuedConnection);
    });
    mGrid.initialize(this);
    glGenVertexArrays(1, &mEmptyVao);
    glGenBuffers(1, &mInstanceVbo);
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
    glDeleteVertexArrays(1, &mEmptyVao);
    mEmptyVao = 0;
    glDeleteBuffers(1, &mInstanceVbo);
    mInstanceVbo = 0;
    for (auto& program : mMeshPrograms)
        program.reset();
    mLineProgram.reset();
    mBackgroundProgram.reset();
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
        mWindOn ? mMeshSkeleton : std::shared_ptr<const skel::Skeleton>();
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
        keys.insert(impostorKey(t));
    mImpostors.retain([&keys](Impostors::Key k) { return keys.count(k) > 0; });
}

void Viewport::resizeGL(int width, int height) {
    (void)width;
    (void)height;
    // Until the user moves the camera, keep the scene framed for the new aspect ratio.
    if (mAutoFramed) applyFrame();
}

void Viewport::paintGL() {
    QElapsedTimer frameTimer;
    frameTimer.start();
    struct FrameTime { // the frame's CPU time, however paintGL returns
        QElapsedTimer& timer;
        double& ms;
        ~FrameTime() { ms = double(timer.nsecsElapsed()) * 1e-6; }
    } frameTime{frameTimer, mLastPaintMs};
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
    const std::vector<TreeDraw>& order = mLastDrawList;
    bakeImpostors(order);

    glClearColor(kBackgroundBottom.x, kBackgroundBottom.y, kBackgroundBottom.z, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);

    glDisable(GL_DEPTH_TEST);
    glDepthMask(GL_FALSE);
    mBackgroundProgram->bind();
    setUniform(*mBackgroundProgram, "uTop", kBackgroundTop);
    setUniform(*mBackgroundProgram, "uBottom", kBackgroundBottom);
    glBindVertexArray(mEmptyVao);
    glDrawArrays(GL_TRIANGLES, 0, 3);

    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LEQUAL);

    if (mGridVisible) mGrid.draw(*mLineProgram, viewProj);

    glDepthMask(GL_TRUE);
    mUnflushed = 0;
    mDrawnTriangles = 0;
    mDrawnTrees = 0;
    mDrawnMotion = 0;
    mDrawnPerLevel.fill(0);
    mDrawnTrianglesPerLevel.fill(0);
    mImpostorDrawCalls = 0;
    mInstancedDrawCalls = 0;
    mDrawnWindTriangles = 0;
    mPaintWindTime = windTime();
    const std::vector<DrawRange>& sceneRanges = mBuffers.sceneRanges();
    if (!sceneRanges.empty() || mBuffers.hasTrees()) {
        MeshUniforms u;
        u.viewProj = viewProj;
        u.eye = mCamera.eye();
        u.light = light;
        u.vertexColor = mBuffers.sceneVertexColors();
        // What each tree draws (its level), then the frame's wind: every swaying mesh's
        // element rotations for its tree's time, made here once and uploaded in one buffer
        // before the first draw (a buffer changed between draws would stall the renderer).
        struct Drawn {
            const TreeDraw* draw = nullptr;
            const mesh::Mesh* mesh = nullptr; ///< null: an impostor card
            int windBase = -1;                ///< its rotations in the frame's buffer
        };
        std::vector<Drawn> drawns;
        drawns.reserve(order.size());
        for (const TreeDraw& d : order) {
            const ViewTree& t = mTrees[d.index];
            ++mDrawnTrees;
            Drawn entry{&d};
            if ((d.level != ViewLod::kImpostorLevel || !mImpostors.has(impostorKey(t))) &&
                t.lod.instance && t.lod.variant) {
                // Below the impostor an instance draws its variant's level for its size on
                // screen (the drawlist's choice; its coarsest while the atlas bakes).
                const std::vector<mesh::DistanceLevel>& levels = t.lod.variant->levels;
                const std::size_t k = d.variantLevel >= 0
                                          ? std::min(std::size_t(d.variantLevel), levels.size() - 1)
                                          : levels.size() - 1;
                entry.mesh = levels[k].mesh.get();
                const std::size_t level =
                    std::size_t(std::min(d.level, ViewLod::kImpostorLevel - 1));
                ++mDrawnPerLevel[level];
                mDrawnTrianglesPerLevel[level] += entry.mesh->triangleCount();
                mDrawnMotion += d.motion ? 1 : 0;
            } else if (d.level != ViewLod::kImpostorLevel || !mImpostors.has(impostorKey(t))) {
                int used = 0;
                bool motion = false;
                // A frame drawn at reduced resolution while the view moves also draws the
                // trees' motion levels; the sharp frame that follows draws them at rest.
                entry.mesh = mLod->meshFor(t.mesh.get(), d.level, &used, mLastReduced, &motion);
                ++mDrawnPerLevel[std::size_t(used)];
                mDrawnTrianglesPerLevel[std::size_t(used)] += entry.mesh->triangleCount();
                mDrawnMotion += motion ? 1 : 0;
            }
            drawns.push_back(entry);
        }
        std::vector<int> previewBases(mPreview.size(), -1);
        int sceneBase = -1;
        GLuint rotations = 0;
        if (windActive()) {
            mWindRotations.clear();
            auto add = [this](const wind::WindElements* elements, float phase) {
                if (!elements) return -1;
                const int base = int(mWindRotations.size());
                appendWindRotations(*elements, windFrameAt(phase), mWindRotations);
                return base;
            };
            if (mBuffers.sceneWindElements()) sceneBase = add(mBuffers.sceneElements().get(), 0);
            for (Drawn& d : drawns)
                if (d.mesh)
                    if (const TreeBuffers::GpuMesh* gpu = mBuffers.find(d.mesh);
                        gpu && gpu->windElements)
                        d.windBase = add(gpu->elements.get(), mTrees[d.draw->index].windPhase);
            for (std::size_t i = 0; i < mPreview.size(); ++i)
                if (const TreeBuffers::GpuMesh* gpu = mBuffers.find(mPreview[i].mesh.get());
                    gpu && gpu->windElements)
                    previewBases[i] = add(gpu->elements.get(), mPreview[i].windPhase);
            rotations = mBuffers.uploadWindRotations(mWindRotations);
            glActiveTexture(GL_TEXTURE0 + kWindRotationsUnit);
            glBindTexture(GL_TEXTURE_BUFFER, rotations);
            glActiveTexture(GL_TEXTURE0);
        }
        if (!rotations) sceneBase = -1;
        u.wind = windFrameAt(0.0f);
        u.windBase = std::max(sceneBase, 0);
        setMeshUniforms(u);
        glActiveTexture(GL_TEXTURE0);
        glBindVertexArray(mBuffers.sceneVao());
        mDrawWind = sceneBase >= 0;
        if (mDrawWind) bindWindElements(mBuffers.sceneWindElements());
        drawRanges(sceneRanges);
        for (const DrawRange& r : sceneRanges) {
            mDrawnTriangles += r.indexCount / 3;
            if (mDrawWind) mDrawnWindTriangles += r.indexCount / 3;
        }
        mDrawWind = false;
        u.vertexColor = false;
        setMeshUniforms(u);
        // Nearest first, so that the depth test spares the rasteriser what is hidden behind.
        std::vector<const TreeDraw*> cards;
        // Instances of a variant's level, in the order of their nearest instance: one instanced
        // draw call per level and material for all of them (swaying ones are drawn one by one).
        std::vector<std::pair<const mesh::Mesh*, std::vector<glm::mat4>>> groups;
        std::map<const mesh::Mesh*, std::size_t> groupOf;
        for (const Drawn& d : drawns) {
            const ViewTree& t = mTrees[d.draw->index];
            const float highlight = t.id && mHighlighted.contains(t.id) ? 0.45f : 0.0f;
            if (!d.mesh) {
                cards.push_back(d.draw);
                continue;
            }
            if (t.lod.instance && highlight == 0.0f && d.windBase < 0) {
                auto [it, added] = groupOf.emplace(d.mesh, groups.size());
                if (added) groups.push_back({d.mesh, {}});
                groups[it->second].second.push_back(t.transform);
                continue;
            }
            drawTreeMesh(*d.mesh, t.transform, highlight, t.windPhase, rotations ? d.windBase : -1);
        }
        drawInstanced(groups);
        for (std::size_t i = 0; i < mPreview.size(); ++i)
            if (mPreview[i].mesh)
                drawTreeMesh(*mPreview[i].mesh, mPreview[i].transform, 0.25f, mPreview[i].windPhase,
                             rotations ? previewBases[i] : -1);
        if (!cards.empty()) {
            // The target's height: the reduced one while the view moves.
            const float targetHeight = float(full.height()) * (mLastReduced ? mMotionScale : 1.0f);
            mImpostors.begin(viewProj, mCamera.eye(),
                             targetHeight / (2.0f * std::tan(0.5f * mCamera.fovY())), mLastReduced);
            for (const TreeDraw* d : cards) {
                const ViewTree& t = mTrees[d->index];
                // A unique tree standing in with its variant's atlas: scaled to its height.
                const glm::mat4 model =
                    t.lod.impostorScale != 1.0f
                        ? glm::scale(t.transform, glm::vec3(t.lod.impostorScale))
                        : t.transform;
                mImpostors.draw(impostorKey(t), model,
                                t.id && mHighlighted.contains(t.id) ? 0.45f : 0.0f);
                ++mDrawnPerLevel[ViewLod::kImpostorLevel];
                mDrawnTrianglesPerLevel[ViewLod::kImpostorLevel] += 2;
                mDrawnTriangles += 2;
            }
            mImpostorDrawCalls = mImpostors.end();
        }
    }
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

void Viewport::drawTreeMesh(const mesh::Mesh& m, const glm::mat4& transform, float highlight,
                            float windPhase, int windBase) {
    const TreeBuffers::GpuMesh* gpu = mBuffers.find(&m);
    if (!gpu) return;
    MeshUniforms u = mMeshUniforms;
    u.model = transform;
    u.highlight = highlight;
    mDrawWind = windBase >= 0 && gpu->windElements != 0;
    if (mDrawWind) {
        u.wind = windFrameAt(windPhase);
        u.windBase = windBase;
        bindWindElements(gpu->windElements);
    }
    setMeshUniforms(u);
    glBindVertexArray(gpu->vao);
    drawRanges(gpu->ranges);
    for (const DrawRange& r : gpu->ranges) {
        mDrawnTriangles += r.indexCount / 3;
        if (mDrawWind) mDrawnWindTriangles += r.indexCount / 3;
    }
    mDrawWind = false;
}

void Viewport::bindWindElements(GLuint texture) {
    glActiveTexture(GL_TEXTURE0 + kWindElementsUnit);
    glBindTexture(GL_TEXTURE_BUFFER, texture);
    glActiveTexture(GL_TEXTURE0);
}

void Viewport::drawInstanced(
    const std::vector<std::pair<const mesh::Mesh*, std::vector<glm::mat4>>>& groups) {
    if (groups.empty()) return;
    // Every instance's transform in one buffer, each level's instances one run of it.
    std::vector<glm::mat4> all;
    for (const auto& [m, list] : groups)
        all.insert(all.end(), list.begin(), list.end());
    glBindBuffer(GL_ARRAY_BUFFER, mInstanceVbo);
    glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(all.size() * sizeof(glm::mat4)), all.data(),
                 GL_STREAM_DRAW);
    MeshUniforms u = mMeshUniforms;
    u.model = glm::mat4(1.0f);
    u.highlight = 0.0f;
    setMeshUniforms(u);
    std::size_t first = 0;
    for (const auto& [m, list] : groups) {
        const TreeBuffers::GpuMesh* gpu = mBuffers.find(m);
        glBindVertexArray(gpu->vao);
        std::size_t triangles = 0;
        for (const DrawRange& r : gpu->ranges)
            triangles += r.indexCount / 3;
        mDrawnTriangles += triangles * list.size();
        // Under a software renderer, runs of about kFlushTriangles, each flushed (drawRanges),
        // so the rasteriser's threads start on the nearer instances while this one bins on.
        const std::size_t run =
            mSoftware
                ? std::max<std::size_t>(1, kFlushTriangles / std::max<std::size_t>(1, triangles))
                : list.size();
        for (std::size_t done = 0; done < list.size(); done += run) {
            // The instance transform (shaders/mesh.vert, INSTANCED): locations 12-15, a column
            // each, one step per instance.
            for (GLuint c = 0; c < 4; ++c) {
                glEnableVertexAttribArray(kInstanceAttribute + c);
                glVertexAttribPointer(
                    kInstanceAttribute + c, 4, GL_FLOAT, GL_FALSE, sizeof(glm::mat4),
                    reinterpret_cast<const void*>(((first + done) * 4 + c) * sizeof(glm::vec4)));
                glVertexAttribDivisor(kInstanceAttribute + c, 1);
            }
            drawRanges(gpu->ranges, GLsizei(std::min(run, list.size() - done)));
        }
        first += list.size();
    }
    glBindBuffer(GL_ARRAY_BUFFER, 0);
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
    if (mLastReduced && windActive())
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
        impostorPx[i] = mImpostors.switchHeightPx(impostorKey(mTrees[i]));
    // Picking keeps the full mesh; only drawing follows the level of detail.
    if (!windActive()) return buildDrawList(view, drawn, mTreeBounds, instances, impostorPx);
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

Impostors::Key Viewport::impostorKey(const ViewTree& t) {
    if (t.lod.variant) return static_cast<Impostors::Key>(t.lod.variant.get());
    return t.lod.skeleton ? static_cast<Impostors::Key>(t.lod.skeleton.get())
                          : static_cast<Impostors::Key>(t.mesh.get());
}

void Viewport::bakeImpostors(const std::vector<TreeDraw>& order) {
    // Atlases bake on the impostors' worker (one per variant: its instances and the unique
    // trees of its species share it); the trees still waiting are drawn with their coarsest
    // mesh meanwhile, and a frame now and then uploads what is done.
    static const mesh::ImpostorTextures textures(exporter::resourcesDir() / "textures");
    if (mImpostors.collect() > 0) mTreesDirty = true;
    mImpostorsWanted = 0;
    for (const TreeDraw& d : order) {
        const ViewTree& t = mTrees[d.index];
        const Impostors::Key key = impostorKey(t);
        if (d.level != ViewLod::kImpostorLevel || mImpostors.has(key)) continue;
        ++mImpostorsWanted;
        if (mImpostors.isBaking(key)) continue;
        std::shared_ptr<const void> owner;
        std::shared_ptr<const mesh::Mesh> source, reference;
        if (t.lod.variant) {
            // The variant's level made for a tree about twice the atlas' cell high on the
            // reference view (the bake supersamples twice): all its views can show.
            const ViewVariant& v = *t.lod.variant;
            const double refFov = v.referenceFovYDegrees * 3.14159265358979323846 / 180.0;
            const double distance = double(v.height) * v.referenceHeightPx /
                                    (2.0 * std::tan(0.5 * refFov) * 2.0 * Impostors::kCell);
            source = v.levels[mesh::levelFor(v.levels, distance)].mesh;
            reference = v.levels.front().mesh;
            owner = t.lod.variant;
        } else {
            // Baked from the tree's coarse level once the worker has made it, or from its own
            // mesh when it has no levels coming.
            source = mLod->levelMesh(t.mesh.get(), ViewLod::kImpostorLevel - 1);
            if (!source && mLod->pending() > 0 && t.lod.skeleton) continue;
            if (!source) source = t.mesh;
            reference = t.mesh;
            owner = t.lod.skeleton ? std::shared_ptr<const void>(t.lod.skeleton)
                                   : std::shared_ptr<const void>(t.mesh);
        }
        mImpostors.request(key, std::move(owner), std::move(source), textures, std::move(reference),
                           ViewLod::impostorHeightPx());
    }
    // Atlases still baking are collected by the timer's frames too, even when no tree in the
    // view wants one now (the view moved nearer meanwhile): else lodPending() stays up.
    if ((mImpostorsWanted > 0 || mImpostors.baking() > 0) && !mBakeTimer->isActive())
        mBakeTimer->start();
}

void Viewport::setMeshUniforms(const MeshUniforms& uniforms) {
    mMeshUniforms = uniforms;
    ++mMeshUniformsStamp;
}

QOpenGLShaderProgram& Viewport::useMeshProgram(int variant) {
    QOpenGLShaderProgram& program = *mMeshPrograms[std::size_t(variant)];
    program.bind();
    std::uint64_t& stamp = mMeshProgramStamps[std::size_t(variant)];
    if (stamp != mMeshUniformsStamp) {
        // Only what changed since this variant was last used is stale; setting all is cheap.
        const MeshUniforms& u = mMeshUniforms;
        setUniform(program, "uViewProj", u.viewProj);
        setUniform(program, "uModel", u.model);
        setUniform(program, "uEye", u.eye);
        setUniform(program, "uLightDir", u.light);
        program.setUniformValue("uVertexColor", u.vertexColor);
        program.setUniformValue("uHighlight", u.highlight);
        program.setUniformValue("uTexture", 0);
        program.setUniformValue("uNormalMap", 1);
        if (variant & kMeshWind) setWindUniforms(program, u.wind, u.windBase);
        stamp = mMeshUniformsStamp;
    }
    return program;
}

void Viewport::drawRanges(const std::vector<DrawRange>& ranges, GLsizei instances) {
    // Leaf cards cut out by alpha to coverage where the target is multisampled (issue #33);
    // the written alpha is then 1 (ALPHA_TO_ONE), as every other draw's.
    GLint samples = 0;
    glGetIntegerv(GL_SAMPLES, &samples);
    for (const DrawRange& r : ranges) {
        QOpenGLShaderProgram& program =
            useMeshProgram((r.texture != 0 ? kMeshTextured : 0) | (r.alphaTest ? kMeshCutout : 0) |
                           (mDrawWind ? kMeshWind : 0) | (instances > 0 ? kMeshInstanced : 0));
        setUniform(program, "uAlbedo", r.color);
        const bool toCoverage = r.alphaTest && r.texture != 0 && samples > 1;
        if (r.alphaTest && r.texture != 0) program.setUniformValue("uAlphaToCoverage", toCoverage);
        if (toCoverage) {
            glEnable(GL_SAMPLE_ALPHA_TO_COVERAGE);
            glEnable(GL_SAMPLE_ALPHA_TO_ONE);
        } else {
            glDisable(GL_SAMPLE_ALPHA_TO_COVERAGE);
            glDisable(GL_SAMPLE_ALPHA_TO_ONE);
        }
        if (r.texture != 0) {
            glActiveTexture(GL_TEXTURE1);
            glBindTexture(GL_TEXTURE_2D, r.normalMap);
            glActiveTexture(GL_TEXTURE0);
        }
        glBindTexture(GL_TEXTURE_2D, r.texture);
        if (r.twoSided || !mCullBackFaces)
            glDisable(GL_CULL_FACE);
        else
            glEnable(GL_CULL_FACE);
        if (instances > 0) {
            // One call for every instance; under a software renderer a flush after it hands
            // the rasteriser's threads what is binned so far (see below).
            glDrawElementsInstanced(GL_TRIANGLES, GLsizei(r.indexCount), GL_UNSIGNED_INT,
                                    reinterpret_cast<void*>(std::uintptr_t(r.firstIndex) * 4u),
                                    instances);
            ++mInstancedDrawCalls;
            mUnflushed += std::size_t(r.indexCount / 3) * std::size_t(instances);
            if (mSoftware && mUnflushed >= kFlushTriangles) {
                glFlush();
                mUnflushed = 0;
            }
            continue;
        }
        if (!mSoftware) {
            glDrawElements(GL_TRIANGLES, GLsizei(r.indexCount), GL_UNSIGNED_INT,
                           reinterpret_cast<void*>(std::uintptr_t(r.firstIndex) * 4u));
            continue;
        }
        // Mesa llvmpipe transforms and bins on this thread and rasterises on its own threads
        // only when the frame is flushed, so a frame used one core at a time: a flush every
        // kFlushTriangles hands them what is drawn so far (the nearer trees, or the first
        // part of one large mesh) while this thread goes on with the rest.
        std::size_t first = r.firstIndex, left = r.indexCount / 3;
        while (left > 0) {
            const std::size_t n = std::min(left, kFlushTriangles - mUnflushed);
            glDrawElements(GL_TRIANGLES, GLsizei(3 * n), GL_UNSIGNED_INT,
                           reinterpret_cast<void*>(std::uintptr_t(first) * 4u));
            first += 3 * n;
            left -= n;
            mUnflushed += n;
            if (mUnflushed >= kFlushTriangles) {
                glFlush();
                mUnflushed = 0;
            }
        }
    }
    glBindTexture(GL_TEXTURE_2D, 0);
    glDisable(GL_CULL_FACE);
    glDisable(GL_SAMPLE_ALPHA_TO_COVERAGE);
    glDisable(GL_SAMPLE_ALPHA_TO_ONE);
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
