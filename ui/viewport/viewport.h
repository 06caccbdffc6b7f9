#pragma once

#include <array>
#include <cstdint>
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <QElapsedTimer>
#include <QImage>
#include <QOpenGLFunctions_3_3_Core>
#include <QPoint>
#include <QRect>
#include <QSet>
#include <QString>
#include <QStringList>
#include <QSurfaceFormat>
#include <QWidget>

#include <glm/glm.hpp>

#include "engine/wind/windmodel.h"
#include "ui/generation/vertexdata.h"
#include "ui/viewport/backgroundpass.h"
#include "ui/viewport/drawlist.h"
#include "ui/viewport/grid.h"
#include "ui/viewport/impostors.h"
#include "ui/viewport/orbitcamera.h"
#include "ui/viewport/overlays.h"
#include "ui/viewport/picking.h"
#include "ui/viewport/reducedtarget.h"
#include "ui/viewport/treebuffers.h"
#include "ui/viewport/treepass.h"
#include "ui/viewport/viewlod.h"
#include "ui/viewport/viewportsurface.h"
#include "ui/viewport/viewtree.h"
#include "ui/viewport/windclock.h"

class QOpenGLContext;
class QOpenGLShaderProgram;
class QTimer;

namespace sylva::mesh {
struct Mesh;
}
namespace sylva::skel {
struct Skeleton;
}

namespace sylva::ui {

/// What a tool (ui/viewport/toolcontroller.h) gets from the viewport. press() returns true
/// when the tool takes the drag (the camera then does not move); move() and release() follow
/// for that drag only. click() comes for a press and release of the left button that did not
/// move more than a few pixels and was not taken as a drag. key() returns true when used.
class ViewportTool {
public:
    virtual ~ViewportTool() = default;
    virtual bool press(QMouseEvent* event) = 0;
    virtual void move(QMouseEvent* event) = 0;
    virtual void release(QMouseEvent* event) = 0;
    virtual void click(QMouseEvent* event) = 0;
    virtual bool key(QKeyEvent* event) = 0;
};

/// The 3D view: draws a mesh (bark and leaf submeshes) over a gradient background and a ground
/// grid with OpenGL 3.3 core, and lets the user orbit (left drag), pan (right or middle drag,
/// or Shift + left drag), zoom (wheel) and frame the tree (F).
///
/// A widget that holds a native OpenGL window (QOpenGLWindow in a window container) rather
/// than a QOpenGLWidget: a QOpenGLWidget makes Qt compose the whole main window with OpenGL
/// on every repaint of any widget in it, which under a software renderer costs more than
/// drawing an empty view (docs/perf/editor.md). The window passes its mouse, wheel and key
/// events to this widget, so tools, tests and event filters see the widget as before, and
/// keyboard focus and shortcuts stay with the widgets. The OpenGL calls below (update(),
/// makeCurrent(), grabFramebuffer() …) keep QOpenGLWidget's names.
///
/// This class holds the scene, the camera, input and the frame's order; its jobs live beside
/// it: the native window and surface format (viewportsurface), the GLSL (shaders/, loaded by
/// shaderprogram), the GPU buffers and textures (treebuffers), what to draw at which level
/// (drawlist, pure), the frame's passes in their order (backgroundpass, grid, treepass over
/// meshpass and impostors, overlays with the rubber band), the wind clock (windclock), the
/// impostors' baking (impostors), the reduced-resolution target.
class Viewport : public QWidget, protected QOpenGLFunctions_3_3_Core {
    Q_OBJECT

public:
    /// Requests an OpenGL 3.3 core profile with depth and 4x multisampling for every context,
    /// and frames drawn as soon as the event loop is idle (QT_QPA_UPDATE_IDLE_TIME=0 unless
    /// set). Call before constructing QApplication.
    static void installDefaultSurfaceFormat();
    /// Edit ▸ Preferences' multisampling (QSettings "viewport/samples"): kAutoSamples, 0, 2, 4
    /// or 8 samples a pixel. Automatic is 4 on a GPU and none on a software renderer (Mesa
    /// llvmpipe draws a frame 2-3 times faster without it, docs/perf/editor.md).
    static constexpr int kAutoSamples = ViewportSurface::kAutoSamples;
    static int samplesPreference();
    static void setSamplesPreference(int samples);
    /// Puts the preference (or SYLVA_MSAA, which wins) into the default surface format that
    /// new viewports take; automatic asks the driver which renderer it is. Call after
    /// QApplication is made and named, before the first viewport. Returns the samples set.
    static int applySamplesPreference();

