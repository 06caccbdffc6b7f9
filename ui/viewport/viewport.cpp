#include "ui/viewport/viewport.h"

#include <algorithm>
#include <cmath>
#include <cstddef>

#include <QApplication>
#include <QImage>
#include <QKeyEvent>
#include <QMouseEvent>
#include <QOffscreenSurface>
#include <QOpenGLContext>
#include <QOpenGLFunctions>
#include <QOpenGLShaderProgram>
#include <QOpenGLWindow>
#include <QSettings>
#include <QSurfaceFormat>
#include <QTimer>
#include <QVBoxLayout>
#include <QWheelEvent>

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/type_ptr.hpp>

#include "engine/export/treeexport.h"
#include "engine/mesh/mesh.h"
#include "ui/generation/vertexdata.h"
#include "ui/viewport/textureimage.h"

namespace sylva::ui {

namespace {

const char* const kMeshVertexShader = R"(#version 330 core
layout(location = 0) in vec3 aPosition;
layout(location = 1) in vec3 aNormal;
layout(location = 2) in vec3 aColor;
layout(location = 3) in vec2 aUv;
layout(location = 4) in float aOcclusion;
uniform mat4 uViewProj;
uniform mat4 uModel; // a tree's instance transform: rotation, uniform scale, translation
uniform vec3 uEye;
out vec3 vNormal;
out vec3 vColor;
out vec2 vUv;
out float vOcclusion;
void main() {
    vec4 world = uModel * vec4(aPosition, 1.0);
    // Normals turned towards the viewer here, per vertex, so that leaf cards and inconsistent
    // windings light the same from both sides: a software renderer interpolates three fewer
    // values per pixel than if the fragment shader did it from the world position.
    vec3 n = mat3(uModel) * aNormal;
    vNormal = dot(n, uEye - world.xyz) < 0.0 ? -n : n;
    vColor = aColor;
    vUv = aUv;
    vOcclusion = aOcclusion;
    gl_Position = uViewProj * world;
}
)";

// Lambert key light plus a hemisphere ambient (sky above, warm ground below), both dimmed by
// the crown's per-vertex occlusion. Normals come turned towards the viewer (vertex shader); a
// leaf lit from behind lets a little light through. Textures are sRGB: decoded to linear before
// lighting, with gamma 2 (a square and a square root: under a software renderer two pow() per
// pixel cost 5 % of a frame, and the difference to 2.2 does not show). Leaf cards are
// cut out by their texture's alpha, sharpened with the mipmap level so that far leaves keep
// their area instead of fading away.
// The shader is compiled in four variants (kMeshTextured, kMeshCutout, both, neither)
// rather than branching on uniforms: a software renderer (Mesa llvmpipe) runs both sides of a
// branch with masks, and a shader that can discard loses the early depth test for every
// triangle drawn with it, so bark paid for the leaves' texture lookup and cut-out.
const char* const kMeshFragmentShader = R"(
in vec3 vNormal;
in vec3 vColor;
in vec2 vUv;
in float vOcclusion;
uniform vec3 uAlbedo;
uniform bool uVertexColor; // colour by a node attribute instead of the material
uniform sampler2D uTexture;
uniform vec3 uLightDir;
uniform float uHighlight; // a selected tree: blended towards orange
out vec4 fragColor;
void main() {
#ifdef TEXTURED
    vec4 tex = texture(uTexture, vUv);
#ifdef CUTOUT
    vec2 texel = vUv * vec2(textureSize(uTexture, 0));
    float lod = 0.5 * log2(max(dot(dFdx(texel), dFdx(texel)), dot(dFdy(texel), dFdy(texel))));
    if (tex.a * (1.0 + 0.25 * max(lod, 0.0)) < 0.5) discard;
#endif
    vec3 material = tex.rgb * tex.rgb;
#else
    vec3 material = uAlbedo;
#endif
    vec3 n = vNormal;
    float len = length(n);
    n = len > 1e-6 ? n / len : vec3(0.0, 1.0, 0.0);
    float facing = dot(n, uLightDir);
    float diffuse = max(facing, 0.0);
#ifdef CUTOUT
    diffuse += 0.35 * max(-facing, 0.0); // a leaf card: translucent
#endif
    vec3 sky = vec3(0.62, 0.70, 0.85);
    vec3 ground = vec3(0.30, 0.25, 0.20);
    vec3 ambient = mix(ground, sky, 0.5 * n.y + 0.5);
    vec3 albedo = uVertexColor ? vColor : material;
    float ao = clamp(vOcclusion, 0.0, 1.0);
    vec3 color = albedo * (0.55 * ambient * ao +
                           1.35 * vec3(1.0, 0.96, 0.90) * diffuse * (0.4 + 0.6 * ao));
    color = mix(color, vec3(1.0, 0.45, 0.05), uHighlight);
    fragColor = vec4(sqrt(color), 1.0);
}
)";

const char* const kLineVertexShader = R"(#version 330 core
layout(location = 0) in vec3 aPosition;
layout(location = 1) in vec4 aColor;
uniform mat4 uViewProj;
out vec4 vColor;
out vec3 vWorld;
void main() {
    vColor = aColor;
    vWorld = aPosition;
    gl_Position = uViewProj * vec4(aPosition, 1.0);
}
)";

// The grid fades out towards its rim so that it has no hard edge.
const char* const kLineFragmentShader = R"(#version 330 core
in vec4 vColor;
in vec3 vWorld;
uniform vec3 uCenter;
uniform float uExtent;
out vec4 fragColor;
void main() {
    float r = length(vWorld.xz - uCenter.xz) / uExtent;
    fragColor = vec4(vColor.rgb, vColor.a * (1.0 - smoothstep(0.55, 1.0, r)));
}
)";

