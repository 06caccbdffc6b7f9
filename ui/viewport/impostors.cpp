#include "ui/viewport/impostors.h"

#include <QOpenGLShaderProgram>
#include <QtConcurrent/QtConcurrentRun>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <iterator>
#include <limits>

#include "engine/export/materials.h"
#include "engine/mesh/mesh.h"
#include "engine/mesh/occlusion.h"
#include "ui/viewport/drawlist.h"
#include "ui/viewport/impostorlighting.h"
#include "ui/viewport/shaderprogram.h"
#include "ui/viewport/viewlod.h"
#include "ui/viewport/viewtree.h"

namespace sylva::ui {

Impostors::Impostors() {
    mBakeTimer.setSingleShot(true);
    mBakeTimer.setInterval(100);
    QObject::connect(&mBakeTimer, &QTimer::timeout, [this] {
        if (mWake) mWake();
    });
}

Impostors::Key Impostors::keyOf(const ViewTree& t) {
    if (t.lod.variant) return static_cast<Key>(t.lod.variant.get());
    return t.lod.skeleton ? static_cast<Key>(t.lod.skeleton.get()) : static_cast<Key>(t.mesh.get());
}

bool Impostors::schedule(const std::vector<TreeDraw>& order, const std::vector<ViewTree>& trees,
                         const ViewLod& lod) {
    // Atlases bake on the worker (one per variant: its instances and the unique trees of its
    // species share it); the trees still waiting are drawn with their coarsest mesh meanwhile,
    // and a frame now and then uploads what is done.
    static const mesh::ImpostorTextures textures(exporter::resourcesDir() / "textures");
    const bool collected = collect() > 0;
    mWanted = 0;
    for (const TreeDraw& d : order) {
        const ViewTree& t = trees[d.index];
        const Key key = keyOf(t);
        if (d.level != ViewLod::kImpostorLevel || has(key)) continue;
        ++mWanted;
        if (isBaking(key)) continue;
        std::shared_ptr<const void> owner;
        std::shared_ptr<const mesh::Mesh> source, reference;
        if (t.lod.variant) {
            // The variant's level made for a tree about twice the atlas' cell high on the
            // reference view (the bake supersamples twice): all its views can show.
            const ViewVariant& v = *t.lod.variant;
            const double refFov = v.referenceFovYDegrees * 3.14159265358979323846 / 180.0;
            const double distance = double(v.height) * v.referenceHeightPx /
                                    (2.0 * std::tan(0.5 * refFov) * 2.0 * kCell);
            source = v.levels[mesh::levelFor(v.levels, distance)].mesh;
            reference = v.levels.front().mesh;
            owner = t.lod.variant;
        } else {
            // Baked from the tree's coarse level once the worker has made it, or from its own
            // mesh when it has no levels coming.
            source = lod.levelMesh(t.mesh.get(), ViewLod::kImpostorLevel - 1);
            if (!source && lod.pending() > 0 && t.lod.skeleton) continue;
            if (!source) source = t.mesh;
            reference = t.mesh;
            owner = t.lod.skeleton ? std::shared_ptr<const void>(t.lod.skeleton)
                                   : std::shared_ptr<const void>(t.mesh);
        }
        request(key, std::move(owner), std::move(source), textures, std::move(reference),
                ViewLod::impostorHeightPx());
    }
    // Atlases still baking are collected by the timer's frames too, even when no tree in the
    // view wants one now (the view moved nearer meanwhile): else the view's pending count
    // stays up.
    if ((mWanted > 0 || baking() > 0) && !mBakeTimer.isActive()) mBakeTimer.start();
    return collected;
}

bool Impostors::initialize(QOpenGLFunctions_3_3_Core* gl, QString& error) {
    mGl = gl;
    // One card drawn from the vertex id alone (shaders/impostor.vert).
    // Two programs: the marched one and, for small cards, the one-fetch one (FLAT).
    mProgram =
        buildShaderProgram(QStringLiteral("impostor.vert"), QStringLiteral("impostor.frag"), error);
    if (!mProgram) return false;
    mFlatProgram = buildShaderProgram(QStringLiteral("impostor.vert"),
                                      QStringLiteral("impostor.frag"), error, kFlatDefines);
    if (!mFlatProgram) return false;
    // The card's corners come from the vertex id; per instance: the model matrix (locations
    // 0-3) and the highlight (4).
    gl->glGenVertexArrays(1, &mVao);
    gl->glGenBuffers(1, &mInstances);
    gl->glBindVertexArray(mVao);
    gl->glBindBuffer(GL_ARRAY_BUFFER, mInstances);
    for (GLuint c = 0; c < 4; ++c) {
        gl->glEnableVertexAttribArray(c);
        gl->glVertexAttribPointer(c, 4, GL_FLOAT, GL_FALSE, sizeof(Instance),
                                  reinterpret_cast<const void*>(c * sizeof(glm::vec4)));
        gl->glVertexAttribDivisor(c, 1);
    }
    gl->glEnableVertexAttribArray(4);
    gl->glVertexAttribPointer(4, 1, GL_FLOAT, GL_FALSE, sizeof(Instance),
                              reinterpret_cast<const void*>(offsetof(Instance, highlight)));
    gl->glVertexAttribDivisor(4, 1);
    gl->glBindVertexArray(0);
    gl->glBindBuffer(GL_ARRAY_BUFFER, 0);
    return true;
}

void Impostors::release() {
    // The worker's atlases are dropped; its thread finishes the one it bakes.
    for (auto& [key, job] : mBaking)
        job.future.waitForFinished();
    mBaking.clear();
    if (!mGl) return;
    for (auto& [key, card] : mCards) {
        const GLuint textures[2] = {card.lit, card.depth};
        mGl->glDeleteTextures(2, textures);
    }
    mCards.clear();
    if (mVao) mGl->glDeleteVertexArrays(1, &mVao);
    if (mInstances) mGl->glDeleteBuffers(1, &mInstances);
    mVao = mInstances = 0;
    mProgram.reset();
    mFlatProgram.reset();
    mGl = nullptr;
}

GLuint Impostors::upload(const Image& image) {
    QOpenGLFunctions_3_3_Core& gl = *mGl;
    GLuint t = 0;
    gl.glGenTextures(1, &t);
    gl.glBindTexture(GL_TEXTURE_2D, t);
    gl.glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    const GLenum format = image.channels == 4 ? GL_RGBA : image.channels == 3 ? GL_RGB : GL_RED;
    const GLint internal = image.channels == 4 ? GL_RGBA8 : image.channels == 3 ? GL_RGB8 : GL_R8;
    gl.glTexImage2D(GL_TEXTURE_2D, 0, internal, image.width, image.height, 0, format,
                    GL_UNSIGNED_BYTE, image.pixels.data());
    gl.glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
    // Mipmaps of the whole atlas mix neighbouring views below cell / 8 pixels: the levels stop
    // there (the colour is bled into empty texels, so the levels above keep the edges clean).
    gl.glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAX_LEVEL, kMaxLevel);
    gl.glGenerateMipmap(GL_TEXTURE_2D);
    gl.glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
    gl.glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    gl.glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    gl.glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    return t;
}