    explicit Viewport(QWidget* parent = nullptr);
    ~Viewport() override;

    /// Shows \p mesh (nullptr clears the view) in its materials' colours. With \p frame the
    /// camera frames its bounds. \p vertices: the mesh's vertices as interleaveVertices()
    /// makes them (ui/generation/vertexdata.h), when the caller made them on a worker; else the
    /// viewport makes them when it uploads.
    /// \p skeleton: what the mesh was made from, which gives it wind data (null: it stands
    /// still in the wind).
    void setMesh(std::shared_ptr<const mesh::Mesh> mesh, bool frame = true,
                 std::shared_ptr<const std::vector<ViewVertex>> vertices = nullptr,
                 std::shared_ptr<const skel::Skeleton> skeleton = nullptr);
    /// Colours the mesh per vertex (linear RGB, one per vertex, e.g. attributeColors()), or by
    /// its materials again when \p colors is empty or does not match the mesh.
    void setVertexColors(std::vector<glm::vec3> colors);
    bool usesVertexColors() const {
        return !mVertexColors.empty() && mVertexColors.size() == vertexCount();
    }
    const std::shared_ptr<const mesh::Mesh>& mesh() const { return mMesh; }

    /// Draws each tree of a forest separately (beside the mesh of setMesh(), which then holds
    /// the obstacles). A mesh already on the GPU (the same pointer as before: the tree did not
    /// change) is not uploaded again. With \p frame the camera frames everything.
    void setTrees(std::vector<ViewTree> trees, bool frame = false);
    const std::vector<ViewTree>& trees() const { return mTrees; }
    /// Trees drawn highlighted (the selection) and trees not drawn (hidden in the outliner).
    void setHighlightedTrees(const QSet<std::uint32_t>& ids);
    void setHiddenTrees(const QSet<std::uint32_t>& ids);
    /// Trees of a tool's preview (a brush stroke), drawn highlighted until cleared.
    void setPreviewTrees(std::vector<ViewTree> trees);
    /// Moves tree \p index to \p transform on screen only (a drag's live preview; the next
    /// setTrees() puts back what the document holds).
    void setTreeTransform(std::size_t index, const glm::mat4& transform);
    /// World boxes of the trees, in the order of trees().
    const std::vector<Bounds>& treeBounds() const { return mTreeBounds; }

    /// The ray through a point of the widget (logical pixels), from the eye.
    Ray rayAt(const QPointF& pos) const;
    /// Where a world point is drawn, in widget pixels; none when behind the camera or outside.
    std::optional<QPointF> project(const glm::vec3& world) const;
    /// The index into trees() of the tree drawn at \p pos (its own triangles), or -1.
    int treeAt(const QPointF& pos) const { return pickAt(pos).index; }
    /// The same with the hit's distance from the eye (metres along rayAt(pos)).
    TreeHit pickAt(const QPointF& pos) const;
    /// Frames a box (the selection): the camera aims at it and backs off until it fits.
    void frameBox(const glm::vec3& lo, const glm::vec3& hi);

    void setTool(ViewportTool* tool) { mTool = tool; }
    /// Lines drawn over the scene at every paint (a tool's handles), asked for at each paint.
    void setOverlay(std::function<std::vector<OverlayLine>()> provider) {
        mOverlay = std::move(provider);
        update();
    }
    /// A rubber band (widget pixels) drawn over the scene; an empty rectangle removes it.
    void setBand(const QRect& band);
    QRect band() const { return mBand; }
    const QSet<std::uint32_t>& highlightedTrees() const { return mHighlighted; }
    /// Meshes uploaded to the GPU since construction (for tests: unchanged trees are not).
    std::size_t uploads() const { return mUploads; }
    /// Coarser levels of detail uploaded (ui/viewport/viewlod.h), not counted in uploads().
    std::size_t levelUploads() const { return mLevelUploads; }
    /// Trees drawn in the last frame: those whose box is outside the view are skipped.
    std::size_t drawnTrees() const { return mStats.trees; }
    /// Trees the last frame drew at their motion level (the view was moving).
    std::size_t drawnMotion() const { return mStats.motion; }

