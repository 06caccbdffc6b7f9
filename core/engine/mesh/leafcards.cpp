#include "engine/mesh/leafcards.h"

#include "engine/util/error.h"

namespace sylva::mesh {

namespace {

CardSpan makeRoomForCards(Mesh& out, std::size_t cards, bool grow) {
    CardSpan span;
    span.firstVertex = out.positions.size();
    span.firstIndex = out.indices.size();
    if (out.submeshes.empty() && span.firstIndex > 0)
        out.submeshes.push_back({"bark", 0, static_cast<std::uint32_t>(span.firstIndex)});
    const std::size_t nv = span.firstVertex + 4 * cards;
    if (grow) {
        out.positions.resize(nv);
        out.normals.resize(nv, glm::vec3(0, 1, 0));
        out.uvs.resize(nv, glm::vec2(0.0f));
        out.indices.resize(span.firstIndex + 6 * cards);
    } else {
        out.positions.reserve(nv);
        out.normals.reserve(nv);
        out.uvs.reserve(nv);
        out.indices.reserve(span.firstIndex + 6 * cards);
    }
    span.wind = !out.branchOrder.empty();
    if (span.wind) {
        out.branchOrder.resize(nv, 0);
        out.flexibility.resize(nv, 1.0f);
    }
    span.ids = !out.node.empty();
    if (span.ids) out.node.resize(nv, Mesh::kNoNode);
    // Leaf tints (leaftint.h) are given after the cards are made: white until then.
    if (!out.colors.empty()) out.colors.resize(nv, glm::u8vec4(255));
    return span;
}

} // namespace

CardSpan growForCards(Mesh& out, std::size_t cards) {
    return makeRoomForCards(out, cards, true);
}

CardSpan reserveForCards(Mesh& out, std::size_t cards) {
    return makeRoomForCards(out, cards, false);
}

void appendLeafCards(Mesh& out, const std::vector<skel::Leaf>& leaves,
                     const LeafCardSettings& settings, const skel::Skeleton* skeleton) {
    requireRange("leaf_aspect", settings.aspect, 1e-6, 4.0);
    requireRange("leaf_scale", settings.sizeScale, 1e-6, 100.0);
    if (leaves.empty()) return;
    const CardSpan span = growForCards(out, leaves.size());
    const std::size_t v0 = span.firstVertex;
    const std::size_t i0 = span.firstIndex;
    const bool wind = span.wind;
    const bool ids = span.ids;
    const auto aspect = static_cast<float>(settings.aspect);
    const auto scale = static_cast<float>(settings.sizeScale);
    static const glm::vec2 kUv[4] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
    for (std::size_t k = 0; k < leaves.size(); ++k) {
        const skel::Leaf& leaf = leaves[k];
        const float len = leaf.size * scale;
        const glm::vec3 h = skel::headingOf(leaf.orientation) * len;
        const glm::vec3 l = skel::leftOf(leaf.orientation) * (0.5f * aspect * len);
        const glm::vec3 n = glm::normalize(skel::upOf(leaf.orientation));
        const glm::vec3 corners[4] = {leaf.position + l, leaf.position - l, leaf.position - l + h,
                                      leaf.position + l + h};
        const std::size_t v = v0 + 4 * k;
        for (std::size_t c = 0; c < 4; ++c) {
            out.positions[v + c] = corners[c];
            out.normals[v + c] = n;
            out.uvs[v + c] = kUv[c];
            if (ids)
                out.node[v + c] =
                    leaf.node >= 0 ? static_cast<std::uint32_t>(leaf.node) : Mesh::kNoNode;
            if (wind) {
                const bool known = skeleton && leaf.node >= 0 &&
                                   static_cast<std::size_t>(leaf.node) < skeleton->size();
                out.branchOrder[v + c] =
                    known ? skeleton->order[static_cast<std::size_t>(leaf.node)] : 0;
                out.flexibility[v + c] = 1.0f;
            }
        }
        const auto b = static_cast<std::uint32_t>(v);
        const std::uint32_t tri[6] = {b, b + 1, b + 2, b, b + 2, b + 3};
        for (std::size_t t = 0; t < 6; ++t)
            out.indices[i0 + 6 * k + t] = tri[t];
    }
    out.submeshes.push_back(
        {"leaf", static_cast<std::uint32_t>(i0), static_cast<std::uint32_t>(6 * leaves.size())});
}

} // namespace sylva::mesh