void Impostors::request(Key key, std::shared_ptr<const void> owner,
                        std::shared_ptr<const mesh::Mesh> source, mesh::ImpostorMaterials materials,
                        std::shared_ptr<const mesh::Mesh> reference, double startHeightPx) {
    if (!mGl || !mProgram || !key || !source || source->triangleCount() == 0 || has(key) ||
        isBaking(key))
        return;
    mPool.setMaxThreadCount(1);
    Baking job;
    job.owner = std::move(owner);
    job.future =
        QtConcurrent::run(&mPool, [source = std::move(source), materials = std::move(materials),
                                   reference = std::move(reference), startHeightPx]() {
            // Not niced (the levels' worker is): a few atlases a forest, one per variant, and
            // until they are baked its far trees draw meshes, which costs every frame; niced,
            // they waited minutes on a loaded machine.
            mesh::ImpostorSettings settings;
            settings.grid = kGrid;
            settings.cellPixels = kCell;
            settings.supersample = 2;
            Baked baked;
            try {
                baked.impostor = mesh::bakeImpostor(*source, materials, settings);
                baked.extent = cardExtent(baked.impostor);
                baked.lit = litImpostorAtlas(baked.impostor, crownOcclusion(*source));
                // Where the impostor matches the tree (issue 40: a willow's impostor lost its
                // hanging curtains where it took over): measured against the full tree, the
                // switch moved down to where the silhouettes agree.
                const mesh::Mesh& tree = reference ? *reference : *source;
                const float height = mesh::verticalExtent(tree);
                const double start = std::max(startHeightPx, kFloorHeightPx);
                // SYLVA_IMPOSTOR_FIT=0: the default switch for every atlas (tests that measure
                // the impostor itself at sizes where it would not be drawn).
                static const bool measure =
                    qEnvironmentVariableIsSet("SYLVA_IMPOSTOR_FIT")
                        ? qEnvironmentVariableIntValue("SYLVA_IMPOSTOR_FIT") != 0
                        : true;
                if (height > 0.0f && measure) {
                    baked.fit = mesh::impostorSwitchHeight(tree, baked.impostor, double(height),
                                                           start, 0.9, kFloorHeightPx);
                } else {
                    baked.fit.heightPx = start;
                }
            } catch (...) {
                baked.impostor = mesh::Impostor{}; // an empty atlas: the tree keeps its mesh
            }
            return baked;
        });
    mBaking.emplace(key, std::move(job));
}

