#pragma once

#include <array>
#include <atomic>
#include <cstddef>
#include <cstdint>
#include <map>
#include <memory>
#include <set>
#include <vector>

#include <QFutureWatcher>
#include <QObject>
#include <QThreadPool>

#include <glm/glm.hpp>

#include "ui/generation/treelodsource.h"

namespace sylva::mesh {
struct Mesh;
}

namespace sylva::ui {

/// The viewport's distance level of detail (issue 18). Each tree gets kLevels levels: level 0
/// is the mesh the generation made; the levels up to kImpostorLevel are made by the engine's
/// silhouette-keeping camera LOD (mesh::buildTreeMesh with a camera distance) for a tree seen
/// smaller and smaller on screen, on a worker thread, once per mesh (a tree that did not change
/// keeps its levels); the last is an impostor.
/// The viewport picks a level per tree and frame from the tree's projected height
/// (levelFor()); picking and the selection still use the full mesh.
class ViewLod : public QObject {
    Q_OBJECT

public:
    static constexpr int kLevels = 4;
    /// The farthest level is no mesh but the baked octahedral impostor (ui/viewport/impostors.h),
    /// which the viewport bakes from the level below it (meshFor() gives that level).
    static constexpr int kImpostorLevel = kLevels - 1;
    /// The camera distance, in tree heights, for which level \p level (1..kLevels-1) is built,
    /// at the LOD's reference view (1080 px high, 60° field of view): the tree then spans
    /// about 935 / levelHeights(level) pixels.
    static double levelHeights(int level);
    /// The level to draw for a tree seen as small as the reference view shows it from
    /// \p equivalentHeights tree heights away (see equivalentHeights()): the coarsest level
    /// built for no more than that distance.
    static int levelFor(double equivalentHeights);
    /// The height on screen (pixels, on any viewport) under which a tree is drawn as its
    /// impostor: about 94 px.
    static double impostorHeightPx();
    /// How far, in tree heights, the reference view would be from a tree \p worldHeight metres
    /// high to show it as large as a camera \p distance metres away with a vertical field of
    /// view \p fovY (radians) shows it on a viewport \p viewportHeightPx pixels high.
    static double equivalentHeights(double distance, double worldHeight, double fovY,
                                    double viewportHeightPx);
    /// The pixels a tree \p worldHeight metres high spans, \p distance metres away, with a
    /// vertical field of view \p fovY (radians) on a viewport \p viewportHeightPx pixels high.
    static double heightOnScreenPx(double distance, double worldHeight, double fovY,
                                   double viewportHeightPx);

    explicit ViewLod(QObject* parent = nullptr);
    ~ViewLod() override;

    /// Off: every tree is drawn at full detail and nothing is built (SYLVA_VIEW_LOD=0 too).
    void setEnabled(bool enabled);
    bool isEnabled() const { return mEnabled; }

    /// The trees now in the view, by their full mesh and source: levels of meshes no longer
    /// listed are dropped, those of new meshes are scheduled in the order given.
    void
    setTrees(const std::vector<std::pair<std::shared_ptr<const mesh::Mesh>, TreeLodSource>>& trees);

    /// The mesh to draw for the tree whose full mesh is \p full at \p level: the coarsest built
    /// level not above \p level, else \p full itself; \p used (when given) gets its level.
    /// \p moving (a frame drawn while the view moves, under a software renderer): the tree's
    /// motion level instead when it has fewer triangles; \p usedMotion (when given) says so.
    const mesh::Mesh* meshFor(const mesh::Mesh* full, int level, int* used = nullptr,
                              bool moving = false, bool* usedMotion = nullptr) const;
    /// How much farther than its own finest level a tree's motion level is made: while the view
    /// moves, a software renderer draws every tree as if it were this many times as far (the
    /// sharp frame at rest draws the levels above).
    static constexpr double kMotionFactor = 3.0;
    /// The coarsest built level of \p full not above \p level (1..), shared; null when none.
    std::shared_ptr<const mesh::Mesh> levelMesh(const mesh::Mesh* full, int level) const;
    /// Every distinct mesh of every level (for the GPU buffers).
    std::vector<std::shared_ptr<const mesh::Mesh>> allLevelMeshes() const;
    /// The coarser levels (and motion level) made for the tree whose full mesh is \p full.
    std::vector<std::shared_ptr<const mesh::Mesh>> levelMeshesOf(const mesh::Mesh* full) const;

    /// Trees whose levels are still being made.
    std::size_t pending() const { return mQueue.size() + (mRunning ? mRunningCount : 0); }

Q_SIGNALS:
    /// New levels are ready (emitted on the GUI thread, once the queue is done): the viewport
    /// uploads and repaints.
    void levelsReady();

private:
    struct Job {
        std::shared_ptr<const mesh::Mesh> full;
        TreeLodSource source;
    };
    struct Built {
        const mesh::Mesh* full = nullptr;
        std::array<std::shared_ptr<const mesh::Mesh>, kLevels> levels;
        std::shared_ptr<const mesh::Mesh> motion; ///< drawn while the view moves, if made
    };
    void startNext();
    void finished();

    bool mEnabled = true;
    std::map<const mesh::Mesh*, Built> mLevels; ///< keyed by the full mesh
    std::map<const mesh::Mesh*, std::shared_ptr<const mesh::Mesh>> mAlive; ///< full meshes listed
    std::vector<Job> mQueue;
    bool mRunning = false;
    bool mReady = false; ///< levels arrived since the last levelsReady()
    std::size_t mRunningCount = 0;
    std::set<const mesh::Mesh*> mRunningKeys;
    std::vector<std::pair<std::shared_ptr<const mesh::Mesh>, TreeLodSource>> mListed;
    std::shared_ptr<std::atomic<bool>> mCancel;
    QThreadPool mPool; ///< one thread, niced
    QFutureWatcher<std::vector<Built>> mWatcher;
};

} // namespace sylva::ui
