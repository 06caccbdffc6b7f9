#include "engine/wind/windrig.h"

#include <algorithm>
#include <cmath>
#include <numeric>

#include "engine/util/error.h"

namespace sylva::wind {

namespace {

using Influences = std::vector<std::pair<std::int32_t, float>>;

void addScaled(Influences& into, const Influences& from, float scale) {
    if (scale <= 0.0f) return;
    for (const auto& [joint, w] : from) {
        // A copy: clang 14 cannot capture a structured binding in a lambda.
        const std::int32_t id = joint;
        auto it =
            std::find_if(into.begin(), into.end(), [&](const auto& x) { return x.first == id; });
        if (it == into.end())
            into.emplace_back(joint, w * scale);
        else
            it->second += w * scale;
    }
}

struct Sampler {
    const Rig& rig;
    const WindElements& elements;

    /// The joints (and weights) that carry a point at fraction u of element e.
    Influences at(std::int32_t e, float u) const {
        if (e < 0) return {{0, 1.0f}};
        const auto ei = static_cast<std::size_t>(e);
        const WindElement& el = elements.elements[ei];
        const std::int32_t first = rig.elementFirstJoint[ei];
        const std::int32_t count = rig.elementJointCount[ei];
        if (count == 0) return at(el.parent, el.attachU);
        // Sample points: for a trunk k/n with k = 0..n (count = n + 1); else k/n, k = 1..n,
        // and the attachment at u = 0.
        const bool base = el.parent < 0;
        const int n = base ? count - 1 : count;
        if (n == 0) return {{first, 1.0f}};
        const float x = std::clamp(u, 0.0f, 1.0f) * static_cast<float>(n);
        const int k = std::min(static_cast<int>(std::floor(x)), n - 1);
        const float s = x - static_cast<float>(k);
        Influences out;
        auto sample = [&](int kk) -> Influences {
            if (base) return {{first + kk, 1.0f}};
            if (kk == 0) return at(el.parent, el.attachU);
            return {{first + kk - 1, 1.0f}};
        };
        addScaled(out, sample(k), 1.0f - s);
        addScaled(out, sample(k + 1), s);
        return out;
    }
};

void finishWeights(Influences& inf, glm::u16vec4& joints, glm::vec4& weights) {
    std::erase_if(inf, [](const auto& x) { return x.second <= 1e-6f; });
    std::sort(inf.begin(), inf.end(), [](const auto& a, const auto& b) {
        return a.second != b.second ? a.second > b.second : a.first < b.first;
    });
    if (inf.size() > 4) inf.resize(4);
    float sum = 0.0f;
    for (const auto& x : inf)
        sum += x.second;
    joints = glm::u16vec4(0);
    weights = glm::vec4(0.0f);
    if (inf.empty() || sum <= 0.0f) {
        weights.x = 1.0f;
        return;
    }
    for (std::size_t i = 0; i < inf.size(); ++i) {
        joints[static_cast<int>(i)] = static_cast<std::uint16_t>(inf[i].first);
        weights[static_cast<int>(i)] = inf[i].second / sum;
    }
}

RigidPose compose(const RigidPose& a, const RigidPose& b) { // a after b
    return {a.rotation * b.rotation, a.rotation * b.translation + a.translation};
}

RigidPose inverse(const RigidPose& a) {
    const glm::quat inv = glm::conjugate(a.rotation);
    return {inv, -(inv * a.translation)};
}

} // namespace

std::vector<std::pair<std::int32_t, float>>
jointWeights(const Rig& rig, const WindElements& elements, std::int32_t element, float u) {
    return Sampler{rig, elements}.at(element, u);
}

void validate(const RigSettings& s) {
    requireRange("bone budget", s.maxBones, 2, 1024);
    requireRange("clip frames per second", s.fps, 1.0, 240.0);
}

Rig buildRig(const WindElements& elements, const skel::Skeleton& skeleton,
             const RigSettings& settings) {
    validate(settings);
    const std::size_t ne = elements.elements.size();
    Rig rig;
    rig.elementFirstJoint.assign(ne, -1);
    rig.elementJointCount.assign(ne, 0);
    std::vector<std::size_t> roots, limbs, branches;
    for (std::size_t e = 0; e < ne; ++e) {
        const int level = elements.elements[e].level;
        (level == 0 ? roots : level == 1 ? limbs : branches).push_back(e);
    }
    int budget = settings.maxBones;
    if (!roots.empty() && budget < 2 * static_cast<int>(roots.size()))
        throw LimitExceeded("a bone budget of " + std::to_string(budget) +
                            " is below two bones for each of the tree's " +
                            std::to_string(roots.size()) + " trunks");
    std::vector<int> segments(ne, 0);
    const int perTrunk = roots.empty() ? 0
                                       : std::clamp((budget - static_cast<int>(roots.size())) /
                                                        (4 * static_cast<int>(roots.size())),
                                                    1, 6);
    for (std::size_t e : roots) {
        segments[e] = perTrunk;
        budget -= perTrunk + 1;
    }
    auto bySize = [&](std::vector<std::size_t>& list) {
        std::stable_sort(list.begin(), list.end(), [&](std::size_t a, std::size_t b) {
            const WindElement& x = elements.elements[a];
            const WindElement& y = elements.elements[b];
            return x.length * x.radius > y.length * y.radius;
        });
    };
    bySize(limbs);
    bySize(branches);
    for (std::size_t e : limbs)
        if (budget >= 2) {
            segments[e] = 2;
            budget -= 2;
        }
    for (std::size_t e : branches)
        if (budget >= 1 && segments[static_cast<std::size_t>(elements.elements[e].parent)] > 0) {
            segments[e] = 1;
            budget -= 1;
        }
    // Joints in element order (parents before children); rest positions at the node of the
    // element nearest each fraction (the bind position does not change the skinned result).
    std::vector<std::vector<std::int32_t>> nodesOf(ne);
    for (std::size_t j = 0; j < skeleton.size(); ++j)
        if (elements.nodeElement[j] >= 0)
            nodesOf[static_cast<std::size_t>(elements.nodeElement[j])].push_back(
                static_cast<std::int32_t>(j));
    Sampler sampler{rig, elements};
    for (std::size_t e = 0; e < ne; ++e) {
        if (segments[e] == 0) continue;
        const WindElement& el = elements.elements[e];
        const bool base = el.parent < 0;
        const int n = segments[e];
        rig.elementFirstJoint[e] = static_cast<std::int32_t>(rig.joints.size());
        for (int k = base ? 0 : 1; k <= n; ++k) {
            RigJoint joint;
            joint.element = static_cast<std::int32_t>(e);
            joint.u = static_cast<float>(k) / static_cast<float>(n);
            joint.name = "wind_" + std::to_string(e) + "_" + std::to_string(k);
            joint.rest = el.pivot;
            float best = k == 0 ? 0.0f : 2.0f;
            for (std::int32_t node : nodesOf[e]) {
                const float d = std::abs(elements.nodeU[static_cast<std::size_t>(node)] - joint.u);
                if (d < best) {
                    best = d;
                    joint.rest = skeleton.position[static_cast<std::size_t>(node)];
                }
            }
            if (k > (base ? 0 : 1)) {
                joint.parent = static_cast<std::int32_t>(rig.joints.size()) - 1;
            } else if (!base) {
                // The strongest joint where the element hangs.
                const Influences inf = sampler.at(el.parent, el.attachU);
                joint.parent = std::max_element(inf.begin(), inf.end(), [](auto& a, auto& b) {
                                   return a.second < b.second;
                               })->first;
            }
            rig.joints.push_back(joint);
        }
        rig.elementJointCount[e] =
            static_cast<std::int32_t>(rig.joints.size()) - rig.elementFirstJoint[e];
    }
    return rig;
}

SkinWeights skinWeights(const Rig& rig, const WindElements& elements, const mesh::Mesh& m) {
    if (m.node.size() != m.positions.size())
        throw InvalidInput("skin weights need the mesh's node ids (tube_mesh node_ids)");
    SkinWeights out;
    const std::size_t nv = m.positions.size();
    // Each vertex written once (no zero-fill first: bench_wind).
    out.joints.reserve(nv);
    out.weights.reserve(nv);
    Sampler sampler{rig, elements};
    const std::size_t nn = elements.nodeElement.size();
    std::vector<glm::u16vec4> nodeJoints(nn);
    std::vector<glm::vec4> nodeWeights(nn);
    std::vector<std::uint8_t> done(nn, 0);
    for (std::size_t i = 0; i < nv; ++i) {
        const std::uint32_t node = m.node[i];
        if (node == mesh::Mesh::kNoNode || node >= nn || elements.nodeElement[node] < 0) {
            out.joints.emplace_back(0);
            out.weights.emplace_back(1, 0, 0, 0);
            continue;
        }
        if (!done[node]) {
            Influences inf = sampler.at(elements.nodeElement[node], elements.nodeU[node]);
            finishWeights(inf, nodeJoints[node], nodeWeights[node]);
            done[node] = 1;
        }
        out.joints.push_back(nodeJoints[node]);
        out.weights.push_back(nodeWeights[node]);
    }
    return out;
}

RigidPose elementPose(const WindElements& elements, std::int32_t element, float u,
                      const WindFrame& frame) {
    float treePhase = 0.0f;
    for (std::int32_t e = element; e >= 0;
         e = elements.elements[static_cast<std::size_t>(e)].parent)
        treePhase = elements.elements[static_cast<std::size_t>(e)].phase;
    RigidPose pose;
    float fraction = u;
    // Innermost first: pose = T_parent ∘ … ∘ T_element.
    for (std::int32_t e = element; e >= 0;) {
        const WindElement& el = elements.elements[static_cast<std::size_t>(e)];
        const glm::vec3 r =
            elementRotation(frame, el.direction, el.stiffness, el.phase, el.level, treePhase) *
            bendProfile(fraction);
        const float angle = glm::length(r);
        const glm::quat q =
            angle > 1e-12f ? glm::angleAxis(angle, r / angle) : glm::quat(1, 0, 0, 0);
        const RigidPose t{q, el.pivot - q * el.pivot};
        pose = compose(t, pose);
        fraction = el.attachU;
        e = el.parent;
    }
    return pose;
}

WindClip bakeClip(const Rig& rig, const WindElements& elements, const WindSettings& wind,
                  const RigSettings& settings) {
    validate(wind);
    validate(settings);
    WindClip clip;
    const auto frames = static_cast<std::size_t>(std::max(
                            1.0, std::round(static_cast<double>(wind.period) * settings.fps))) +
                        1;
    const std::size_t nj = rig.joints.size();
    clip.jointCount = nj;
    clip.times.resize(frames);
    clip.translation.resize(frames * nj);
    clip.rotation.resize(frames * nj);
    std::vector<RigidPose> world(nj);
    for (std::size_t f = 0; f < frames; ++f) {
        const double t = f + 1 == frames ? wind.period
                                         : static_cast<double>(f) * wind.period /
                                               static_cast<double>(frames - 1);
        clip.times[f] = static_cast<float>(t);
        if (f + 1 == frames && f > 0) {
            // The loop closes exactly: the last frame is the first.
            std::copy_n(clip.translation.begin(), nj, clip.translation.begin() + f * nj);
            std::copy_n(clip.rotation.begin(), nj, clip.rotation.begin() + f * nj);
            break;
        }
        const WindFrame frame = windFrame(wind, t);
        for (std::size_t j = 0; j < nj; ++j) {
            const RigJoint& joint = rig.joints[j];
            const RigidPose m = elementPose(elements, joint.element, joint.u, frame);
            world[j] = {m.rotation, m.rotation * joint.rest + m.translation};
            RigidPose local = world[j];
            if (joint.parent >= 0)
                local = compose(inverse(world[static_cast<std::size_t>(joint.parent)]), world[j]);
            glm::quat q = glm::normalize(local.rotation);
            if (q.w < 0.0f) q = -q;
            clip.translation[f * nj + j] = local.translation;
            clip.rotation[f * nj + j] = q;
        }
    }
    return clip;
}

} // namespace sylva::wind
