#include <gtest/gtest.h>

#include <cstring>

#include "engine/util/error.h"
#include "engine/wind/windelements.h"
#include "engine/wind/windrig.h"
#include "windtree.h"

using namespace sylva;
using namespace sylva::wind;

namespace {

struct Posed {
    std::vector<glm::vec3> skinned, model;
};

// Linear blend skinning of every vertex at one frame, against the model's own displacement
// (leaf flutter left out: the rig does not carry it).
Posed pose(const Rig& rig, const WindClip& clip, const SkinWeights& w, const mesh::Mesh& m,
           const WindSettings& settings, std::size_t frame) {
    const std::size_t nj = rig.joints.size();
    std::vector<glm::mat4> world(nj);
    for (std::size_t j = 0; j < nj; ++j) {
        const glm::mat4 local = glm::translate(glm::mat4(1.0f), clip.translation[frame * nj + j]) *
                                glm::mat4_cast(clip.rotation[frame * nj + j]);
        world[j] = rig.joints[j].parent < 0
                       ? local
                       : world[static_cast<std::size_t>(rig.joints[j].parent)] * local;
    }
    Posed out;
    const WindFrame f = windFrame(settings, clip.times[frame]);
    for (std::size_t i = 0; i < m.positions.size(); ++i) {
        glm::vec3 p(0.0f);
        for (int k = 0; k < 4; ++k) {
            const std::size_t j = w.joints[i][k];
            p += w.weights[i][k] *
                 glm::vec3(world[j] * glm::translate(glm::mat4(1.0f), -rig.joints[j].rest) *
                           glm::vec4(m.positions[i], 1.0f));
        }
        out.skinned.push_back(p);
        mesh::WindVertex v = m.wind[i];
        v.leaf.y = 0.0f;
        out.model.push_back(displace(v, m.positions[i], nullptr, f));
    }
    return out;
}

} // namespace

TEST(WindRig, StaysWithinTheBoneBudget) {
    const skel::Skeleton s = windtest::windTree();
    const WindElements e = buildWindElements(s);
    for (int budget : {2, 5, 12, 64}) {
        RigSettings rs;
        rs.maxBones = budget;
        const Rig rig = buildRig(e, s, rs);
        EXPECT_LE(static_cast<int>(rig.joints.size()), budget);
        EXPECT_GE(rig.joints.size(), 2u);
        for (std::size_t j = 0; j < rig.joints.size(); ++j)
            EXPECT_LT(rig.joints[j].parent, static_cast<std::int32_t>(j));
        EXPECT_EQ(rig.joints[0].parent, -1);
    }
    RigSettings one;
    one.maxBones = 1;
    EXPECT_THROW(buildRig(e, s, one), InvalidInput);
}

TEST(WindRig, WeightsSumToOneWithAtMostFourInfluences) {
    const skel::Skeleton s = windtest::windTree();
    const WindElements e = buildWindElements(s);
    mesh::Mesh m = windtest::windTreeMesh(s);
    for (int budget : {2, 9, 64}) {
        RigSettings rs;
        rs.maxBones = budget;
        const Rig rig = buildRig(e, s, rs);
        const SkinWeights w = skinWeights(rig, e, m);
        ASSERT_EQ(w.weights.size(), m.positions.size());
        for (std::size_t i = 0; i < w.weights.size(); ++i) {
            const glm::vec4& x = w.weights[i];
            EXPECT_NEAR(x.x + x.y + x.z + x.w, 1.0f, 1e-3f);
            EXPECT_GT(x.x, 0.0f);
            for (int k = 0; k < 4; ++k) {
                EXPECT_GE(x[k], 0.0f);
                EXPECT_LT(w.joints[i][k], rig.joints.size());
            }
        }
    }
}

TEST(WindRig, ForksDoNotTear) {
    // At the point where an element hangs, its own weights are its parent's there.
    const skel::Skeleton s = windtest::windTree();
    const WindElements e = buildWindElements(s);
    const Rig rig = buildRig(e, s, RigSettings{});
    for (std::size_t i = 0; i < e.elements.size(); ++i) {
        const WindElement& el = e.elements[i];
        if (el.parent < 0) continue;
        auto own = jointWeights(rig, e, static_cast<std::int32_t>(i), 0.0f);
        auto parent = jointWeights(rig, e, el.parent, el.attachU);
        std::sort(own.begin(), own.end());
        std::sort(parent.begin(), parent.end());
        std::erase_if(own, [](auto& x) { return x.second == 0.0f; });
        std::erase_if(parent, [](auto& x) { return x.second == 0.0f; });
        ASSERT_EQ(own.size(), parent.size()) << i;
        for (std::size_t k = 0; k < own.size(); ++k) {
            EXPECT_EQ(own[k].first, parent[k].first);
            EXPECT_NEAR(own[k].second, parent[k].second, 1e-6f);
        }
    }
}

TEST(WindRig, ClipLoopsAndFollowsTheModel) {
    const skel::Skeleton s = windtest::windTree();
    const WindElements e = buildWindElements(s);
    mesh::Mesh m = windtest::windTreeMesh(s);
    addWindData(m, s);
    const Rig rig = buildRig(e, s, RigSettings{});
    WindSettings ws;
    ws.strength = 1.0f;
    const WindClip clip = bakeClip(rig, e, ws, RigSettings{});
    ASSERT_EQ(clip.frameCount(), 121u); // 4 s at 30 fps, both ends
    EXPECT_EQ(clip.times.front(), 0.0f);
    EXPECT_EQ(clip.times.back(), 4.0f);
    const std::size_t nj = rig.joints.size();
    EXPECT_EQ(0, std::memcmp(&clip.rotation[0], &clip.rotation[120 * nj], nj * sizeof(glm::quat)));
    EXPECT_EQ(
        0, std::memcmp(&clip.translation[0], &clip.translation[120 * nj], nj * sizeof(glm::vec3)));
    const SkinWeights w = skinWeights(rig, e, m);
    float worst = 0.0f, moved = 0.0f;
    for (std::size_t f : {0u, 17u, 45u, 90u}) {
        const Posed p = pose(rig, clip, w, m, ws, f);
        for (std::size_t i = 0; i < p.skinned.size(); ++i) {
            worst = std::max(worst, glm::length(p.skinned[i] - p.model[i]));
            moved = std::max(moved, glm::length(p.model[i] - m.positions[i]));
        }
    }
    EXPECT_GT(moved, 0.2f);
    // The skinned tree stays within 15 % of the largest motion of the model's.
    EXPECT_LT(worst, 0.15f * moved);
}

TEST(WindRig, IsDeterministic) {
    const skel::Skeleton s = windtest::windTree();
    const WindElements e = buildWindElements(s);
    const Rig a = buildRig(e, s, RigSettings{}), b = buildRig(e, s, RigSettings{});
    const WindClip ca = bakeClip(a, e, WindSettings{}, RigSettings{});
    const WindClip cb = bakeClip(b, e, WindSettings{}, RigSettings{});
    ASSERT_EQ(ca.rotation.size(), cb.rotation.size());
    EXPECT_EQ(0, std::memcmp(ca.rotation.data(), cb.rotation.data(),
                             ca.rotation.size() * sizeof(glm::quat)));
}