// One triangle that covers the screen; no vertex buffer needed.
const char* const kBackgroundVertexShader = R"(#version 330 core
out float vT;
void main() {
    vec2 p = vec2(gl_VertexID == 1 ? 3.0 : -1.0, gl_VertexID == 2 ? 3.0 : -1.0);
    vT = 0.5 * p.y + 0.5;
    gl_Position = vec4(p, 0.0, 1.0);
}
)";

const char* const kBackgroundFragmentShader = R"(#version 330 core
in float vT;
uniform vec3 uTop;
uniform vec3 uBottom;
out vec4 fragColor;
void main() {
    fragColor = vec4(mix(uBottom, uTop, clamp(vT, 0.0, 1.0)), 1.0);
}
)";

// sRGB colours of the background gradient.
constexpr glm::vec3 kBackgroundTop{0.42f, 0.53f, 0.68f};
constexpr glm::vec3 kBackgroundBottom{0.84f, 0.86f, 0.88f};

std::unique_ptr<QOpenGLShaderProgram> buildProgram(const char* vertex, const char* fragment,
                                                   QString& error) {
    auto program = std::make_unique<QOpenGLShaderProgram>();
    if (!program->addShaderFromSourceCode(QOpenGLShader::Vertex, vertex) ||
        !program->addShaderFromSourceCode(QOpenGLShader::Fragment, fragment) || !program->link()) {
        error = QStringLiteral("shader error: ") + program->log();
        return nullptr;
    }
    return program;
}

void setUniform(QOpenGLShaderProgram& program, const char* name, const glm::vec3& v) {
    program.setUniformValue(name, v.x, v.y, v.z);
}

void setUniform(QOpenGLShaderProgram& program, const char* name, const glm::mat4& m) {
    // glm is column-major like OpenGL, so the raw array goes through unchanged.
    program.setUniformValue(program.uniformLocation(name),
                            QMatrix4x4(glm::value_ptr(m)).transposed());
}

bool indicesInRange(const mesh::Mesh& m) {
    for (std::uint32_t index : m.indices)
        if (index >= m.positions.size()) return false;
    return true;
}

} // namespace

glm::vec3 Viewport::materialColor(const std::string& material) {
    if (material == "leaf" || material == "leaves" || material == "foliage")
        return {0.11f, 0.30f, 0.06f};
    if (material == "bark" || material.empty()) return {0.17f, 0.10f, 0.055f};
    if (material == "ground") return {0.10f, 0.09f, 0.05f}; // a project's terrain
    return {0.35f, 0.35f, 0.35f};                           // obstacles and anything else
}

void Viewport::installDefaultSurfaceFormat() {
    QSurfaceFormat format = QSurfaceFormat::defaultFormat();
    format.setRenderableType(QSurfaceFormat::OpenGL);
    format.setVersion(3, 3);
    format.setProfile(QSurfaceFormat::CoreProfile);
    format.setDepthBufferSize(24);
    // SYLVA_MSAA=0 turns multisampling off: a software renderer (Mesa llvmpipe) draws a
    // frame about twice as fast without it (docs/performance.md).
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

int Viewport::samplesPreference() {
    const int samples = QSettings().value(QStringLiteral("viewport/samples"), kAutoSamples).toInt();
    return samples == 0 || samples == 2 || samples == 4 || samples == 8 ? samples : kAutoSamples;
}

void Viewport::setSamplesPreference(int samples) {
    QSettings().setValue(QStringLiteral("viewport/samples"), samples);
}

int Viewport::applySamplesPreference() {
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
            const QString name = QString::fromLatin1(renderer ? renderer : "").toLower();
            for (const char* software : {"llvmpipe", "softpipe", "swrast", "swiftshader"})
                if (name.contains(QLatin1String(software))) samples = 0;
            probe.doneCurrent();
        }
    }
    QSurfaceFormat format = QSurfaceFormat::defaultFormat();
    format.setSamples(samples);
    QSurfaceFormat::setDefaultFormat(format);
    return samples;
}

/// The native OpenGL window a Viewport draws into: paints with the viewport's GL code and
/// hands its input to the viewport widget (which the rest of the editor talks to).
class ViewportSurface : public QOpenGLWindow {
public:
    explicit ViewportSurface(Viewport& view) : QOpenGLWindow(NoPartialUpdate), mView(view) {}

protected:
    void initializeGL() override { mView.initializeGL(); }
    void resizeGL(int w, int h) override { mView.resizeGL(w, h); }
    void paintGL() override { mView.paintGL(); }

