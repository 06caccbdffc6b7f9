#include "ui/generation/windvertexdata.h"

#include <algorithm>
#include <cmath>

#include <glm/gtc/packing.hpp>

#include "engine/graph/graph.h"
#include "engine/mesh/mesh.h"
#include "engine/util/random.h"
#include "engine/util/seedsalts.h"
#include "engine/wind/windelements.h"

namespace sylva::ui {

std::vector<glm::vec4> windElementTexels(const wind::WindElements& elements) {
    std::vector<glm::vec4> out;
    out.reserve(elements.elements.size());
    for (const wind::WindElement& el : elements.elements)
        out.emplace_back(el.pivot, static_cast<float>(el.parent));
    return out;
}

void appendWindRotations(const wind::WindElements& elements, const wind::WindFrame& frame,
                         std::vector<glm::vec4>& out) {
    const std::vector<wind::WindElement>& els = elements.elements;
    const std::size_t first = out.size();
    out.resize(first + els.size());
    // The root's phase drives its tree's gusts at every level (elementRotation's treePhase,
    // wind::displace's phase.x); parents come before children.
    std::vector<float> rootPhase(els.size(), 0.0f);
    for (std::size_t e = 0; e < els.size(); ++e) {
        const wind::WindElement& el = els[e];
        rootPhase[e] = el.parent < 0 ? el.phase : rootPhase[static_cast<std::size_t>(el.parent)];
        out[first + e] = glm::vec4(wind::elementRotation(frame, el.direction, el.stiffness,
                                                         el.phase, el.level, rootPhase[e]),
                                   el.attachU);
    }
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
    // Leaf cards: the flutter weight as the exports' _WIND data has it.
    wind::forEachLeafFlutter(
        m, [&](std::uint32_t v, float flutter) { out[v].flutter = glm::packHalf1x16(flutter); });
    return out;
}

namespace {

// wind.glsl's windTurn / windRotate: Rodrigues with the series of sin(a)/a and (1 - cos a)/a²
// (below 1e-7 off for the model's angles, at most 0.6 rad), what the shader computes.
glm::vec3 rotateSeries(const glm::vec3& r, const glm::vec3& v) {
    const float a2 = glm::dot(r, r);
    const float s = 1.0f - a2 * (1.0f / 6.0f - a2 * (1.0f / 120.0f - a2 * (1.0f / 5040.0f)));
    const float t = 0.5f - a2 * (1.0f / 24.0f - a2 * (1.0f / 720.0f - a2 * (1.0f / 40320.0f)));
    const float c = 1.0f - a2 * t;
    return v * c + glm::cross(r, v) * s + r * (glm::dot(r, v) * t);
}

} // namespace

glm::vec3 displacePacked(const std::vector<glm::vec4>& texels,
                         const std::vector<glm::vec4>& rotations, const ViewWindVertex& v,
                         const glm::vec3& position, glm::vec3* normal,
                         const wind::WindFrame& frame) {
    if (v.element == 0 || frame.strength <= 0.0f) return position;
    glm::vec3 p = position;
    glm::vec3 n = normal ? *normal : glm::vec3(0.0f);
    // wind.glsl's windDisplace, line for line.
    const float flutterWeight = glm::unpackHalf1x16(v.flutter);
    if (flutterWeight > 0.0f) {
        const float len = glm::length(n);
        if (len > 1e-12f) {
            const float phase = static_cast<float>(v.flutterPhase) * 0x1.0p-24f;
            const float cycles =
                std::max(1.0f, std::floor(frame.baseCycles * 6.0f * (0.8f + 0.4f * phase) + 0.5f));
            const float flutter =
                flutterWeight * frame.strength * (0.2f + 0.15f * frame.gustiness) *
                std::sin(frame.omega * cycles * frame.time + 6.28318530717958647692f * phase);
            p += n * (flutter / len);
        }
    }
    auto e = static_cast<std::int32_t>(v.element - 1u);
    float u = static_cast<float>(v.u) / 65535.0f;
    float rootY = position.y;
    for (int k = 0; k < 3 && e >= 0; ++k) {
        const glm::vec4 t = texels[static_cast<std::size_t>(e)];
        const glm::vec4 r = rotations[static_cast<std::size_t>(e)];
        const glm::vec3 rot = glm::vec3(r) * wind::bendProfile(u);
        const glm::vec3 pivot(t);
        p = pivot + rotateSeries(rot, p - pivot);
        n = rotateSeries(rot, n);
        rootY = t.y;
        u = r.w;
        e = static_cast<std::int32_t>(t.w);
    }
    p.y = std::max(p.y, std::min(position.y, rootY));
    if (normal) *normal = n;
    return p;
}

float windPhaseOf(std::uint64_t treeId) {
    if (treeId == 0) return 0.0f;
    return static_cast<float>(mixSeed(salt::kViewWindPhase, treeId) >> 40) * 0x1.0p-24f;
}

void requestNodeIds(graph::SpeciesGraph& graph) {
    for (graph::NodeDesc& n : graph.nodes)
        if (graph::roleOf(n.type) == graph::NodeRole::Mesher)
            n.params.objectRef()["node_ids"] = sylva::Value(true);
}

} // namespace sylva::ui