    /// Triangles drawn in the last frame (trees at their level of detail, obstacles, terrain).
    std::size_t drawnTriangles() const { return mStats.triangles; }
    /// Trees drawn at each level of detail in the last frame (0 = full).
    const std::array<std::size_t, ViewLod::kLevels>& drawnPerLevel() const {
        return mStats.perLevel;
    }
    /// Triangles the last frame's trees drew at each level of detail (impostors: 2 each).
    const std::array<std::size_t, ViewLod::kLevels>& drawnTrianglesPerLevel() const {
        return mStats.trianglesPerLevel;
    }
    /// The height on screen (pixels) under which tree \p index is drawn as its impostor: where
    /// its baked atlas matches its mesh (Impostors::switchHeightPx()); negative while none is
    /// baked. Impostors that switch later than the default: impostorsSwitchedLater().
    double impostorSwitchPx(std::size_t index) const {
        return index < mTrees.size() ? mImpostors.switchHeightPx(Impostors::keyOf(mTrees[index]))
                                     : -1.0;
    }
    std::size_t impostorsSwitchedLater() const { return mImpostors.switchedLater(); }
    /// Instanced draw calls the last frame's impostors took (one per atlas in view).
    std::size_t impostorDrawCalls() const { return mStats.impostorDrawCalls; }
    /// Instanced draw calls the last frame's variant instances took (one per variant level in
    /// view and material), and the tree meshes on the GPU (one buffer set each: a variant's
    /// levels once, whatever its instances).
    std::size_t instancedDrawCalls() const { return mStats.instancedDrawCalls; }
    /// What the last frame drew, nearest first, with the levels (ui/viewport/drawlist.h).
    const std::vector<TreeDraw>& lastDrawList() const { return mLastDrawList; }
    std::size_t gpuTreeMeshes() const { return mBuffers.treeMeshCount(); }
    /// The distance level of detail (ui/viewport/viewlod.h).
    ViewLod& lod() { return *mLod; }
    /// Trees whose coarser levels or impostor are still to be made (0: the view is final).
    /// (As of the last frame: draw one after the view changed.)
    std::size_t lodPending() const {
        return mLod->pending() + mImpostors.wanted() + mImpostors.baking();
    }

    /// Milliseconds the last upload of setMesh()'s mesh took (vertices, indices, textures;
    /// its wind data only with View ▸ Wind on), and the last frame's paintGL (upload included).
    double lastUploadMs() const { return mLastUploadMs; }
    double lastPaintMs() const { return mLastPaintMs; }
    /// Milliseconds from the end of the last frame's paintGL to its swap done (frameSwapped):
    /// the window system's part of putting the frame on screen.
    double lastPresentMs() const { return mLastPresentMs; }
    /// Frames painted since the viewport was made (tests count the repaints an edit causes).
    std::size_t framesPainted() const { return mFramesPainted; }
    /// The mesh setMesh() gave (none after a failed preview).
    const std::shared_ptr<const mesh::Mesh>& shownMesh() const { return mMesh; }
    OrbitCamera& camera() { return mCamera; }
    const OrbitCamera& camera() const { return mCamera; }
    /// Aims the camera at the mesh's bounds (or the unit box around the origin when empty).
    /// Forgets a view set by setViewFrom().
    void frameScene();
    /// Shows the next meshes from \p eye towards \p target (a project's camera) instead of
    /// framing them; the zoom limits still follow the framed bounds. frameScene() (F) goes back
    /// to framing.
    void setViewFrom(const glm::vec3& eye, const glm::vec3& target);
    void clearViewFrom() { mViewFrom = false; }

    void setGridVisible(bool visible);
    bool isGridVisible() const { return mGridVisible; }

