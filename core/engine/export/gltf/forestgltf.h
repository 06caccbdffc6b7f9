#pragma once

#include <cstdint>
#include <filesystem>
#include <map>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include <glm/glm.hpp>
#include <glm/gtc/quaternion.hpp>

#include "engine/export/gltf/gltfbuilder.h"
#include "engine/export/gltf/gltfmesh.h"
#include "engine/export/materials.h"
#include "engine/mesh/mesh.h"

namespace sylva::exporter::gltf {

struct ForestGltfOptions {
    /// Side of the square cells (metres, > 0) the forest is split into, aligned to the world
    /// origin: one node per cell, so an engine can still cull the instanced trees by cell.
    float cellSize = 50.0f;
    /// Sylva's textures folder, for materials without a sourceFile (resourcesDir()/textures).
    std::filesystem::path shippedTextures;
    Durability durability = Durability::Atomic;
};

/// A forest (or one tree) as glTF 2.0: each variant's mesh once, its instances through
/// `EXT_mesh_gpu_instancing`, each unique tree as its own mesh node. Meshes are written when they
/// are added (streamed to the builder's temporary); instances are kept (48 bytes each) until
/// commit(), which writes the node tree:
///
///     scene ─ "sylva" ─┬─ "cell_<i>_<j>" (one per non-empty cell, i = floor(x / cellSize),
///                      │   j = floor(z / cellSize), ordered by i then j)
///                      │     ├─ "<variant>_cell_<i>_<j>": mesh = the variant, translation = its
///                      │     │   first instance's position, EXT_mesh_gpu_instancing with
///                      │     │   TRANSLATION (relative to the node), ROTATION, SCALE; extras
///                      │     │   {"sylva_variant": name, "sylva_ids": [id per instance]}
///                      │     └─ "<tree name>": a unique tree, its mesh and TRS; extras
///                      │         {"sylva_id": id}
///
/// Instances keep the order they were added within each node; cells and variants are sorted, so
/// the file is a pure function of the calls. The extension is used, not required: a reader
/// without it (Blender 3.4) still shows each cell's variants once, at a real tree's place.
class ForestGltfWriter {
public:
    /// \param materials known materials (defaultMaterials(): a species' own are added from its
    /// meshes). \throw IoError
    ForestGltfWriter(std::filesystem::path path, GltfFormat format, Progress& progress,
                     ForestGltfOptions options = {},
                     std::vector<Material> materials = defaultMaterials());

    /// Writes a variant's mesh; returns the variant's index for addInstance. An empty mesh
    /// (nothing grew) is not written: its trees are nodes without a mesh, keeping their ids.
    int addVariant(const std::string& name, const mesh::Mesh& mesh);
    /// An instanced tree: \p variant as returned by addVariant, \p id the tree's stable id,
    /// its world transform (translation · rotation · scale, metres).
    void addInstance(int variant, std::uint64_t id, const glm::vec3& position,
                     const glm::quat& rotation, const glm::vec3& scale);
    /// A mesh for unique trees; returns its index for addTree (a mesh two trees share is added
    /// once and placed twice); an empty mesh is not written, its trees are nodes without one.
    int addTreeMesh(const std::string& name, const mesh::Mesh& mesh);
    /// A unique tree node named \p name (unique names are the caller's: "<species>_<id>").
    void addTree(const std::string& name, std::uint64_t id, int treeMesh, const glm::vec3& position,
                 const glm::quat& rotation, const glm::vec3& scale);

    /// The builder, for what this class does not write (skins, animations, extensions).
    GltfBuilder& builder() { return mBuilder; }
    /// The materials met so far (for copyTextures beside a .gltf).
    const std::vector<Material>& materials() const { return mMaterials.materials(); }
    std::size_t instanceCount() const { return mInstanceCount; }

    /// Writes the nodes and the file(s); returns them, main file first.
    /// \throw IoError, Cancelled, LimitExceeded
    std::vector<std::filesystem::path> commit();

private:
    struct Placed {
        std::uint64_t id;
        glm::vec3 position;
        glm::quat rotation;
        glm::vec3 scale;
    };
    struct UniqueTree {
        std::string name;
        std::uint64_t id;
        int mesh;
        Placed where;
    };
    struct Cell {
        std::map<int, std::vector<Placed>> instances; ///< variant → its instances here
        std::vector<UniqueTree> trees;
    };
    std::pair<int, int> cellOf(const glm::vec3& position) const;

    GltfBuilder mBuilder;
    ForestGltfOptions mOptions;
    MaterialTable mMaterials;
    std::vector<std::pair<std::string, int>> mVariants; ///< name, glTF mesh
    std::vector<int> mTreeMeshes;                       ///< glTF mesh of each addTreeMesh
    std::map<std::pair<int, int>, Cell> mCells;
    std::size_t mInstanceCount = 0;
};

} // namespace sylva::exporter::gltf
