#pragma once

#include <array>
#include <functional>
#include <map>
#include <memory>
#include <vector>

#include <QFuture>
#include <QOpenGLFunctions_3_3_Core>
#include <QString>
#include <QThreadPool>
#include <QTimer>

#include <glm/glm.hpp>

#include "engine/mesh/impostor.h"
#include "engine/mesh/impostorfit.h"

class QOpenGLShaderProgram;

namespace sylva::mesh {
struct Mesh;
}

namespace sylva::ui {

class ViewLod;
struct TreeDraw;
struct ViewTree;

/// The farthest level of the viewport's LOD (ui/viewport/viewlod.h): a tree a few dozen pixels
/// high drawn as one camera-facing card with the engine's baked hemi-octahedral impostor
/// (mesh::bakeImpostor, the same atlas `sylva-cli lods` writes, docs/lods.md): the three atlas
/// views around the view direction blended by an ordered dither (no popping while the view
/// turns), the viewer's ray marched against the chosen view's depth (shaders/impostor.frag),
/// lit like the meshes by the camera's key light, baked into the atlas when it is uploaded
/// (ui/viewport/impostorlighting.h). Atlases are baked on a
/// worker thread (request(); the GUI thread only uploads them, collect()) from a coarse mesh
/// level, and kept per key while a tree draws it: one per variant (its instances and the
/// unique trees of its species it stands in for share it), or one per tree without a variant.
/// It schedules its own baking (schedule(), once a frame): what the frame's trees want, and a
/// frame now and then (setWake()) while atlases bake.
class Impostors {
public:
    Impostors();
    /// The atlas: kGrid × kGrid views of kCell pixels.
    static constexpr int kGrid = 8;
    static constexpr int kCell = 64;
    /// The defines of the one-fetch program (shaders/impostor.frag's FLAT).
    static constexpr const char* kFlatDefines = "#define FLAT\n";

    /// Builds the impostor shader; false (and \p error) when it does not compile.
    bool initialize(QOpenGLFunctions_3_3_Core* gl, QString& error);
    /// Frees every texture and the shader (with the context current).
    void release();

    /// What an atlas is kept for: the tree's skeleton when it has one (the instances of a
    /// variant share it, whatever level of detail each draws), else its mesh.
    using Key = const void*;
    /// The atlas a tree draws far away: its variant's (shared by its instances and the unique
    /// trees of its species that stand in with it), else its skeleton's, else its mesh's.
    static Key keyOf(const ViewTree& t);
    /// A frame's scheduling, before it draws: uploads what the worker finished (true when any
    /// came: the frame's tree buffers are then stale) and requests the atlas of every tree of
    /// \p order drawn at the impostor level that has none yet: a variant's from its level made
    /// for a tree about twice the atlas' cell high, a unique tree's from \p lod's level below
    /// the impostor once made (or its own mesh when it has no levels coming). The trees still
    /// waiting draw their coarsest mesh meanwhile (wanted()). While atlases are wanted or bake,
    /// the wake function (setWake()) is called about every 100 ms so that a frame collects them.
    bool schedule(const std::vector<TreeDraw>& order, const std::vector<ViewTree>& trees,
                  const ViewLod& lod);
    /// Trees of the last schedule() drawn at the impostor level without their atlas.
    std::size_t wanted() const { return mWanted; }
    /// What schedule() calls for a frame while atlases bake (the viewport's update()).
    void setWake(std::function<void()> wake) { mWake = std::move(wake); }
    bool has(Key key) const { return mCards.count(key) > 0; }
    /// Whether the atlas of \p key is being baked.
    bool isBaking(Key key) const { return mBaking.count(key) > 0; }
    /// Atlases being baked.
    std::size_t baking() const { return mBaking.size(); }
    /// Starts baking the impostor of \p key (kept alive by \p owner) on the worker from
    /// \p source (a coarse level: the atlas' views are a few dozen pixels), and measuring
    /// where it may take over from \p reference (the tree's full mesh, the source when null):
    /// the largest height on screen up to \p startHeightPx where its silhouette matches the
    /// tree's (mesh::impostorSwitchHeight, IoU >= 0.9); nothing when it is baked or being baked.
    void request(Key key, std::shared_ptr<const void> owner,
                 std::shared_ptr<const mesh::Mesh> source, mesh::ImpostorMaterials materials,
                 std::shared_ptr<const mesh::Mesh> reference = nullptr,
                 double startHeightPx = 94.0);
    /// The tree height on screen (pixels) under which the atlas of \p key is drawn (measured
    /// when it was baked); a negative value while it is not baked.
    double switchHeightPx(Key key) const;
    /// Impostors whose silhouette does not match their tree where the default switch would
    /// draw them, and so switch later (for View ▸ Statistics and the tests).
    std::size_t switchedLater() const;
    /// The lowest height the measure searches down to (a tree that small is an impostor
    /// whatever it loses: its mesh would cost a forest's far trees their frame).
    static constexpr double kFloorHeightPx = 24.0;
    /// Uploads the atlases the worker finished (context current); returns how many.
    std::size_t collect();
    /// The card's part that any view of \p imp covers, in units of the bounding sphere's radius
    /// around its centre: (x, y_min, y_max), the card spanning [-x, x] × [y_min, y_max] (a
    /// tree is narrower than high: most of the square card is empty, and a software renderer
    /// pays for every pixel of it), with a margin for the views' blending. (1, -1, 1) at most.
    static glm::vec3 cardExtent(const mesh::Impostor& imp);
    /// The crown occlusion the card's atlas is lit with (litImpostorAtlas): the mean of
    /// mesh::crownOcclusion over the corners of \p m's leaf triangles (all its triangles when
    /// it has no leaves), the value the viewport's mesh shader dims the same leaves by per
    /// vertex. Measured against the tree's full mesh (tests/ui/test_viewportimpostor.cpp,
    /// docs/lods.md): the constant 0.42 before made impostors 0.50-0.68 as bright as the mesh.
    static float crownOcclusion(const mesh::Mesh& m);
    /// Drops the impostors whose key \p keep does not accept.
    void retain(const std::function<bool(Key)>& keep);
    std::size_t size() const { return mCards.size(); }