    /// View ▸ Wind: trees with wind data (a skeleton and node ids) sway on the GPU by the
    /// engine's wind model (ui/viewport/shaders/wind.glsl, docs/wind.md), each tree its
    /// windPhase later in the loop; the view then draws frames continuously while the wind
    /// clock runs. Impostors stand still. Off: the picture is the one without wind.
    void setWindEnabled(bool on);
    bool windEnabled() const { return mWind->enabled(); }
    /// The wind the trees sway in (the project's; the engine's default until set).
    void setWind(const wind::WindSettings& settings);
    const wind::WindSettings& wind() const { return mWind->settings(); }
    /// Freezes the wind clock at \p seconds (scripts, tests and pictures: the same time gives
    /// the same frame), or lets it run with the wall clock again (nullopt).
    void setWindTime(std::optional<double> seconds);
    /// The wind clock now, in seconds.
    double windTime() const { return mWind->time(); }
    /// Triangles drawn swaying in the last frame.
    std::size_t drawnWindTriangles() const { return mStats.windTriangles; }

    /// Culls the back faces of Sylva's bark tubes (on by default; DrawRange::twoSided says
    /// what never is). Off only for comparisons: the picture is the same.
    void setBackFaceCulling(bool on) {
        mTreePass.meshes().setBackFaceCulling(on);
        update();
    }
    bool backFaceCulling() const { return mTreePass.meshes().backFaceCulling(); }

    /// While the view moves (the camera or a dragged tree changed since the last frame) a
    /// software renderer draws the scene at this fraction of the resolution and scales it up;
    /// a sharp frame follows when the view rests (kSharpAfterMs). 1 on a graphics card, with
    /// multisampling, or with SYLVA_MOTION_SCALE=1 (0.25 to 1; kSoftwareMotionScale otherwise).
    float motionScale() const { return mMotionScale; }
    static constexpr int kSharpAfterMs = 250;
    /// The moving frames' resolution under a software renderer (motionScale()).
    static constexpr float kSoftwareMotionScale = 0.4f;
    /// While the view moves under a software renderer, every tree picks its level and the
    /// impostor's switch as if the target were this many times smaller still, drawn by the
    /// impostors' one-fetch cards (Impostors::begin's moving), but a tree higher than
    /// kMaxMovingImpostorPx on the target stays its coarsest mesh (an atlas view magnified
    /// further reads as blocks, bare crowns as blobs; 1.2 cells: 27-33 fps, 1.5: the alder
    /// demo's bare crowns blotted). With kSoftwareMotionScale that brings the 1,000-tree
    /// benchmark to about 30 fps (27-36, docs/perf/lods.md); the sharp frame at rest draws the
    /// levels the window's pixels ask for.
    static constexpr double kMotionLodBias = 1.5;
    static constexpr double kMaxMovingImpostorPx = 1.35 * Impostors::kCell;
    /// The viewport's image at full resolution (for screenshots), whether the view moves.
    QImage grabSharp();
    /// Whether the last frame was drawn at the reduced resolution.
    bool lastFrameReduced() const { return mLastReduced; }

    /// Renderer and version as reported by the driver, empty before initializeGL().
    QString glInfo() const { return mGlInfo; }
    /// Why rendering is not possible (no 3.3 context, a shader failed), empty when fine.
    QString glError() const { return mGlError; }
    /// Why texture files were drawn without their texture (unreadable, or larger than
    /// kMaxTexturePixels), one line each, in the order they were met; each is also emitted as
    /// warning().
    QStringList textureProblems() const { return mBuffers.textureProblems(); }

    QSize sizeHint() const override { return {960, 720}; }

    /// Schedules a frame of the OpenGL window (hides QWidget::update, which would repaint
    /// only the container).
    void update();
    /// Makes the view's context current on its window (for GL work outside paintGL()).
    void makeCurrent();
    void doneCurrent();
    /// The view's context, null until the window was first shown.
    QOpenGLContext* context() const;
    /// The framebuffer paintGL() draws into.
    GLuint defaultFramebufferObject() const;
    /// Draws a frame and reads it back (without showing it), as QOpenGLWidget's does.
    QImage grabFramebuffer();
    /// The surface format asked for (set before the view is first shown).
    QSurfaceFormat format() const;
    void setFormat(const QSurfaceFormat& format);
    /// The native window the view draws into (for screenshots of the whole main window).
    QWindow* surface() const;

Q_SIGNALS:
    void cameraChanged();
    /// A frame is on screen.
    void frameSwapped();
    /// Something the user should know about the picture (a texture drawn without its file);
    /// emitted once per file, after the frame that met it.
    void warning(const QString& text);

protected:
    void initializeGL();
    void resizeGL(int width, int height);
    void paintGL();
    bool event(QEvent* event) override;