    bool event(QEvent* event) override {
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

private:
    /// A click in the view makes its main window the active one (the one keys go to), as a
    /// click in a widget does: without that, an X server without a window manager (Xvfb)
    /// sends keys to the window under the pointer, this one, and Qt matches no shortcut.
    void activateMainWindow() {
        QWidget* top = mView.window();
        if (top && QApplication::activeWindow() != top) top->activateWindow();
    }

    Viewport& mView;
};

Viewport::Viewport(QWidget* parent) : QWidget(parent) {
    QSurfaceFormat format = QSurfaceFormat::defaultFormat();
    format.setVersion(3, 3);
    format.setProfile(QSurfaceFormat::CoreProfile);
    format.setDepthBufferSize(24);
    if (format.samples() < 0) format.setSamples(QSurfaceFormat::defaultFormat().samples());
    // format() reports the context's format once it exists, whose samples are not the FBO's.
    mSamples = format.samples();
    mSurface = new ViewportSurface(*this);
    mSurface->setFormat(format);
    QWidget* container = QWidget::createWindowContainer(mSurface, this);
    container->setFocusPolicy(Qt::NoFocus);
    // Keyboard focus stays with the widget: shortcuts and the widget's key handling work as
    // for any widget, and a click does not take focus from the main window. Set once
    // embedded: the container sets the window's flags.
    mSurface->setFlag(Qt::WindowDoesNotAcceptFocus);
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->addWidget(container);
    connect(mSurface, &QOpenGLWindow::frameSwapped, this, &Viewport::frameSwapped);
    setFocusPolicy(Qt::StrongFocus);
    setMouseTracking(false);
    setMinimumSize(160, 120);
    mSharpTimer = new QTimer(this);
    mSharpTimer->setSingleShot(true);
    mSharpTimer->setInterval(kSharpAfterMs);
    connect(mSharpTimer, &QTimer::timeout, this, [this] {
        mSharpNext = true;
        update();
    });
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
    // A window's back buffer holds nothing defined after a swap: draw a frame into it and
    // read it back without swapping (what is on screen is left as it is).
    if (!isVisible() || !mSurface->isExposed()) return {};
    mSurface->makeCurrent();
    if (!context()) return {};
    paintGL();
    const int w = int(std::lround(width() * devicePixelRatioF()));
    const int h = int(std::lround(height() * devicePixelRatioF()));
    QImage image(w, h, QImage::Format_RGBA8888);
    QOpenGLFunctions* f = context()->functions();
    f->glBindFramebuffer(GL_FRAMEBUFFER, defaultFramebufferObject());
    f->glPixelStorei(GL_PACK_ALIGNMENT, 4);
    f->glReadPixels(0, 0, w, h, GL_RGBA, GL_UNSIGNED_BYTE, image.bits());
    mSurface->doneCurrent();
    image = image.mirrored().convertToFormat(QImage::Format_RGB32);
    image.setDevicePixelRatio(devicePixelRatioF());
    return image;
}

bool Viewport::event(QEvent* event) {
    // The cursor a tool sets on the widget is the window's too.
    if (event->type() == QEvent::CursorChange) mSurface->setCursor(cursor());
    return QWidget::event(event);
}

void Viewport::setMesh(std::shared_ptr<const mesh::Mesh> mesh, bool frame,
                       std::shared_ptr<const std::vector<ViewVertex>> vertices) {
    mMesh = std::move(mesh);
    mMeshVertices = std::move(vertices);
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
    mGridExtent = 0.0f; // rebuilt for the new scene size at the next paint
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
    {
        // A software rasteriser's frame time grows with the pixels drawn; a GPU's hardly does.
        const QString renderer =
            QString::fromLatin1(reinterpret_cast<const char*>(glGetString(GL_RENDERER))).toLower();
        bool software = false;
        for (const char* name : {"llvmpipe", "softpipe", "swrast", "swiftshader"})
            software = software || renderer.contains(QLatin1String(name));
        mSoftware = software;
        mMotionScale = software && mSamples <= 1 ? 0.5f : 1.0f;
        if (qEnvironmentVariableIsSet("SYLVA_MOTION_SCALE"))
            mMotionScale =
                std::clamp(qEnvironmentVariable("SYLVA_MOTION_SCALE").toFloat(), 0.25f, 1.0f);
        if (mSamples > 1) mMotionScale = 1.0f; // no blit into a multisampled framebuffer
    }
    bool meshOk = true;
    for (int v = 0; v < kMeshVariants && meshOk; ++v) {
        QByteArray fragment("#version 330 core\n");
        if (v & kMeshTextured) fragment += "#define TEXTURED 1\n";
        if (v & kMeshCutout) fragment += "#define CUTOUT 1\n";
        fragment += kMeshFragmentShader;
        mMeshPrograms[v] = buildProgram(kMeshVertexShader, fragment.constData(), mGlError);
        meshOk = mMeshPrograms[v] != nullptr;
    }
    if (meshOk) mLineProgram = buildProgram(kLineVertexShader, kLineFragmentShader, mGlError);
    if (mLineProgram)
        mBackgroundProgram =
            buildProgram(kBackgroundVertexShader, kBackgroundFragmentShader, mGlError);
    if (!mBackgroundProgram) return;
    if (!mImpostors.initialize(this, mGlError)) return;

    glGenVertexArrays(1, &mMeshVao);
    glGenBuffers(1, &mMeshVbo);
    glGenBuffers(1, &mMeshIbo);
    glGenVertexArrays(1, &mGridVao);
    glGenBuffers(1, &mGridVbo);
    glGenVertexArrays(1, &mEmptyVao);

    glBindVertexArray(mMeshVao);
    glBindBuffer(GL_ARRAY_BUFFER, mMeshVbo);
    glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, mMeshIbo);
    // Position, normal, attribute colour (zero unless the view colours by an attribute), uv,
    // occlusion.
    setMeshAttributes();

    glGenVertexArrays(1, &mOverlayVao);
    glGenBuffers(1, &mOverlayVbo);
    for (const auto& [vao, vbo] :
         {std::pair{mGridVao, mGridVbo}, std::pair{mOverlayVao, mOverlayVbo}}) {
        glBindVertexArray(vao);
        glBindBuffer(GL_ARRAY_BUFFER, vbo);
        glEnableVertexAttribArray(0);
        glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, 7 * sizeof(float), nullptr);
        glEnableVertexAttribArray(1);
        glVertexAttribPointer(1, 4, GL_FLOAT, GL_FALSE, 7 * sizeof(float),
                              reinterpret_cast<void*>(3 * sizeof(float)));
    }
    glBindVertexArray(0);
    mGlReady = true;
    mMeshDirty = true;
    mTreesDirty = true;
    mGridExtent = 0.0f;
}

