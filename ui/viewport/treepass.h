#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

#include <QOpenGLFunctions_3_3_Core>
#include <QSet>
#include <QString>

#include <glm/glm.hpp>

#include "ui/viewport/drawlist.h"
#include "ui/viewport/meshpass.h"
#include "ui/viewport/viewlod.h"
#include "ui/viewport/viewtree.h"

namespace sylva::ui {

class Impostors;
class TreeBuffers;
class WindClock;

/// What a viewport frame drew (View ▸ Statistics, the tests and the perf gate read it).
struct DrawStats {
    std::size_t trees = 0;         ///< trees in view (drawn at any level)
    std::size_t triangles = 0;     ///< trees, obstacles, terrain, impostor cards (2 each)
    std::size_t windTriangles = 0; ///< drawn swaying
    std::size_t motion = 0;        ///< trees drawn at their motion level
    std::size_t impostorDrawCalls = 0;
    std::size_t instancedDrawCalls = 0;
    std::array<std::size_t, ViewLod::kLevels> perLevel{};          ///< trees, 0 = full
    std::array<std::size_t, ViewLod::kLevels> trianglesPerLevel{}; ///< impostors: 2 each
};

/// One frame's view as the trees pass draws it.
struct TreeFrame {
    glm::mat4 viewProj{1.0f};
    glm::vec3 eye{0.0f};
    glm::vec3 light{0.0f, 1.0f, 0.0f}; ///< the camera's key light (impostorlighting.h)
    /// The pixels a unit at distance 1 spans on the target drawn into (Impostors::begin()).
    float pixelsPerUnit = 1.0f;
    /// Drawn at the reduced resolution while the view moves: the trees' motion levels.
    bool reduced = false;
};

/// The scene's pass of a viewport frame: the scene mesh (obstacles, terrain or a species'
/// tree), then the trees of the draw list nearest first at their levels (a unique tree's
/// ViewLod level, an instance's variant level, instances grouped into instanced calls), the
/// preview trees of a tool, and the impostor cards. With the wind clock active it makes the
/// frame's element rotations of every swaying mesh once and uploads them in one buffer before
/// the first draw (a buffer changed between draws would stall the renderer).
class TreePass {
public:
    /// Builds the mesh shader's variants (MeshPass); false (and \p error) when one fails.
    bool initialize(QOpenGLFunctions_3_3_Core* gl, TreeBuffers* buffers, ViewLod* lod,
                    Impostors* impostors, const WindClock* wind, bool software, QString& error);
    void release() { mMeshes.release(); }
    MeshPass& meshes() { return mMeshes; }
    const MeshPass& meshes() const { return mMeshes; }

    /// Draws \p order (what the draw list chose for \p trees) and \p preview; trees whose id
    /// is in \p highlighted are drawn highlighted. Returns what was drawn.
    DrawStats draw(const TreeFrame& frame, const std::vector<ViewTree>& trees,
                   const std::vector<ViewTree>& preview, const std::vector<TreeDraw>& order,
                   const QSet<std::uint32_t>& highlighted);

private:
    /// What a tree of the draw list draws this frame.
    struct Drawn {
        const TreeDraw* draw = nullptr;
        const mesh::Mesh* mesh = nullptr; ///< null: an impostor card
        int windBase = -1;                ///< its rotations in the frame's buffer
    };
    std::vector<Drawn> chooseMeshes(const std::vector<ViewTree>& trees,
                                    const std::vector<TreeDraw>& order, bool reduced,
                                    DrawStats& stats) const;
    void drawCards(const TreeFrame& frame, const std::vector<ViewTree>& trees,
                   const std::vector<const TreeDraw*>& cards,
                   const QSet<std::uint32_t>& highlighted, DrawStats& stats);

    QOpenGLFunctions_3_3_Core* mGl = nullptr;
    TreeBuffers* mBuffers = nullptr;
    ViewLod* mLod = nullptr;
    Impostors* mImpostors = nullptr;
    const WindClock* mWind = nullptr;
    MeshPass mMeshes;
    std::vector<glm::vec4> mWindRotations; ///< the frame's, kept for its capacity
};

} // namespace sylva::ui