    void mousePressEvent(QMouseEvent* event) override;
    void mouseMoveEvent(QMouseEvent* event) override;
    void mouseReleaseEvent(QMouseEvent* event) override;
    void wheelEvent(QWheelEvent* event) override;
    void keyPressEvent(QKeyEvent* event) override;

private:
    /// Whether levels that just arrived change what the last frame drew: a tree it drew at a
    /// coarser level than its full mesh (or as an impostor) now has that level.
    bool levelsChangeView() const;
    enum class DragMode { None, Orbit, Pan };

    void releaseGl();
    void applyFrame();
    void uploadMesh();
    float aspect() const;

    std::size_t vertexCount() const;

    std::shared_ptr<const mesh::Mesh> mMesh;
    std::shared_ptr<const std::vector<ViewVertex>> mMeshVertices; ///< made on a worker, or none
    std::shared_ptr<const skel::Skeleton> mMeshSkeleton;          ///< the mesh's, or none
    std::vector<glm::vec3> mVertexColors;
    glm::vec3 mBoundsLo{-0.5f, 0.0f, -0.5f};
    glm::vec3 mBoundsHi{0.5f, 1.0f, 0.5f};
    OrbitCamera mCamera;
    bool mMeshDirty = false;
    bool mAutoFramed = true;
    bool mViewFrom = false; ///< applyFrame() looks from mViewEye at mViewTarget
    glm::vec3 mViewEye{0.0f}, mViewTarget{0.0f};
    bool mGridVisible = true;

    DragMode mDrag = DragMode::None;
    QPoint mLastMouse;

    ViewportSurface* mSurface = nullptr;
    bool mSoftware = false; ///< a software renderer (Mesa llvmpipe …)
    QRect mBand;
    bool mGlReady = false;
    QString mGlInfo;
    QString mGlError;
    std::unique_ptr<QOpenGLShaderProgram> mLineProgram; ///< the grid's and the overlays'
    TreeBuffers mBuffers;
    // The frame's passes, in their order.
    BackgroundPass mBackground;
    Grid mGrid;
    TreePass mTreePass;
    Overlays mOverlays;
    DrawStats mStats; ///< the last frame's

    void syncTreeBuffers();
    /// The trees to draw this frame, nearest first, with their levels (ui/viewport/drawlist.h).
    std::vector<TreeDraw> treesToDraw(const glm::mat4& viewProj) const;
    /// Tree \p index is hidden by its check box in the outliner (picking and drawing skip it).
    bool isHidden(std::size_t index) const {
        return mTrees[index].id != 0 && mHidden.contains(mTrees[index].id);
    }
    double mLastUploadMs = 0.0;
    double mLastPaintMs = 0.0;
    double mLastPresentMs = 0.0;
    QElapsedTimer mPaintStart; ///< the last paintGL's start
    std::size_t mFramesPainted = 0;
    WindClock* mWind = nullptr; ///< a child
    void updateBounds();
    std::vector<ViewTree> mTrees;
    std::vector<ViewTree> mPreview;
    std::vector<Bounds> mTreeBounds;
    ViewportTool* mTool = nullptr;
    std::function<std::vector<OverlayLine>()> mOverlay;
    bool mToolDrag = false;
    QPoint mPressPos;
    bool mMovedSincePress = false;
    bool mTreesDirty = false;
    QSet<std::uint32_t> mHighlighted, mHidden;
    std::size_t mUploads = 0;
    std::size_t mLevelUploads = 0;
    // Reduced resolution while the view moves (motionScale()).
    float mMotionScale = 1.0f;
    int mSamples = 0; ///< multisampling of the widget's framebuffer, as requested
    bool mLastReduced = false;
    bool mSharpNext = false;
    glm::mat4 mLastViewProj{0.0f};
    bool mTransformsMoved = false;
    QTimer* mSharpTimer = nullptr;
    ReducedTarget mReduced;
    std::vector<TreeDraw> mLastDrawList;
    ViewLod* mLod = nullptr; ///< a child
    Impostors mImpostors;
};

} // namespace sylva::ui