void Viewport::releaseGl() {
    releaseTreeBuffers();
    releaseReducedTarget();
    glDeleteVertexArrays(1, &mOverlayVao);
    glDeleteBuffers(1, &mOverlayVbo);
    mOverlayVao = mOverlayVbo = 0;
    mImpostors.release();
    glDeleteVertexArrays(1, &mMeshVao);
    glDeleteBuffers(1, &mMeshVbo);
    glDeleteBuffers(1, &mMeshIbo);
    glDeleteVertexArrays(1, &mGridVao);
    glDeleteBuffers(1, &mGridVbo);
    glDeleteVertexArrays(1, &mEmptyVao);
    mMeshVao = mMeshVbo = mMeshIbo = mGridVao = mGridVbo = mEmptyVao = 0;
    for (const auto& [path, id] : mTextures)
        if (id) glDeleteTextures(1, &id);
    mTextures.clear();
    for (auto& program : mMeshPrograms)
        program.reset();
    mLineProgram.reset();
    mBackgroundProgram.reset();
    mGlReady = false;
}

namespace {
std::vector<Viewport::DrawRange> rangesOf(const mesh::Mesh& m) {
    std::vector<Viewport::DrawRange> ranges;
    const auto total = static_cast<std::uint32_t>(m.indices.size());
    if (m.submeshes.empty()) {
        ranges.push_back({Viewport::materialColor("bark"), 0, total});
        return ranges;
    }
    for (const mesh::Submesh& s : m.submeshes) {
        if (s.firstIndex >= total) continue;
        const std::uint32_t count = std::min(s.indexCount, total - s.firstIndex);
        Viewport::DrawRange r{Viewport::materialColor(s.material), s.firstIndex, count - count % 3};
        // Sylva's bark tubes are closed and wound counter-clockwise seen from outside, so their
        // back faces are never seen: culling them spares the rasteriser half the triangles
        // (a third of a software renderer's frame). Ribbons made for one camera are not.
        r.twoSided = s.material != "bark" || m.cameraRibbons;
        ranges.push_back(r);
    }
    return ranges;
}
} // namespace

void Viewport::uploadMesh() {
    mMeshDirty = false;
    mRanges.clear();
    if (!mMesh || mMesh->empty() || mMesh->indices.empty()) return;
    const mesh::Mesh& m = *mMesh;
    // A bad index would make the driver read out of bounds; refuse the mesh instead.
    if (!indicesInRange(m)) {
        mGlError = tr("The mesh has an index out of range; it is not drawn.");
        return;
    }
    const bool colored = mVertexColors.size() == m.positions.size();
    // The vertices made beside the mesh on a worker, when they fit and no attribute colours
    // replace theirs; else made here.
    std::vector<ViewVertex> made;
    const bool prepared = !colored && mMeshVertices && mMeshVertices->size() == m.positions.size();
    if (!prepared) made = interleaveVertices(m, mVertexColors);
    const std::vector<ViewVertex>& interleaved = prepared ? *mMeshVertices : made;
    mUseVertexColors = colored;
    glBindVertexArray(mMeshVao);
    glBindBuffer(GL_ARRAY_BUFFER, mMeshVbo);
    glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(interleaved.size() * sizeof(ViewVertex)),
                 interleaved.data(), GL_STATIC_DRAW);
    glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, mMeshIbo);
    glBufferData(GL_ELEMENT_ARRAY_BUFFER, GLsizeiptr(m.indices.size() * sizeof(std::uint32_t)),
                 m.indices.data(), GL_STATIC_DRAW);
    glBindVertexArray(0);

    mRanges = rangesOf(m);
    bindTextures(m, mRanges);
}

void Viewport::setMeshAttributes() {
    constexpr GLsizei kStride = sizeof(ViewVertex);
    auto at = [](std::size_t offset) { return reinterpret_cast<void*>(offset); };
    for (GLuint a = 0; a < 5; ++a)
        glEnableVertexAttribArray(a);
    glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, kStride, at(offsetof(ViewVertex, position)));
    glVertexAttribPointer(1, 3, GL_FLOAT, GL_FALSE, kStride, at(offsetof(ViewVertex, normal)));
    glVertexAttribPointer(2, 3, GL_FLOAT, GL_FALSE, kStride, at(offsetof(ViewVertex, color)));
    glVertexAttribPointer(3, 2, GL_FLOAT, GL_FALSE, kStride, at(offsetof(ViewVertex, uv)));
    glVertexAttribPointer(4, 1, GL_FLOAT, GL_FALSE, kStride, at(offsetof(ViewVertex, occlusion)));
}

void Viewport::bindTextures(const mesh::Mesh& m, std::vector<DrawRange>& ranges) {
    // rangesOf() keeps the submeshes' order, skipping those that start past the indices.
    std::size_t r = 0;
    const auto total = static_cast<std::uint32_t>(m.indices.size());
    for (const mesh::Submesh& s : m.submeshes) {
        if (s.firstIndex >= total) continue;
        if (r >= ranges.size()) break;
        ranges[r].texture = textureFor(s.material, s.texture);
        ranges[r].alphaTest = s.material == "leaf" && ranges[r].texture != 0;
        ++r;
    }
    if (m.submeshes.empty() && !ranges.empty()) ranges[0].texture = textureFor("bark", {});
}

