#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include <glm/ext/vector_uint4_sized.hpp>
#include <glm/glm.hpp>

namespace sylva::mesh {

/// A contiguous run of triangles that share one material.
struct Submesh {
    std::string material;         ///< "bark", "leaf", ...
    std::uint32_t firstIndex = 0; ///< into Mesh::indices
    std::uint32_t indexCount = 0;
    /// The diffuse texture of this run (a PNG path, absolute or as the species file gave it);
    /// empty: the material's default (Sylva's shipped bark.png / leaf.png).
    std::string texture{};
};

/// Per-vertex data of the wind model (engine/wind, docs/wind.md): the vertex moves with up to
/// three nested sway elements (level 0 = its trunk, 1 = the main limb, 2 = the branch), each a
/// bend about a pivot, plus a leaf flutter. 128 bytes, all floats (eight vec4),
/// interleaved as written to glTF (`_WIND_PIVOT0..2`, `_WIND_BRANCH0..2`, `_WIND_PHASE`,
/// `_WIND_LEAF`).
struct WindVertex {
    glm::vec4 pivot[3];  ///< xyz: element pivot (mesh frame, m); w: bend fraction u, 0..1
    glm::vec4 branch[3]; ///< xyz: element direction (unit); w: stiffness, 0 = no element
    glm::vec4 phase;     ///< phases (0..1) of levels 0, 1, 2 and of the leaf flutter
    /// x: hierarchy level (0..2); y: leaf flutter weight (m, 0 on bark); z, w: 0 (reserved)
    glm::vec4 leaf;
};
static_assert(sizeof(WindVertex) == 128, "the wind vertex is 32 floats");

/// Indexed triangle mesh, the output of meshing nodes and the input of exporters and the
/// viewport. Attributes are per vertex; normals and uvs are empty or of positions' size.
struct Mesh {
    std::vector<glm::vec3> positions;
    std::vector<glm::vec3> normals;
    std::vector<glm::vec2> uvs;
    std::vector<std::uint32_t> indices; ///< three per triangle
    std::vector<Submesh> submeshes;     ///< cover indices in order; empty means one "bark" run
    /// Optional per-vertex attributes for game-engine wind shaders (empty or of positions' size):
    /// the branch order of the vertex's branch, and a 0 (rigid trunk) .. 1 (thinnest twig,
    /// leaves) flexibility weight.
    std::vector<std::uint16_t> branchOrder;
    std::vector<float> flexibility;
    /// Optional (empty or of positions' size): the skeleton node each vertex was made for (its
    /// ring's node, the first node of a lateral for the lateral's base ring, a cap's end node,
    /// a leaf card's node; kNoNode when unknown), so that a viewer can colour the mesh by
    /// per-node attributes (light, vigour, age, order).
    std::vector<std::uint32_t> node;
    /// Optional (empty or of positions' size): the wind model's data, filled by wind::addWindData.
    std::vector<WindVertex> wind;
    /// Optional (empty or of positions' size): a colour the vertex multiplies its material's
    /// colour by, linear RGBA, 255 = x1: leaf cards' per-card tint (mesh/leaftint.h), white on
    /// bark. 4 bytes a vertex; written as glTF COLOR_0, FBX vertex colours, USD displayColor.
    std::vector<glm::u8vec4> colors;
    static constexpr std::uint32_t kNoNode = 0xffffffffu;
    /// The bark holds flat ribbons turned to one camera (the camera LOD's thinnest twigs): a
    /// viewer must draw this bark from both sides (closed tubes alone can cull back faces).
    bool cameraRibbons = false;

    std::size_t vertexCount() const { return positions.size(); }
    std::size_t triangleCount() const { return indices.size() / 3; }
    bool empty() const { return positions.empty(); }
};

} // namespace sylva::mesh
