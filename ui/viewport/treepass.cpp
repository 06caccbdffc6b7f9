#include "ui/viewport/treepass.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <utility>

#include <glm/gtc/matrix_transform.hpp>

#include "engine/mesh/mesh.h"
#include "ui/generation/windvertexdata.h"
#include "ui/viewport/impostors.h"
#include "ui/viewport/treebuffers.h"
#include "ui/viewport/windclock.h"
#include "ui/viewport/windshader.h"

namespace sylva::ui {

bool TreePass::initialize(QOpenGLFunctions_3_3_Core* gl, TreeBuffers* buffers, ViewLod* lod,
                          Impostors* impostors, const WindClock* wind, bool software,
                          QString& error) {
    mGl = gl;
    mBuffers = buffers;
    mLod = lod;
    mImpostors = impostors;
    mWind = wind;
    return mMeshes.initialize(gl, buffers, wind, software, error);
}

std::vector<TreePass::Drawn> TreePass::chooseMeshes(const std::vector<ViewTree>& trees,
                                                    const std::vector<TreeDraw>& order,
                                                    bool reduced, DrawStats& stats) const {
    std::vector<Drawn> drawns;
    drawns.reserve(order.size());
    for (const TreeDraw& d : order) {
        const ViewTree& t = trees[d.index];
        ++stats.trees;
        Drawn entry{&d};
        const bool card =
            d.level == ViewLod::kImpostorLevel && mImpostors->has(Impostors::keyOf(t));
        if (!card && t.lod.instance && t.lod.variant) {
            // Below the impostor an instance draws its variant's level for its size on
            // screen (the drawlist's choice; its coarsest while the atlas bakes).
            const std::vector<mesh::DistanceLevel>& levels = t.lod.variant->levels;
            const std::size_t k = d.variantLevel >= 0
                                      ? std::min(std::size_t(d.variantLevel), levels.size() - 1)
                                      : levels.size() - 1;
            entry.mesh = levels[k].mesh.get();
            const std::size_t level = std::size_t(std::min(d.level, ViewLod::kImpostorLevel - 1));
            ++stats.perLevel[level];
            stats.trianglesPerLevel[level] += entry.mesh->triangleCount();
            stats.motion += d.motion ? 1 : 0;
        } else if (!card) {
            int used = 0;
            bool motion = false;
            // A frame drawn at reduced resolution while the view moves also draws the
            // trees' motion levels; the sharp frame that follows draws them at rest.
            entry.mesh = mLod->meshFor(t.mesh.get(), d.level, &used, reduced, &motion);
            ++stats.perLevel[std::size_t(used)];
            stats.trianglesPerLevel[std::size_t(used)] += entry.mesh->triangleCount();
            stats.motion += motion ? 1 : 0;
        }
        drawns.push_back(entry);
    }
    return drawns;
}

DrawStats TreePass::draw(const TreeFrame& frame, const std::vector<ViewTree>& trees,
                         const std::vector<ViewTree>& preview, const std::vector<TreeDraw>& order,
                         const QSet<std::uint32_t>& highlighted) {
    DrawStats stats;
    mMeshes.beginFrame();
    const std::vector<DrawRange>& sceneRanges = mBuffers->sceneRanges();
    if (sceneRanges.empty() && !mBuffers->hasTrees()) return stats;
    QOpenGLFunctions_3_3_Core& gl = *mGl;
    MeshPass::Uniforms u;
    u.viewProj = frame.viewProj;
    u.eye = frame.eye;
    u.light = frame.light;
    u.vertexColor = mBuffers->sceneVertexColors();
    // What each tree draws (its level), then the frame's wind: every swaying mesh's element
    // rotations for its tree's time.
    std::vector<Drawn> drawns = chooseMeshes(trees, order, frame.reduced, stats);
    std::vector<int> previewBases(preview.size(), -1);
    int sceneBase = -1;
    GLuint rotations = 0;
    if (mWind->active()) {
        mWindRotations.clear();
        auto add = [this](const wind::WindElements* elements, float phase) {
            if (!elements) return -1;
            const int base = int(mWindRotations.size());
            appendWindRotations(*elements, mWind->frameAt(phase), mWindRotations);
            return base;
        };
        if (mBuffers->sceneWindElements()) sceneBase = add(mBuffers->sceneElements().get(), 0);
        for (Drawn& d : drawns)
            if (d.mesh)
                if (const TreeBuffers::GpuMesh* gpu = mBuffers->find(d.mesh);
                    gpu && gpu->windElements)
                    d.windBase = add(gpu->elements.get(), trees[d.draw->index].windPhase);
        for (std::size_t i = 0; i < preview.size(); ++i)
            if (const TreeBuffers::GpuMesh* gpu = mBuffers->find(preview[i].mesh.get());
                gpu && gpu->windElements)
                previewBases[i] = add(gpu->elements.get(), preview[i].windPhase);
        rotations = mBuffers->uploadWindRotations(mWindRotations);
        gl.glActiveTexture(GL_TEXTURE0 + kWindRotationsUnit);
        gl.glBindTexture(GL_TEXTURE_BUFFER, rotations);
        gl.glActiveTexture(GL_TEXTURE0);
    }
    if (!rotations) sceneBase = -1;
    u.wind = mWind->frameAt(0.0f);
    u.windBase = std::max(sceneBase, 0);
    mMeshes.setUniforms(u);
    gl.glActiveTexture(GL_TEXTURE0);
    gl.glBindVertexArray(mBuffers->sceneVao());
    mMeshes.drawScene(sceneRanges, sceneBase >= 0 ? mBuffers->sceneWindElements() : 0);
    u.vertexColor = false;
    mMeshes.setUniforms(u);
    // Nearest first, so that the depth test spares the rasteriser what is hidden behind.
    std::vector<const TreeDraw*> cards;
    // Instances of a variant's level, in the order of their nearest instance: one instanced
    // draw call per level and material for all of them (swaying ones are drawn one by one).
    std::vector<std::pair<const mesh::Mesh*, std::vector<glm::mat4>>> groups;
    std::map<const mesh::Mesh*, std::size_t> groupOf;
    for (const Drawn& d : drawns) {
        const ViewTree& t = trees[d.draw->index];
        const float highlight = t.id && highlighted.contains(t.id) ? 0.45f : 0.0f;
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
        mMeshes.drawMesh(*d.mesh, t.transform, highlight, t.windPhase, rotations ? d.windBase : -1);
    }
    mMeshes.drawInstanced(groups);
    for (std::size_t i = 0; i < preview.size(); ++i)
        if (preview[i].mesh)
            mMeshes.drawMesh(*preview[i].mesh, preview[i].transform, 0.25f, preview[i].windPhase,
                             rotations ? previewBases[i] : -1);
    drawCards(frame, trees, cards, highlighted, stats);
    stats.triangles += mMeshes.counts().triangles;
    stats.windTriangles = mMeshes.counts().windTriangles;
    stats.instancedDrawCalls = mMeshes.counts().instancedDrawCalls;
    return stats;
}

void TreePass::drawCards(const TreeFrame& frame, const std::vector<ViewTree>& trees,
                         const std::vector<const TreeDraw*>& cards,
                         const QSet<std::uint32_t>& highlighted, DrawStats& stats) {
    if (cards.empty()) return;
    mImpostors->begin(frame.viewProj, frame.eye, frame.pixelsPerUnit, frame.reduced);
    for (const TreeDraw* d : cards) {
        const ViewTree& t = trees[d->index];
        // A unique tree standing in with its variant's atlas: scaled to its height.
        const glm::mat4 model = t.lod.impostorScale != 1.0f
                                    ? glm::scale(t.transform, glm::vec3(t.lod.impostorScale))
                                    : t.transform;
        mImpostors->draw(Impostors::keyOf(t), model,
                         t.id && highlighted.contains(t.id) ? 0.45f : 0.0f);
        ++stats.perLevel[ViewLod::kImpostorLevel];
        stats.trianglesPerLevel[ViewLod::kImpostorLevel] += 2;
        stats.triangles += 2;
    }
    stats.impostorDrawCalls = mImpostors->end();
}

} // namespace sylva::ui