GLuint Viewport::textureFor(const std::string& material, const std::string& file) {
    std::string path = file;
    if (path.empty()) {
        // Sylva's shipped textures for the two materials it makes; nothing for the rest.
        if (material != "bark" && material != "leaf") return 0;
        const std::filesystem::path dir = exporter::resourcesDir();
        if (dir.empty()) return 0;
        path = (dir / "textures" / (material + ".png")).string();
    }
    if (auto it = mTextures.find(path); it != mTextures.end()) return it->second;
    GLuint id = 0;
    GLint gpuSide = 0;
    glGetIntegerv(GL_MAX_TEXTURE_SIZE, &gpuSide);
    TextureImage read = readTextureImage(QString::fromStdString(path),
                                         gpuSide > 0 ? std::min(gpuSide, kMaxViewTextureSide)
                                                     : kMaxViewTextureSide);
    if (!read.problem.isEmpty()) {
        mTextureProblems << read.problem;
        // Not from inside a frame: the status bar repaints.
        QMetaObject::invokeMethod(
            this, [this, text = read.problem] { Q_EMIT warning(text); }, Qt::QueuedConnection);
    }
    QImage image = std::move(read.image);
    if (!image.isNull()) {
        // OpenGL's first row is v = 0, the image's bottom (a leaf's stem).
        image = image.convertToFormat(QImage::Format_RGBA8888).mirrored();
        glGenTextures(1, &id);
        glBindTexture(GL_TEXTURE_2D, id);
        glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, image.width(), image.height(), 0, GL_RGBA,
                     GL_UNSIGNED_BYTE, image.constBits());
        glGenerateMipmap(GL_TEXTURE_2D);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
        const GLint wrap = material == "leaf" ? GL_CLAMP_TO_EDGE : GL_REPEAT;
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, wrap);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, wrap);
        glBindTexture(GL_TEXTURE_2D, 0);
    }
    mTextures.emplace(path, id); // a file that cannot be read is not tried again
    return id;
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
        hidden[i] = mTrees[i].id != 0 && mHidden.contains(mTrees[i].id);
    return pickTree(rayAt(pos), mTrees, mTreeBounds, hidden);
}

void Viewport::frameBox(const glm::vec3& lo, const glm::vec3& hi) {
    mViewFrom = false;
    mCamera.frame(lo, hi, aspect());
    mAutoFramed = false;
    mGridExtent = 0.0f;
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
    std::map<const mesh::Mesh*, GpuMesh> kept;
    std::vector<std::shared_ptr<const mesh::Mesh>> all;
    for (const ViewTree& t : mTrees)
        all.push_back(t.mesh);
    for (const ViewTree& t : mPreview)
        all.push_back(t.mesh);
    const std::size_t treeMeshes = all.size();
    for (std::shared_ptr<const mesh::Mesh>& level : mLod->allLevelMeshes())
        all.push_back(std::move(level));
    for (std::size_t k = 0; k < all.size(); ++k) {
        const std::shared_ptr<const mesh::Mesh>& treeMesh = all[k];
        if (!treeMesh || treeMesh->empty() || kept.count(treeMesh.get())) continue;
        auto old = mGpuTrees.find(treeMesh.get());
        if (old != mGpuTrees.end()) {
            kept.insert(mGpuTrees.extract(old));
            continue;
        }
        if (!indicesInRange(*treeMesh)) continue;
        GpuMesh gpu;
        gpu.mesh = treeMesh;
        gpu.ranges = rangesOf(*treeMesh);
        bindTextures(*treeMesh, gpu.ranges);
        glGenVertexArrays(1, &gpu.vao);
        glGenBuffers(1, &gpu.vbo);
        glGenBuffers(1, &gpu.ibo);
        glBindVertexArray(gpu.vao);
        glBindBuffer(GL_ARRAY_BUFFER, gpu.vbo);
        const std::vector<ViewVertex> data = interleaveVertices(*treeMesh, {});
        glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(data.size() * sizeof(ViewVertex)), data.data(),
                     GL_STATIC_DRAW);
        glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, gpu.ibo);
        glBufferData(GL_ELEMENT_ARRAY_BUFFER,
                     GLsizeiptr(treeMesh->indices.size() * sizeof(std::uint32_t)),
                     treeMesh->indices.data(), GL_STATIC_DRAW);
        setMeshAttributes();
        glBindVertexArray(0);
        ++(k < treeMeshes ? mUploads : mLevelUploads);
        kept.emplace(treeMesh.get(), std::move(gpu));
    }
    releaseTreeBuffers(); // those no tree draws any more
    mGpuTrees = std::move(kept);
    mImpostors.retain([this](const mesh::Mesh* m) { return mGpuTrees.count(m) > 0; });
}

void Viewport::releaseTreeBuffers() {
    for (auto& [key, gpu] : mGpuTrees) {
        glDeleteVertexArrays(1, &gpu.vao);
        glDeleteBuffers(1, &gpu.vbo);
        glDeleteBuffers(1, &gpu.ibo);
    }
    mGpuTrees.clear();
}

