#include "ui/generation/windvertexdata.h"

#include <algorithm>
#include <cmath>

#include <glm/gtc/packing.hpp>

#include "engine/graph/graph.h"
#include "engine/mesh/mesh.h"
#include "engine/util/random.h"
#include "engine/util/seedsalts.h"

namespace sylva::ui {

std::vector<glm::vec4> windElementTexels(const wind::WindElements& elements) {
    const std::vector<wind::WindElement>& els = elements.elements;
    std::vector<glm::vec4> out;
    out.reserve(els.size() * kWindTexelsPerElement);
    // The root's phase drives the tree's gusts at every level (wind::elementRotation's
    // treePhase): each element carries its root's, so the shader needs no walk for it.
    std::vector<float> rootPhase(els.size(), 0.0f);
    for (std::size_t e = 0; e < els.size(); ++e) {
        const wind::WindElement& el = els[e];
        rootPhase[e] = el.parent < 0 ? el.phase : rootPhase[static_cast<std::size_t>(el.parent)];
        out.emplace_back(el.pivot, el.stiffness);
        out.emplace_back(el.direction, el.phase);
        out.emplace_back(static_cast<float>(el.parent), el.attachU, static_cast<float>(el.level),
                         rootPhase[e]);
    }
    return out;
}

std::vector<ViewWindVertex> windVertices(const mesh::Mesh& m, const wind::WindElements& elements) {
    const std::size_t nv = m.positions.size();
    if (m.node.size() != nv || nv == 0) return {};
    const std::size_t nodes = elements.nodeElement.size();
    std::vector<ViewWindVertex> out(nv);
    for (std::size_t i = 0; i < nv; ++i) {
        const std::uint32_t node = m.node[i];
        if (node == mesh::Mesh::kNoNode || node >= nodes) continue;
        const std::int32_t e = elements.nodeElement[node];
        if (e < 0) continue;
        ViewWindVertex& v = out[i];
        v.element = static_cast<std::uint32_t>(e) + 1u;
        // wind::windVertexOf's flutter phase, as its 24 bits.
        v.flutterPhase = static_cast<std::uint32_t>(mixSeed(salt::kWindPhase + 1, node) >> 40);
        v.u = static_cast<std::uint16_t>(
            std::lround(std::clamp(elements.nodeU[node], 0.0f, 1.0f) * 65535.0f));
    }
    // Leaf cards as wind::addWindData reads them (4 vertices, triangles b, b+1, b+2, b, b+2,
    // b+3; the stem at b): the flutter weight grows with the distance from the stem.
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
                out[b + c].flutter = glm::packHalf1x16(
                    std::max(0.0f, glm::dot(m.positions[b + c] - stem, along / len)));
        }
    }
    return out;
}

glm::vec3 displacePacked(const std::vector<glm::vec4>& texels, const ViewWindVertex& v,
                         const glm::vec3& position, glm::vec3* normal,
                         const wind::WindFrame& frame) {
    if (v.element == 0) return position;
    // Unpacked into the engine's vertex, then the engine's law: what wind.glsl does with the
    // same texels, step by step.
    mesh::WindVertex w{};
    std::int32_t e = static_cast<std::int32_t>(v.element - 1u);
    float u = static_cast<float>(v.u) / 65535.0f;
    const auto at = [&texels](std::int32_t element, int k) {
        return texels[static_cast<std::size_t>(element) * kWindTexelsPerElement +
                      static_cast<std::size_t>(k)];
    };
    w.phase.x = at(e, 2).w;
    while (e >= 0) {
        const glm::vec4 t0 = at(e, 0), t1 = at(e, 1), t2 = at(e, 2);
        const int level = std::clamp(static_cast<int>(t2.z), 0, 2);
        w.pivot[level] = glm::vec4(glm::vec3(t0), u);
        w.branch[level] = glm::vec4(glm::vec3(t1), t0.w);
        w.phase[level] = t1.w;
        u = t2.y;
        e = static_cast<std::int32_t>(t2.x);
    }
    w.phase.w = static_cast<float>(v.flutterPhase) * 0x1.0p-24f;
    w.leaf.y = glm::unpackHalf1x16(v.flutter);
    return wind::displace(w, position, normal, frame);
}

float windPhaseOf(std::uint64_t treeId) {
    if (treeId == 0) return 0.0f;
    return static_cast<float>(mixSeed(salt::kViewWindPhase, treeId) >> 40) * 0x1.0p-24f;
}

void requestNodeIds(graph::SpeciesGraph& graph) {
    for (graph::NodeDesc& n : graph.nodes)
        if (n.type == "tube_mesh") n.params.objectRef()["node_ids"] = sylva::Value(true);
}

} // namespace sylva::ui
