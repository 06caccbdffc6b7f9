#pragma once

#include <cstdint>
#include <filesystem>

#include "engine/mesh/treemesh.h"

namespace sylva {
class Value;
} // namespace sylva

namespace sylva::graph {
class NodeRegistry;
} // namespace sylva::graph

namespace sylva::mesh {

/// Registers the geometry node types (see docs/geometry.md for every parameter):
/// - `tube_mesh`: input one node with a skeleton; outputs the skeleton and a bark + leaf mesh.
///   Params: resolution (3..64, 8), caps, thickness ("skeleton" | "branching"),
///   initial_thickness, thickness_multiplier, radius_scale, leaves, leaf_aspect, leaf_scale,
///   wind_attributes, node_ids (Mesh::node, for colouring by node attributes), wind_data
///   (Mesh::wind, the wind model's per-vertex data; node ids too), lod_distance (-1 =
///   off), lod_bands, lod_min_twig_pixels, lod_simplify_pixels, lod_leaf_cluster_pixels,
///   lod_ribbon_pixels, lod_leafy_twig_pixels, lod_screen_height, lod_fov, bark_texture_file,
///   leaf_texture_file (PNGs relative to the species file; Submesh::texture). Stats: vertices,
///   triangles; timing: mesh.
/// - `leaves`: input one node with a skeleton; outputs the skeleton with placed leaves (and, if
///   the input carries a mesh, that mesh with the new leaves' cards appended).
void registerMeshNodes(graph::NodeRegistry& registry);

/// The tube_mesh node's parameters as settings, for callers that mesh outside the graph (LOD
/// chains, forests). \p seed drives leaf thinning; \p baseDir resolves relative texture files
/// (bark_texture_file, leaf_texture_file), normally the species file's folder.
/// \throw InvalidInput naming the parameter.
TreeMeshSettings treeMeshSettingsFromParams(const sylva::Value& params, std::uint64_t seed,
                                            const std::filesystem::path& baseDir = {});

} // namespace sylva::mesh