void Viewport::buildGrid() {
    const float radius = mCamera.sceneRadius();
    // A power-of-ten spacing that gives a few dozen lines across the framed scene.
    const float step = std::pow(10.0f, std::floor(std::log10(std::max(radius, 1e-3f) * 0.5f)));
    const int half = std::max(5, int(std::ceil(2.0f * radius / step)));
    mGridExtent = float(half) * step;
    const glm::vec3 centre = 0.5f * (mBoundsLo + mBoundsHi);
    const float cx = std::round(centre.x / step) * step;
    const float cz = std::round(centre.z / step) * step;
    const float y = std::min(0.0f, mBoundsLo.y);
    mGridCenter = glm::vec3(cx, y, cz);

    std::vector<float> data;
    data.reserve(std::size_t(4 * half + 2) * 2 * 7);
    auto line = [&](glm::vec3 a, glm::vec3 b, glm::vec4 c) {
        for (const glm::vec3& p : {a, b})
            data.insert(data.end(), {p.x, p.y, p.z, c.x, c.y, c.z, c.w});
    };
    const glm::vec4 minor(0.30f, 0.33f, 0.37f, 0.30f);
    const glm::vec4 major(0.25f, 0.27f, 0.31f, 0.60f);
    for (int i = -half; i <= half; ++i) {
        const float x = cx + float(i) * step;
        const float z = cz + float(i) * step;
        const long long gx = std::llround(x / step);
        const long long gz = std::llround(z / step);
        const glm::vec4 cX =
            gx == 0 ? glm::vec4(0.30f, 0.42f, 0.75f, 0.85f) : (gx % 10 == 0 ? major : minor);
        const glm::vec4 cZ =
            gz == 0 ? glm::vec4(0.75f, 0.30f, 0.28f, 0.85f) : (gz % 10 == 0 ? major : minor);
        // Line of constant x runs along z (the z axis when x == 0), and vice versa.
        line({x, y, cz - mGridExtent}, {x, y, cz + mGridExtent}, cX);
        line({cx - mGridExtent, y, z}, {cx + mGridExtent, y, z}, cZ);
    }
    glBindBuffer(GL_ARRAY_BUFFER, mGridVbo);
    glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(data.size() * sizeof(float)), data.data(),
                 GL_STATIC_DRAW);
    glBindBuffer(GL_ARRAY_BUFFER, 0);
    mGridVertexCount = GLsizei(data.size() / 7);
}

void Viewport::resizeGL(int width, int height) {
    (void)width;
    (void)height;
    // Until the user moves the camera, keep the scene framed for the new aspect ratio.
    if (mAutoFramed) applyFrame();
}

void Viewport::paintGL() {
    if (!mGlReady) {
        // Without our functions, fall back to the context's basic ones to show a neutral grey.
        QOpenGLFunctions* f = context()->functions();
        f->glClearColor(0.25f, 0.25f, 0.25f, 1.0f);
        f->glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
        return;
    }
    if (mMeshDirty) uploadMesh();
    if (mTreesDirty) syncTreeBuffers();
    if (mGridExtent <= 0.0f) buildGrid();

    const glm::mat4 viewProj = mCamera.projectionMatrix(aspect()) * mCamera.viewMatrix();
    // A key light that follows the camera (above, to the left, from the front) keeps the tree
    // readable from every side.
    const glm::vec3 light =
        glm::normalize(-0.5f * mCamera.forward() + 0.8f * mCamera.up() - 0.6f * mCamera.right());
    const std::vector<TreeDraw> order = treesToDraw(viewProj);
    bakeImpostors(order);

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
        mLastReduced = bindReducedTarget(full);
        mSharpTimer->start();
    }
    mSharpNext = false;

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

    if (mGridVisible && mGridVertexCount > 0) {
        glEnable(GL_BLEND);
        glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
        mLineProgram->bind();
        setUniform(*mLineProgram, "uViewProj", viewProj);
        setUniform(*mLineProgram, "uCenter", mGridCenter);
        mLineProgram->setUniformValue("uExtent", mGridExtent);
        glBindVertexArray(mGridVao);
        glDrawArrays(GL_LINES, 0, mGridVertexCount);
        glDisable(GL_BLEND);
    }

    glDepthMask(GL_TRUE);
    mUnflushed = 0;
    mDrawnTriangles = 0;
    mDrawnTrees = 0;
    mDrawnMotion = 0;
    mDrawnPerLevel.fill(0);
    if (!mRanges.empty() || !mGpuTrees.empty()) {
        MeshUniforms u;
        u.viewProj = viewProj;
        u.eye = mCamera.eye();
        u.light = light;
        u.vertexColor = mUseVertexColors;
        setMeshUniforms(u);
        glActiveTexture(GL_TEXTURE0);
        glBindVertexArray(mMeshVao);
        drawRanges(mRanges);
        for (const DrawRange& r : mRanges)
            mDrawnTriangles += r.indexCount / 3;
        u.vertexColor = false;
        setMeshUniforms(u);
        // Nearest first, so that the depth test spares the rasteriser what is hidden behind.
        std::vector<const TreeDraw*> cards;
        for (const TreeDraw& d : order) {
            const ViewTree& t = mTrees[d.index];
            const float highlight = t.id && mHighlighted.contains(t.id) ? 0.45f : 0.0f;
            ++mDrawnTrees;
            if (d.level == ViewLod::kImpostorLevel && mImpostors.has(t.mesh.get())) {
                cards.push_back(&d);
                continue;
            }
            int used = 0;
            bool motion = false;
            // A frame drawn at reduced resolution while the view moves also draws the trees'
            // motion levels; the sharp frame that follows draws them at rest.
            const mesh::Mesh* drawn =
                mLod->meshFor(t.mesh.get(), d.level, &used, mLastReduced, &motion);
            ++mDrawnPerLevel[std::size_t(used)];
            mDrawnMotion += motion ? 1 : 0;
            drawTreeMesh(*drawn, t.transform, highlight);
        }
        for (const ViewTree& t : mPreview)
            if (t.mesh) drawTreeMesh(*t.mesh, t.transform, 0.25f);
        if (!cards.empty()) {
            mImpostors.begin(viewProj);
            for (const TreeDraw* d : cards) {
                const ViewTree& t = mTrees[d->index];
                mImpostors.draw(t.mesh.get(), t.transform,
                                t.id && mHighlighted.contains(t.id) ? 0.45f : 0.0f);
                ++mDrawnPerLevel[ViewLod::kImpostorLevel];
                mDrawnTriangles += 4;
            }
            mImpostors.end();
        }
    }
    drawOverlay(viewProj);
    drawBand();
    glBindVertexArray(0);
    if (mLastReduced) {
        glBindFramebuffer(GL_READ_FRAMEBUFFER, mLowFbo);
        glBindFramebuffer(GL_DRAW_FRAMEBUFFER, defaultFramebufferObject());
        glBlitFramebuffer(0, 0, mLowSize.width(), mLowSize.height(), 0, 0, full.width(),
                          full.height(), GL_COLOR_BUFFER_BIT, GL_LINEAR);
        glBindFramebuffer(GL_FRAMEBUFFER, defaultFramebufferObject());
        glViewport(0, 0, full.width(), full.height());
    }
}