float Impostors::crownOcclusion(const mesh::Mesh& m) {
    const std::vector<float> occlusion = mesh::crownOcclusion(m);
    const bool hasLeaves = std::any_of(m.submeshes.begin(), m.submeshes.end(),
                                       [](const mesh::Submesh& s) { return s.material == "leaf"; });
    double sum = 0.0;
    std::size_t n = 0;
    const auto add = [&](std::size_t first, std::size_t count) {
        for (std::size_t i = first; i < first + count && i < m.indices.size(); ++i)
            if (m.indices[i] < occlusion.size()) {
                sum += double(occlusion[m.indices[i]]);
                ++n;
            }
    };
    if (!hasLeaves) add(0, m.indices.size());
    for (const mesh::Submesh& s : m.submeshes)
        if (hasLeaves && s.material == "leaf") add(s.firstIndex, s.indexCount);
    return n > 0 ? std::clamp(float(sum / double(n)), 0.0f, 1.0f) : 1.0f;
}

glm::vec3 Impostors::cardExtent(const mesh::Impostor& imp) {
    const Image& color = imp.color;
    const int grid = imp.settings.grid, cell = imp.settings.cellPixels;
    if (color.channels != 4 || grid <= 0 || cell <= 0 || color.width != grid * cell ||
        color.height != grid * cell)
        return {1.0f, -1.0f, 1.0f};
    float x = 0.0f, lo = 1.0f, hi = -1.0f;
    for (int py = 0; py < color.height; ++py)
        for (int px = 0; px < color.width; ++px) {
            if (color.pixels[(std::size_t(py) * std::size_t(color.width) + std::size_t(px)) * 4 +
                             3] == 0)
                continue;
            // The texel's place on its view's card: x right, y up, -1..1.
            const float cx = 2.0f * (float(px % cell) + 0.5f) / float(cell) - 1.0f;
            const float cy = 1.0f - 2.0f * (float(py % cell) + 0.5f) / float(cell);
            x = std::max(x, std::abs(cx));
            lo = std::min(lo, cy);
            hi = std::max(hi, cy);
        }
    if (hi < lo) return {1.0f, -1.0f, 1.0f};
    // The blend of three views reprojected through their depth reaches a little past each
    // view's own silhouette (neighbouring views are 90° / (grid - 1) apart): a margin of a
    // tenth of the radius and two texels.
    const float margin = 0.1f + 4.0f / float(cell);
    return {std::min(1.0f, x + margin), std::max(-1.0f, lo - margin), std::min(1.0f, hi + margin)};
}

std::size_t Impostors::collect() {
    std::size_t n = 0;
    for (auto it = mBaking.begin(); it != mBaking.end();) {
        if (!it->second.future.isFinished()) {
            ++it;
            continue;
        }
        const Baked baked = it->second.future.result();
        const mesh::Impostor& imp = baked.impostor;
        if (mGl && !imp.color.pixels.empty()) {
            Card card;
            card.owner = std::move(it->second.owner);
            card.centre = imp.centre;
            card.radius = imp.radius;
            card.extent = baked.extent;
            card.fit = baked.fit;
            card.lit = upload(baked.lit);
            card.depth = upload(imp.depth);
            mGl->glBindTexture(GL_TEXTURE_2D, 0);
            mCards.emplace(it->first, std::move(card));
            ++n;
        }
        it = mBaking.erase(it);
    }
    return n;
}

double Impostors::switchHeightPx(Key key) const {
    const auto it = mCards.find(key);
    return it == mCards.end() ? -1.0 : it->second.fit.heightPx;
}

std::size_t Impostors::switchedLater() const {
    return std::size_t(std::count_if(mCards.begin(), mCards.end(), [](const auto& entry) {
        // The first height tried is the default switch.
        const mesh::ImpostorSwitch& fit = entry.second.fit;
        return !fit.tried.empty() && fit.heightPx < fit.tried.front().first;
    }));
}

void Impostors::retain(const std::function<bool(Key)>& keep) {
    // A job for a key no longer kept finishes on the worker (it holds its own mesh) unheard.
    for (auto it = mBaking.begin(); it != mBaking.end();)
        it = keep(it->first) ? std::next(it) : mBaking.erase(it);
    for (auto it = mCards.begin(); it != mCards.end();) {
        if (keep(it->first)) {
            ++it;
            continue;
        }
        if (mGl) {
            const GLuint textures[2] = {it->second.lit, it->second.depth};
            mGl->glDeleteTextures(2, textures);
        }
        it = mCards.erase(it);
    }
}

