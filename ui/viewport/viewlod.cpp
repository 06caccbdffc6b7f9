#include "ui/viewport/viewlod.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include <QtConcurrent/QtConcurrentRun>

#include <sys/resource.h>
#include <sys/syscall.h>
#include <unistd.h>

#include "engine/mesh/impostor.h"
#include "engine/mesh/mesh.h"
#include "engine/mesh/treemesh.h"

namespace sylva::ui {

namespace {

// Reference view of mesh::LodSettings' pixel thresholds.
constexpr double kReferenceHeightPx = 1080.0;
constexpr double kReferenceFovY = 60.0 * 3.14159265358979323846 / 180.0;

// Levels 1.. are made for a tree this many of its heights away (it then spans about 935 /
// heights pixels of the reference view: 375, 155 and 94: the impostor), with rings of this
// many vertices.
constexpr double kLevelHeights[ViewLod::kLevels] = {0.0, 2.5, 6.0, 10.0};
// A level is made only where it is at least this much farther than the distance the project's
// camera LOD already made the full mesh for (closer, it would hardly be coarser).
constexpr double kReuseFactor = 1.25;
constexpr int kLevelResolution[ViewLod::kLevels] = {0, 6, 4, 3};
// Trees handed to the worker at a time: levels show up while the rest are still made.
constexpr std::size_t kChunk = 8;

// Level \p level of a tree: the engine's camera LOD for the level's distance. Its first band
// is the species' own, the second the level's resolution from just past 0 m, so every level
// uses the pixel thresholds at its distance whatever the species' bands are.
std::shared_ptr<const mesh::Mesh> buildLevel(const TreeLodSource& source, double distance,
                                             int resolution) {
    mesh::TreeMeshSettings settings = *source.settings;
    const int base = settings.lod.bands.empty() ? 8 : settings.lod.bands.front().resolution;
    settings.lod.bands = {{0.0, base, 1.0}, {1e-3, std::min(base, resolution), 1.0}};
    settings.lod.screenHeightPx = kReferenceHeightPx;
    settings.lod.fovYDegrees = 60.0;
    settings.useLod = true;
    settings.cameraDistance = distance;
    settings.hasCamera = false;
    settings.acceptLeafCard = {};
    return std::make_shared<const mesh::Mesh>(mesh::buildTreeMesh(*source.skeleton, settings));
}

} // namespace

double ViewLod::levelHeights(int level) {
    return level > 0 && level < kLevels ? kLevelHeights[level] : 0.0;
}

namespace {
// Where the impostor takes over, in tree heights away at the reference view
// (SYLVA_IMPOSTOR_HEIGHTS for comparisons).
double impostorHeights() {
    static const double at = qEnvironmentVariableIsSet("SYLVA_IMPOSTOR_HEIGHTS")
                                 ? qEnvironmentVariable("SYLVA_IMPOSTOR_HEIGHTS").toDouble()
                                 : kLevelHeights[ViewLod::kImpostorLevel];
    return at;
}
} // namespace

double ViewLod::impostorHeightPx() {
    // A tree spans reference / (2 tan(ref / 2)) / heights pixels at the reference view, and
    // equivalentHeights() maps every view's pixels onto it one to one.
    return kReferenceHeightPx / (2.0 * std::tan(0.5 * kReferenceFovY)) /
           std::max(impostorHeights(), 1e-6);
}

int ViewLod::levelFor(double equivalentHeights) {
    const double impostorAt = impostorHeights();
    int level = 0;
    for (int k = 1; k < kImpostorLevel; ++k)
        if (equivalentHeights >= kLevelHeights[k]) level = k;
    if (equivalentHeights >= impostorAt) level = kImpostorLevel;
    return level;
}

double ViewLod::heightOnScreenPx(double distance, double worldHeight, double fovY,
                                 double viewportHeightPx) {
    return worldHeight * viewportHeightPx / (2.0 * std::max(distance, 1e-6) * std::tan(0.5 * fovY));
}

double ViewLod::equivalentHeights(double distance, double worldHeight, double fovY,
                                  double viewportHeightPx) {
    if (worldHeight <= 1e-6 || viewportHeightPx <= 0.0) return 0.0;
    // Projected height in pixels: worldHeight / (2 d tan(fov/2)) · viewport; the reference view
    // shows it that large from d' = d · (reference / viewport) · tan(fov/2) / tan(ref/2).
    const double scale = (kReferenceHeightPx / viewportHeightPx) *
                         (std::tan(0.5 * fovY) / std::tan(0.5 * kReferenceFovY));
    return distance * scale / worldHeight;
}

ViewLod::ViewLod(QObject* parent) : QObject(parent) {
    mPool.setMaxThreadCount(1);
    mEnabled = qEnvironmentVariableIsSet("SYLVA_VIEW_LOD")
                   ? qEnvironmentVariableIntValue("SYLVA_VIEW_LOD") != 0
                   : true;
    connect(&mWatcher, &QFutureWatcher<std::vector<Built>>::finished, this, &ViewLod::finished);
}

ViewLod::~ViewLod() {
    if (mCancel) mCancel->store(true);
    mWatcher.waitForFinished();
}

void ViewLod::setEnabled(bool enabled) {
    if (enabled == mEnabled) return;
    mEnabled = enabled;
    mQueue.clear();
    mLevels.clear();
    if (enabled) setTrees(mListed); // made again for the trees last listed
    Q_EMIT levelsReady();
}

void ViewLod::setTrees(
    const std::vector<std::pair<std::shared_ptr<const mesh::Mesh>, TreeLodSource>>& trees) {
    std::map<const mesh::Mesh*, std::shared_ptr<const mesh::Mesh>> alive;
    std::vector<Job> queue;
    for (const auto& [full, source] : trees) {
        if (!full || alive.count(full.get())) continue;
        alive.emplace(full.get(), full);
        // Instances draw their variant's levels, made once per variant by the forest.
        if (!mEnabled || !source.skeleton || !source.settings || source.instance) continue;
        if (mLevels.count(full.get()) || mRunningKeys.count(full.get())) continue;
        queue.push_back({full, source});
    }
    // Keep only levels of meshes still drawn (a mesh's address is only reused once it is freed,
    // and mAlive holds every listed mesh until the next call).
    for (auto it = mLevels.begin(); it != mLevels.end();)
        it = alive.count(it->first) ? std::next(it) : mLevels.erase(it);
    mAlive = std::move(alive);
    mQueue = std::move(queue);
    mListed = trees;
    if (!mRunning) startNext();
}

void ViewLod::startNext() {
    if (mQueue.empty()) return;
    const std::size_t n = std::min(kChunk, mQueue.size());
    std::vector<Job> chunk(std::make_move_iterator(mQueue.begin()),
                           std::make_move_iterator(mQueue.begin() + std::ptrdiff_t(n)));
    mQueue.erase(mQueue.begin(), mQueue.begin() + std::ptrdiff_t(n));
    mCancel = std::make_shared<std::atomic<bool>>(false);
    mRunning = true;
    mRunningCount = n;
    mRunningKeys.clear();
    for (const Job& job : chunk)
        mRunningKeys.insert(job.full.get());
    mWatcher.setFuture(QtConcurrent::run(&mPool, [chunk = std::move(chunk), cancel = mCancel]() {
        // Behind the generation and the GUI: levels only make a view faster, an edit's new
        // trees are what the user waits for. The pool's one thread keeps this niceness.
        const auto tid = static_cast<id_t>(syscall(SYS_gettid));
        if (getpriority(PRIO_PROCESS, tid) < 10) setpriority(PRIO_PROCESS, tid, 10);
        std::vector<Built> out;
        for (const Job& job : chunk) {
            if (cancel->load()) break;
            Built built;
            built.full = job.full.get();
            built.levels[0] = job.full;
            const double height = std::max(0.1f, mesh::verticalExtent(*job.full));
            for (int k = 1; k < kImpostorLevel; ++k) {
                const double distance = kLevelHeights[k] * height;
                // Not much coarser than what the project's camera LOD already made: reuse.
                if (distance < kReuseFactor * job.source.builtDistance) continue;
                try {
                    auto m = buildLevel(job.source, distance, kLevelResolution[k]);
                    // Keep a level only where it saves triangles worth a buffer.
                    const mesh::Mesh* finer = built.levels[0].get();
                    for (int j = k - 1; j > 0; --j)
                        if (built.levels[std::size_t(j)]) {
                            finer = built.levels[std::size_t(j)].get();
                            break;
                        }
                    if (m->triangleCount() * 10 < finer->triangleCount() * 9)
                        built.levels[std::size_t(k)] = std::move(m);
                } catch (...) {
                    // A level that cannot be made leaves the finer one in its place.
                }
            }
            // The motion level: the camera LOD for kMotionFactor times the distance of the
            // finest mesh drawn at rest (the project camera's, or level 1's), kept only where it
            // saves at least a tenth of the triangles.
            try {
                const double finest = std::max(job.source.builtDistance, kLevelHeights[1] * height);
                auto m = buildLevel(job.source, kMotionFactor * finest, kLevelResolution[2]);
                if (m->triangleCount() * 10 < job.full->triangleCount() * 9)
                    built.motion = std::move(m);
            } catch (...) {
                // Without one the tree moves at its resting level.
            }
            out.push_back(std::move(built));
        }
        return out;
    }));
}

void ViewLod::finished() {
    // A late signal of an earlier future, or one still running.
    if (!mRunning || !mWatcher.future().isFinished()) return;
    mRunning = false;
    mRunningKeys.clear();
    mRunningCount = 0;
    const std::vector<Built> results = mWatcher.result();
    bool any = false;
    for (const Built& b : results) {
        if (!mEnabled || !mAlive.count(b.full)) continue; // dropped meanwhile
        // levels[0] keeps the full mesh alive, so the key stays that mesh while listed.
        mLevels[b.full] = b;
        any = true;
    }
    mReady = mReady || any;
    startNext();
    // One repaint when all are made, not one a chunk: a repaint of a large forest costs the GUI
    // thread as much as a frame, and the user is likely editing meanwhile.
    if (!mRunning && mReady) {
        mReady = false;
        Q_EMIT levelsReady();
    }
}

const mesh::Mesh* ViewLod::meshFor(const mesh::Mesh* full, int level, int* used, bool moving,
                                   bool* usedMotion) const {
    if (used) *used = 0;
    if (usedMotion) *usedMotion = false;
    if ((level <= 0 && !moving) || !mEnabled) return full;
    auto it = mLevels.find(full);
    if (it == mLevels.end()) return full;
    const mesh::Mesh* chosen = full;
    for (int k = std::min(level, kLevels - 1); k > 0; --k)
        if (it->second.levels[std::size_t(k)]) {
            if (used) *used = k;
            chosen = it->second.levels[std::size_t(k)].get();
            break;
        }
    const mesh::Mesh* motion = it->second.motion.get();
    if (moving && motion && motion->triangleCount() < chosen->triangleCount()) {
        if (usedMotion) *usedMotion = true;
        return motion;
    }
    return chosen;
}

std::shared_ptr<const mesh::Mesh> ViewLod::levelMesh(const mesh::Mesh* full, int level) const {
    auto it = mLevels.find(full);
    if (!mEnabled || it == mLevels.end()) return nullptr;
    for (int k = std::min(level, kLevels - 1); k > 0; --k)
        if (it->second.levels[std::size_t(k)]) return it->second.levels[std::size_t(k)];
    return nullptr;
}

std::vector<std::shared_ptr<const mesh::Mesh>> ViewLod::allLevelMeshes() const {
    std::vector<std::shared_ptr<const mesh::Mesh>> out;
    for (const auto& [key, built] : mLevels) {
        for (int k = 1; k < kLevels; ++k)
            if (built.levels[std::size_t(k)]) out.push_back(built.levels[std::size_t(k)]);
        if (built.motion) out.push_back(built.motion);
    }
    return out;
}

std::vector<std::shared_ptr<const mesh::Mesh>>
ViewLod::levelMeshesOf(const mesh::Mesh* full) const {
    std::vector<std::shared_ptr<const mesh::Mesh>> out;
    auto it = mLevels.find(full);
    if (it == mLevels.end()) return out;
    for (int k = 1; k < kLevels; ++k)
        if (it->second.levels[std::size_t(k)]) out.push_back(it->second.levels[std::size_t(k)]);
    if (it->second.motion) out.push_back(it->second.motion);
    return out;
}

} // namespace sylva::ui