bool Viewport::bindReducedTarget(const QSize& full) {
    const QSize size(std::max(1, int(std::lround(float(full.width()) * mMotionScale))),
                     std::max(1, int(std::lround(float(full.height()) * mMotionScale))));
    if (!mLowFbo || size != mLowSize) {
        releaseReducedTarget();
        glGenFramebuffers(1, &mLowFbo);
        glGenRenderbuffers(1, &mLowColor);
        glGenRenderbuffers(1, &mLowDepth);
        glBindRenderbuffer(GL_RENDERBUFFER, mLowColor);
        glRenderbufferStorage(GL_RENDERBUFFER, GL_RGBA8, size.width(), size.height());
        glBindRenderbuffer(GL_RENDERBUFFER, mLowDepth);
        glRenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH_COMPONENT24, size.width(), size.height());
        glBindFramebuffer(GL_FRAMEBUFFER, mLowFbo);
        glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, mLowColor);
        glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, mLowDepth);
        mLowSize = size;
        if (glCheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE) {
            releaseReducedTarget();
            glBindFramebuffer(GL_FRAMEBUFFER, defaultFramebufferObject());
            mMotionScale = 1.0f; // not again
            return false;
        }
    }
    glBindFramebuffer(GL_FRAMEBUFFER, mLowFbo);
    glViewport(0, 0, mLowSize.width(), mLowSize.height());
    return true;
}

void Viewport::releaseReducedTarget() {
    if (mLowFbo) glDeleteFramebuffers(1, &mLowFbo);
    if (mLowColor) glDeleteRenderbuffers(1, &mLowColor);
    if (mLowDepth) glDeleteRenderbuffers(1, &mLowDepth);
    mLowFbo = mLowColor = mLowDepth = 0;
    mLowSize = {};
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

void Viewport::drawBand() {
    if (mBand.isEmpty()) return;
    // In widget pixels, y down; a translucent fill inside a sharp outline.
    const glm::mat4 pixels =
        glm::ortho(0.0f, float(std::max(1, width())), float(std::max(1, height())), 0.0f);
    const float x0 = float(mBand.left()), y0 = float(mBand.top());
    const float x1 = float(mBand.right() + 1), y1 = float(mBand.bottom() + 1);
    const glm::vec4 fill(0.25f, 0.55f, 0.95f, 0.18f), edge(0.25f, 0.55f, 0.95f, 0.95f);
    std::vector<float> data;
    auto vertex = [&data](float x, float y, const glm::vec4& c) {
        data.insert(data.end(), {x, y, 0.0f, c.x, c.y, c.z, c.w});
    };
    for (const auto& [x, y] : {std::pair{x0, y0}, {x1, y0}, {x1, y1}, {x0, y0}, {x1, y1}, {x0, y1}})
        vertex(x, y, fill);
    const std::pair<float, float> corners[] = {{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}};
    for (int k = 0; k < 4; ++k) {
        vertex(corners[k].first, corners[k].second, edge);
        vertex(corners[(k + 1) % 4].first, corners[(k + 1) % 4].second, edge);
    }
    drawOnTop(data, pixels, 6);
}

void Viewport::drawOverlay(const glm::mat4& viewProj) {
    if (!mOverlay) return;
    const std::vector<OverlayLine> lines = mOverlay();
    if (lines.empty()) return;
    std::vector<float> data;
    data.reserve(lines.size() * 14);
    for (const OverlayLine& l : lines)
        for (const glm::vec3& p : {l.a, l.b})
            data.insert(data.end(), {p.x, p.y, p.z, l.color.x, l.color.y, l.color.z, l.color.w});
    drawOnTop(data, viewProj, 0);
}

void Viewport::drawOnTop(const std::vector<float>& data, const glm::mat4& viewProj,
                         int triangleVertices) {
    // Handles and the band stay visible through the trees and the ground they stand in.
    glDisable(GL_DEPTH_TEST);
    glEnable(GL_BLEND);
    glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    mLineProgram->bind();
    setUniform(*mLineProgram, "uViewProj", viewProj);
    setUniform(*mLineProgram, "uCenter", glm::vec3(0.0f));
    mLineProgram->setUniformValue("uExtent", 1e30f); // no fading
    glBindVertexArray(mOverlayVao);
    glBindBuffer(GL_ARRAY_BUFFER, mOverlayVbo);
    glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(data.size() * sizeof(float)), data.data(),
                 GL_STREAM_DRAW);
    const auto vertices = GLsizei(data.size() / 7);
    if (triangleVertices > 0) glDrawArrays(GL_TRIANGLES, 0, triangleVertices);
    glDrawArrays(GL_LINES, triangleVertices, vertices - triangleVertices);
    glBindBuffer(GL_ARRAY_BUFFER, 0);
    glDisable(GL_BLEND);
    glEnable(GL_DEPTH_TEST);
}