int Impostors::levelFor(float radiusPixels) {
    // The card's square (2 radii) holds kCell texels of a view.
    const float texelsPerPixel = float(kCell) / std::max(2.0f * radiusPixels, 1e-3f);
    return std::clamp(int(std::floor(std::log2(std::max(texelsPerPixel, 1.0f)) + 0.5f)), 0,
                      kMaxLevel);
}

void Impostors::begin(const glm::mat4& viewProj, const glm::vec3& eye, float pixelsPerUnit,
                      bool moving) {
    mEye = eye;
    mPixelsPerUnit = pixelsPerUnit;
    mMoving = moving;
    for (QOpenGLShaderProgram* program : {mProgram.get(), mFlatProgram.get()}) {
        program->bind();
        setUniform(*program, "uViewProj", viewProj);
        setUniform(*program, "uEye", eye);
        program->setUniformValue("uGrid", kGrid);
        program->setUniformValue("uCell", kCell);
        program->setUniformValue("uLit", 0);
        program->setUniformValue("uDepth", 2);
        program->setUniformValue("uOneView", program == mFlatProgram.get() && moving);
    }
    for (auto& [key, levels] : mQueue)
        for (std::vector<Instance>& list : levels)
            list.clear();
}

void Impostors::draw(Key key, const glm::mat4& transform, float highlight) {
    const auto card = mCards.find(key);
    if (card == mCards.end()) return;
    const glm::vec3 centre(transform * glm::vec4(card->second.centre, 1.0f));
    const float radius = card->second.radius * glm::length(glm::vec3(transform[0]));
    const float distance = std::max(glm::length(centre - mEye), 1e-3f);
    mQueue[key][std::size_t(levelFor(radius * mPixelsPerUnit / distance))].push_back(
        {transform, highlight});
}

std::size_t Impostors::end() {
    QOpenGLFunctions_3_3_Core& gl = *mGl;
    gl.glBindVertexArray(mVao);
    gl.glDisable(GL_CULL_FACE);
    gl.glBindBuffer(GL_ARRAY_BUFFER, mInstances);
    std::size_t calls = 0;
    // Drop the atlases no longer drawn.
    for (auto it = mQueue.begin(); it != mQueue.end();) {
        const auto& levels = it->second;
        const bool empty = std::all_of(levels.begin(), levels.end(),
                                       [](const std::vector<Instance>& l) { return l.empty(); });
        it = empty || !mCards.count(it->first) ? mQueue.erase(it) : std::next(it);
    }
    // The finest level first: its cards are the largest, nearest ones, and a card drawn behind
    // them is cut by the depth test before its fragments are shaded. Each atlas' instances are
    // nearest first already (the draw list's order).
    QOpenGLShaderProgram* bound = nullptr;
    for (std::size_t level = 0; level <= std::size_t(kMaxLevel); ++level)
        for (const auto& [key, levels] : mQueue) {
            const std::vector<Instance>& list = levels[level];
            if (list.empty()) continue;
            const Card& c = mCards.at(key);
            // Small cards, and every card while the view moves, read the view's plane without
            // the march (shaders/impostor.frag's FLAT): one fetch a pixel.
            QOpenGLShaderProgram* program =
                mMoving || int(level) >= kFlatFromLevel ? mFlatProgram.get() : mProgram.get();
            if (program != bound) {
                program->bind();
                bound = program;
            }
            setUniform(*program, "uCentre", c.centre);
            program->setUniformValue("uRadius", c.radius);
            setUniform(*program, "uExtent", c.extent);
            program->setUniformValue("uLevel", float(level));
            // Fewer samples of the march for cards read at levels 2-3, a few dozen pixels high
            // at most: the ray's whole march moves a few pixels there (measured: no change in
            // the picture, docs/perf/lods.md).
            program->setUniformValue("uSteps", level >= 2 ? kFarSteps : kNearSteps);
            gl.glActiveTexture(GL_TEXTURE2);
            gl.glBindTexture(GL_TEXTURE_2D, c.depth);
            gl.glActiveTexture(GL_TEXTURE0);
            gl.glBindTexture(GL_TEXTURE_2D, c.lit);
            // Orphaned each time: the driver need not wait for the previous draw's copy.
            gl.glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(list.size() * sizeof(Instance)), nullptr,
                            GL_STREAM_DRAW);
            gl.glBufferSubData(GL_ARRAY_BUFFER, 0, GLsizeiptr(list.size() * sizeof(Instance)),
                               list.data());
            gl.glDrawArraysInstanced(GL_TRIANGLES, 0, 6, GLsizei(list.size()));
            ++calls;
        }
    gl.glBindBuffer(GL_ARRAY_BUFFER, 0);
    for (GLenum unit : {GL_TEXTURE2, GL_TEXTURE0}) {
        gl.glActiveTexture(unit);
        gl.glBindTexture(GL_TEXTURE_2D, 0);
    }
    gl.glBindVertexArray(0);
    return calls;
}

} // namespace sylva::ui
