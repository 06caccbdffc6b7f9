#include "engine/wind/windelements.h"

#include <algorithm>
#include <cmath>

#include "engine/util/error.h"
#include "engine/util/random.h"
#include "engine/util/seedsalts.h"

namespace sylva::wind {

void WindElements::levelsOf(std::size_t node, std::int32_t element[3], float u[3]) const {
    for (int l = 0; l < 3; ++l) {
        element[l] = -1;
        u[l] = 0.0f;
    }
    std::int32_t e = node < nodeElement.size() ? nodeElement[node] : -1;
    float fraction = node < nodeU.size() ? nodeU[node] : 0.0f;
    while (e >= 0) {
        const WindElement& el = elements[static_cast<std::size_t>(e)];
        element[el.level] = e;
        u[el.level] = fraction;
        fraction = el.attachU;
        e = el.parent;
    }
}

WindElements buildWindElements(const skel::Skeleton& s) {
    s.validate();
    const std::size_t n = s.size();
    WindElements out;
    out.nodeElement.assign(n, -1);
    out.nodeU.assign(n, 0.0f);
    std::vector<float> arc(n, 0.0f);
    // The node whose fraction a node takes: itself, or for an axis deeper than level 2 the node
    // of the level-2 element it hangs on (so the whole deeper subtree moves rigidly with it).
    std::vector<std::int32_t> anchor(n, -1);
    std::vector<std::int32_t> attachNode;
    std::vector<std::int32_t> cont(n, -1);
    // Continuation: the first child with its parent's branch order (as the tube mesher chains).
    for (std::size_t j = 0; j < n; ++j) {
        const std::int32_t p = s.parent[j];
        if (p >= 0 && s.order[j] == s.order[static_cast<std::size_t>(p)] &&
            cont[static_cast<std::size_t>(p)] < 0)
            cont[static_cast<std::size_t>(p)] = static_cast<std::int32_t>(j);
    }
    for (std::size_t j = 0; j < n; ++j) {
        if (s.flags[j] & skel::kHidden) continue;
        const std::int32_t p = s.parent[j];
        const auto jj = static_cast<std::int32_t>(j);
        if (p < 0) {
            WindElement el;
            el.pivot = s.position[j];
            el.firstNode = el.tipNode = jj;
            el.radius = s.radius[j];
            el.phase = static_cast<float>(mixSeed(salt::kWindPhase, j) >> 40) * 0x1.0p-24f;
            out.nodeElement[j] = static_cast<std::int32_t>(out.elements.size());
            anchor[j] = jj;
            out.elements.push_back(el);
            attachNode.push_back(-1);
            continue;
        }
        const auto pj = static_cast<std::size_t>(p);
        const std::int32_t pe = out.nodeElement[pj];
        if (pe < 0) continue; // under a hidden node
        const bool frozen = anchor[pj] != p;
        const int level = out.elements[static_cast<std::size_t>(pe)].level;
        if (cont[pj] == jj && !frozen) {
            out.nodeElement[j] = pe;
            anchor[j] = jj;
            arc[j] = arc[pj] + glm::length(s.position[j] - s.position[pj]);
            WindElement& el = out.elements[static_cast<std::size_t>(pe)];
            if (arc[j] > el.length) {
                el.length = arc[j];
                el.tipNode = jj;
            }
        } else if (frozen || level >= 2) {
            out.nodeElement[j] = pe;
            anchor[j] = anchor[pj];
        } else {
            WindElement el;
            el.level = level + 1;
            el.parent = pe;
            el.pivot = s.position[pj];
            el.firstNode = el.tipNode = jj;
            el.radius = s.radius[j];
            arc[j] = glm::length(s.position[j] - el.pivot);
            el.length = arc[j];
            el.phase = static_cast<float>(mixSeed(salt::kWindPhase, j) >> 40) * 0x1.0p-24f;
            out.nodeElement[j] = static_cast<std::int32_t>(out.elements.size());
            anchor[j] = jj;
            out.elements.push_back(el);
            attachNode.push_back(p);
        }
    }
    for (WindElement& el : out.elements) {
        el.length = std::max(el.length, 1e-4f);
        const glm::vec3 d = s.position[static_cast<std::size_t>(el.tipNode)] - el.pivot;
        el.direction = glm::length(d) > 1e-6f ? glm::normalize(d) : glm::vec3(0, 1, 0);
        el.stiffness = elementStiffness(el.level, el.radius, el.length);
    }
    for (std::size_t j = 0; j < n; ++j) {
        if (out.nodeElement[j] < 0) continue;
        const auto a = static_cast<std::size_t>(anchor[j]);
        out.nodeU[j] = std::clamp(
            arc[a] / out.elements[static_cast<std::size_t>(out.nodeElement[a])].length, 0.0f, 1.0f);
    }
    for (std::size_t e = 0; e < out.elements.size(); ++e)
        if (attachNode[e] >= 0)
            out.elements[e].attachU = out.nodeU[static_cast<std::size_t>(attachNode[e])];
    return out;
}

mesh::WindVertex windVertexOf(const WindElements& elements, std::size_t node) {
    mesh::WindVertex v{};
    std::int32_t e[3];
    float u[3];
    elements.levelsOf(node, e, u);
    for (int l = 0; l < 3; ++l) {
        if (e[l] < 0) continue;
        const WindElement& el = elements.elements[static_cast<std::size_t>(e[l])];
        v.pivot[l] = glm::vec4(el.pivot, u[l]);
        v.branch[l] = glm::vec4(el.direction, el.stiffness);
        v.phase[l] = el.phase;
        v.leaf.x = static_cast<float>(l);
    }
    // The flutter's phase: per node, so neighbouring leaves do not flap in step.
    v.phase.w = static_cast<float>(mixSeed(salt::kWindPhase + 1, node) >> 40) * 0x1.0p-24f;
    return v;
}

void forEachLeafFlutter(const mesh::Mesh& m,
                        const std::function<void(std::uint32_t vertex, float flutter)>& weight) {
    const auto nv = static_cast<std::uint32_t>(m.positions.size());
    for (const mesh::Submesh& sm : m.submeshes) {
        if (sm.material != "leaf") continue;
        for (std::uint32_t k = sm.firstIndex; k + 6 <= sm.firstIndex + sm.indexCount; k += 6) {
            if (k + 6 > m.indices.size()) break;
            const std::uint32_t b = m.indices[k];
            if (b + 3 >= nv || m.indices[k + 1] != b + 1 || m.indices[k + 2] != b + 2 ||
                m.indices[k + 5] != b + 3)
                continue;
            const glm::vec3 stem = m.positions[b];
            const glm::vec3 along = m.positions[b + 3] - stem;
            const float len = glm::length(along);
            if (len <= 0.0f) continue;
            for (std::uint32_t c = 0; c < 4; ++c)
                weight(b + c, std::max(0.0f, glm::dot(m.positions[b + c] - stem, along / len)));
        }
    }
}

void addWindData(mesh::Mesh& m, const skel::Skeleton& skeleton) {
    if (m.node.size() != m.positions.size())
        throw InvalidInput("wind data needs the mesh's node ids (tube_mesh node_ids)");
    const WindElements elements = buildWindElements(skeleton);
    const std::size_t nv = m.positions.size();
    std::vector<mesh::WindVertex> perNode(skeleton.size());
    std::vector<std::uint8_t> done(skeleton.size(), 0);
    // Each vertex's 128 bytes written once (not zero-filled first: that pass was half of this
    // function's time on the alder's 74k vertices, bench_wind).
    m.wind.clear();
    m.wind.reserve(nv);
    for (std::size_t i = 0; i < nv; ++i) {
        const std::uint32_t node = m.node[i];
        if (node == mesh::Mesh::kNoNode || node >= skeleton.size()) {
            m.wind.push_back(mesh::WindVertex{});
            continue;
        }
        if (!done[node]) {
            perNode[node] = windVertexOf(elements, node);
            done[node] = 1;
        }
        m.wind.push_back(perNode[node]);
    }
    forEachLeafFlutter(m, [&](std::uint32_t v, float flutter) { m.wind[v].leaf.y = flutter; });
}

glm::vec3 displaceNode(const WindElements& elements, const skel::Skeleton& skeleton,
                       std::size_t node, const WindFrame& frame) {
    const mesh::WindVertex v = windVertexOf(elements, node);
    return displace(v, skeleton.position[node], nullptr, frame);
}

} // namespace sylva::wind
