#pragma once

#include <functional>
#include <map>
#include <memory>

#include <QOpenGLFunctions_3_3_Core>
#include <QString>

#include <glm/glm.hpp>

class QOpenGLShaderProgram;

namespace sylva::mesh {
struct Mesh;
}

namespace sylva::ui {

/// The farthest level of the viewport's LOD (ui/viewport/viewlod.h): a tree a few dozen pixels
/// high drawn as two crossed cards (4 triangles) textured with pictures of the tree itself,
/// taken from the front and the side with the viewport's own shading and alpha-tested, so the
/// outline of the crown is kept. Pictures are taken on the GUI thread at paint time, a few
/// per frame (bake()), and kept per mesh while a tree draws it.
class Impostors {
public:
    /// Pixels of one picture (front or side); a texture holds both side by side.
    static constexpr int kSize = 64;

    /// Draws a mesh in its own frame with the given view-projection, eye and light (the
    /// viewport's mesh shader; the target framebuffer and viewport are set).
    using DrawMesh = std::function<void(const mesh::Mesh& m, const glm::mat4& viewProj,
                                        const glm::vec3& eye, const glm::vec3& light)>;

    /// Builds the card shader; false (and \p error) when it does not compile.
    bool initialize(QOpenGLFunctions_3_3_Core* gl, QString& error);
    /// Frees every texture and the shader (with the context current).
    void release();

    bool has(const mesh::Mesh* m) const { return mCards.count(m) > 0; }
    /// Takes the pictures of \p m; restores framebuffer \p fbo and viewport \p viewport after.
    void bake(const std::shared_ptr<const mesh::Mesh>& m, const DrawMesh& draw, GLuint fbo,
              const glm::ivec4& viewport);
    /// Drops the impostors of meshes \p keep does not accept.
    void retain(const std::function<bool(const mesh::Mesh*)>& keep);
    std::size_t size() const { return mCards.size(); }

    /// Starts drawing cards (binds the shader); then draw() per tree, end() after.
    void begin(const glm::mat4& viewProj);
    void draw(const mesh::Mesh* m, const glm::mat4& transform, float highlight);
    void end();

private:
    struct Card {
        std::shared_ptr<const mesh::Mesh> mesh; ///< keeps the key alive
        GLuint texture = 0;
        glm::vec3 lo{0.0f}, hi{0.0f}; ///< the mesh's bounds in its frame
    };
    QOpenGLFunctions_3_3_Core* mGl = nullptr;
    std::unique_ptr<QOpenGLShaderProgram> mProgram;
    GLuint mVao = 0, mFbo = 0, mDepth = 0;
    std::map<const mesh::Mesh*, Card> mCards;
};

} // namespace sylva::ui