void Viewport::drawTreeMesh(const mesh::Mesh& m, const glm::mat4& transform, float highlight) {
    auto gpu = mGpuTrees.find(&m);
    if (gpu == mGpuTrees.end()) return;
    MeshUniforms u = mMeshUniforms;
    u.model = transform;
    u.highlight = highlight;
    setMeshUniforms(u);
    glBindVertexArray(gpu->second.vao);
    drawRanges(gpu->second.ranges);
    for (const DrawRange& r : gpu->second.ranges)
        mDrawnTriangles += r.indexCount / 3;
}

std::vector<Viewport::TreeDraw> Viewport::treesToDraw(const glm::mat4& viewProj) const {
    // Frustum culling: a tree whose world box lies outside one of the six planes is not drawn
    // (a forest seen from inside draws only what is in front of the camera).
    glm::vec4 planes[6];
    const glm::mat4 m = glm::transpose(viewProj);
    for (int k = 0; k < 3; ++k) {
        planes[2 * k] = m[3] + m[k];
        planes[2 * k + 1] = m[3] - m[k];
    }
    auto visible = [&planes](const Bounds& b) {
        if (b.empty()) return false;
        for (const glm::vec4& p : planes) {
            const glm::vec3 far(p.x >= 0 ? b.hi.x : b.lo.x, p.y >= 0 ? b.hi.y : b.lo.y,
                                p.z >= 0 ? b.hi.z : b.lo.z);
            if (glm::dot(glm::vec3(p), far) + p.w < 0.0f) return false;
        }
        return true;
    };
    // The level of detail of a tree follows its height on screen (ui/viewport/viewlod.h);
    // picking keeps the full mesh.
    const glm::vec3 eye = mCamera.eye();
    const double viewportPx = double(height()) * devicePixelRatioF();
    std::vector<TreeDraw> order;
    order.reserve(mTrees.size());
    for (std::size_t i = 0; i < mTrees.size(); ++i) {
        const ViewTree& t = mTrees[i];
        if (!t.mesh || (t.id && mHidden.contains(t.id))) continue;
        TreeDraw d;
        d.index = i;
        if (i < mTreeBounds.size()) {
            const Bounds& b = mTreeBounds[i];
            if (!visible(b)) continue;
            d.distance = glm::length(0.5f * (b.lo + b.hi) - eye);
            if (mLod->isEnabled())
                d.level = ViewLod::levelFor(
                    ViewLod::equivalentHeights(double(d.distance), double(b.hi.y - b.lo.y),
                                               double(mCamera.fovY()), viewportPx));
        }
        order.push_back(d);
    }
    std::sort(order.begin(), order.end(), [](const TreeDraw& a, const TreeDraw& b) {
        return a.distance < b.distance || (a.distance == b.distance && a.index < b.index);
    });
    return order;
}

void Viewport::bakeImpostors(const std::vector<TreeDraw>& order) {
    // A few pictures a frame, so that a forest coming into view does not stall one frame; the
    // trees still waiting are drawn with their coarsest mesh meanwhile.
    constexpr std::size_t kBakesPerFrame = 24;
    std::size_t baked = 0;
    mImpostorsWanted = 0;
    const Impostors::DrawMesh draw = [this](const mesh::Mesh& m, const glm::mat4& viewProj,
                                            const glm::vec3& eye, const glm::vec3& light) {
        MeshUniforms u;
        u.viewProj = viewProj;
        u.eye = eye;
        u.light = light;
        setMeshUniforms(u);
        glActiveTexture(GL_TEXTURE0);
        const std::size_t triangles = mDrawnTriangles;
        drawTreeMesh(m, glm::mat4(1.0f), 0.0f);
        mDrawnTriangles = triangles;
    };
    const glm::ivec4 viewport(0, 0, int(std::lround(width() * devicePixelRatioF())),
                              int(std::lround(height() * devicePixelRatioF())));
    for (const TreeDraw& d : order) {
        const ViewTree& t = mTrees[d.index];
        if (d.level != ViewLod::kImpostorLevel || mImpostors.has(t.mesh.get())) continue;
        if (baked == kBakesPerFrame) {
            ++mImpostorsWanted;
            continue;
        }
        mImpostors.bake(t.mesh, draw, defaultFramebufferObject(), viewport);
        ++baked;
    }
    glBindVertexArray(0);
    if (mImpostorsWanted > 0) update(); // the next frame takes the next ones
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
        stamp = mMeshUniformsStamp;
    }
    return program;
}

void Viewport::drawRanges(const std::vector<DrawRange>& ranges) {
    for (const DrawRange& r : ranges) {
        QOpenGLShaderProgram& program =
            useMeshProgram((r.texture != 0 ? kMeshTextured : 0) | (r.alphaTest ? kMeshCutout : 0));
        setUniform(program, "uAlbedo", r.color);
        glBindTexture(GL_TEXTURE_2D, r.texture);
        if (r.twoSided || !mCullBackFaces)
            glDisable(GL_CULL_FACE);
        else
            glEnable(GL_CULL_FACE);
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