    /// Starts a frame's impostors; draw() queues a tree, end() draws the queue with one
    /// instanced draw call per atlas and mipmap level (the instances of a variant share
    /// theirs). \p pixelsPerUnit: the pixels a unit at distance 1 spans on the target drawn
    /// into (its height over 2 tan(fovY / 2)). The lighting is the atlas' own
    /// (litImpostorAtlas(): the camera's key light). \p moving: a frame drawn while the view
    /// moves, where every card is drawn without the depth march from its heaviest view alone
    /// (shaders/impostor.frag's FLAT and uOneView: one fetch a pixel); at rest, cards read at
    /// kFlatFromLevel or coarser skip the march (the views still dithered).
    void begin(const glm::mat4& viewProj, const glm::vec3& eye, float pixelsPerUnit,
               bool moving = false);
    void draw(Key key, const glm::mat4& transform, float highlight);
    /// The atlas' mipmap level the shader reads a card at whose bounding sphere spans
    /// \p radiusPixels pixels of radius: the level where a texel is about a pixel, rounded,
    /// 0..kMaxLevel. The shader reads one level per card (a uniform: under Mesa llvmpipe a
    /// level that varies per pixel costs about as much as three more fetches).
    static int levelFor(float radiusPixels);
    /// The finest mipmap level kept beyond the base (the views are cell / 8 at the coarsest).
    static constexpr int kMaxLevel = 3;
    /// Samples of the shader's depth march for cards read at levels 0-1 and 2-3.
    static constexpr int kNearSteps = 4, kFarSteps = 3;
    /// The finest mipmap level drawn without the march at rest (a card of a radius of about
    /// kCell / 8 pixels: the views' parallax there is about a pixel, docs/perf/lods.md).
    static constexpr int kFlatFromLevel = 2;
    /// Returns the number of draw calls made.
    std::size_t end();

private:
    struct Card {
        std::shared_ptr<const void> owner; ///< keeps the key alive
        GLuint lit = 0, depth = 0;         ///< litImpostorAtlas() and the depth map
        glm::vec3 centre{0.0f};
        float radius = 1.0f;
        /// The part of the card any view covers (cardExtent()).
        glm::vec3 extent{1.0f, -1.0f, 1.0f};
        mesh::ImpostorSwitch fit; ///< where it may take over (mesh::impostorSwitchHeight)
    };
    struct Baked {
        mesh::Impostor impostor;
        Image lit; ///< litImpostorAtlas()
        glm::vec3 extent{1.0f, -1.0f, 1.0f};
        mesh::ImpostorSwitch fit;
    };
    struct Instance {
        glm::mat4 model;
        float highlight;
    };
    GLuint upload(const Image& image);
    QOpenGLFunctions_3_3_Core* mGl = nullptr;
    std::unique_ptr<QOpenGLShaderProgram> mProgram;     ///< marched
    std::unique_ptr<QOpenGLShaderProgram> mFlatProgram; ///< one fetch (FLAT)
    bool mMoving = false;
    GLuint mVao = 0, mInstances = 0;
    std::map<Key, std::array<std::vector<Instance>, kMaxLevel + 1>> mQueue;
    glm::vec3 mEye{0.0f};
    float mPixelsPerUnit = 1.0f;
    std::map<Key, Card> mCards;
    struct Baking {
        std::shared_ptr<const void> owner;
        QFuture<Baked> future;
    };
    std::map<Key, Baking> mBaking;
    QThreadPool mPool;       ///< one thread
    std::size_t mWanted = 0; ///< at the last schedule()
    QTimer mBakeTimer;       ///< the next frame while atlases bake
    std::function<void()> mWake;
};

} // namespace sylva::ui
