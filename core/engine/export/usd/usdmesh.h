#pragma once

#include <functional>
#include <string>
#include <utility>
#include <vector>

#include "engine/export/materials.h"
#include "engine/mesh/mesh.h"

namespace sylva::exporter::usd {

/// A mesh's material runs: its submeshes, or one "bark" run over every index when it has none.
std::vector<mesh::Submesh> materialRuns(const mesh::Mesh& mesh);

/// The prim path a run's `material:binding` targets.
using MaterialPathOf = std::function<std::string(const mesh::Submesh&)>;

/// Appends one `def Mesh` per material run of \p mesh (with faces), \p indent spaces deep, each
/// holding only the vertices its run uses (docs/usd.md, "Meshes"): the one mesh writer of the
/// forest stage and the LOD chain's stage. Triangle pairs are written as quads, flat faces'
/// normals `uniform`, atlas uvs indexed. \p compact: positions 0.1 mm, normals 3 and uvs 4
/// decimals, one decimal less from \p cameraDistance 100 m (positions two less from 1 km: a
/// twentieth of a 4K pixel there); else the shortest text that reads back as the same float.
/// Returns how many Mesh prims it wrote. Thread-safe when \p materialPath is.
std::size_t appendMeshPrims(std::string& out, const mesh::Mesh& mesh, int indent, bool compact,
                            const MaterialPathOf& materialPath, double cameraDistance = 0.0);

/// Appends `def Scope "Materials"` (4 spaces deep: a child of the layer's root prim, which is at
/// \p scopePath's parent) with one UsdPreviewSurface material per (prim name, material), in the
/// order given: diffuse texture or colour, the leaf's opacity cut-out, normal and roughness maps
/// (docs/usd.md, "Materials").
void appendMaterialScope(std::string& out, const std::string& scopePath,
                         const std::vector<std::pair<std::string, const Material*>>& materials);

} // namespace sylva::exporter::usd
