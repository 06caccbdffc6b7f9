#pragma once

#include <functional>
#include <map>
#include <memory>
#include <vector>

#include <QOpenGLFunctions_3_3_Core>
#include <QString>

#include <glm/glm.hpp>

#include "engine/mesh/impostor.h"

class QOpenGLShaderProgram;

namespace sylva::mesh {
struct Mesh;
}

namespace sylva::ui {

/// The farthest level of the viewport's LOD (ui/viewport/viewlod.h): a tree a few dozen pixels
/// high drawn as one camera-facing card with the engine's baked hemi-octahedral impostor
/// (mesh::bakeImpostor, the same atlas `sylva-cli lods` writes, docs/lods.md): the three atlas
/// views around the view direction blended and reprojected through their depth (no popping
/// while the view turns), lit with the atlas' normals like the meshes. Atlases are baked on the
/// GUI thread at paint time from the tree's coarsest mesh level, a few per frame (bake()), and
/// kept per full mesh (instances of a variant share theirs) while a tree draws it.
class Impostors {
public:
    /// The atlas: kGrid × kGrid views of kCell pixels.
    static constexpr int kGrid = 8;
    static constexpr int kCell = 64;

    /// Builds the impostor shader; false (and \p error) when it does not compile.
    bool initialize(QOpenGLFunctions_3_3_Core* gl, QString& error);
    /// Frees every texture and the shader (with the context current).
    void release();

    /// What an atlas is kept for: the tree's skeleton when it has one (the instances of a
    /// variant share it, whatever level of detail each draws), else its mesh.
    using Key = const void*;
    bool has(Key key) const { return mCards.count(key) > 0; }
    /// Bakes the impostor of the tree \p key (kept alive by \p owner) from \p source (a coarse
    /// level of it: the atlas' views are a few dozen pixels) and uploads its maps.
    void bake(Key key, std::shared_ptr<const void> owner, const mesh::Mesh& source,
              const mesh::ImpostorMaterials& materials);
    /// Drops the impostors whose key \p keep does not accept.
    void retain(const std::function<bool(Key)>& keep);
    std::size_t size() const { return mCards.size(); }

    /// Starts a frame's impostors; draw() queues a tree, end() draws the queue with one
    /// instanced draw call per atlas (the instances of a variant share theirs).
    void begin(const glm::mat4& viewProj, const glm::vec3& eye, const glm::vec3& light);
    void draw(Key key, const glm::mat4& transform, float highlight);
    /// Returns the number of draw calls made.
    std::size_t end();

private:
    struct Card {
        std::shared_ptr<const void> owner; ///< keeps the key alive
        GLuint color = 0, normal = 0, depth = 0;
        glm::vec3 centre{0.0f};
        float radius = 1.0f;
    };
    struct Instance {
        glm::mat4 model;
        float highlight;
    };
    GLuint upload(const Image& image);
    QOpenGLFunctions_3_3_Core* mGl = nullptr;
    std::unique_ptr<QOpenGLShaderProgram> mProgram;
    GLuint mVao = 0, mInstances = 0;
    std::map<Key, std::vector<Instance>> mQueue;
    std::map<Key, Card> mCards;
};

} // namespace sylva::ui
