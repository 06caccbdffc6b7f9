#pragma once

#include <filesystem>
#include <memory>
#include <string>
#include <unordered_map>
#include <vector>

#include <glm/glm.hpp>
#include <glm/gtc/quaternion.hpp>

#include "engine/export/gltf/forestgltf.h"
#include "engine/export/objwriter.h"
#include "engine/export/sceneexport.h"
#include "engine/export/usd/usdstagewriter.h"
#include "engine/mesh/mesh.h"

namespace sylva::exporter {

/// One tree to export: its mesh in its own frame and where it stands.
struct ExportTree {
    std::string name;
    std::shared_ptr<const mesh::Mesh> mesh;
    glm::vec3 position{0.0f};
    float rotationY = 0.0f; ///< radians about +Y
    float scale = 1.0f;
    /// Index into the last TreeExporter::addVariants list: the tree is an instance of that
    /// variant (its mesh is the variant's); -1: a unique tree.
    std::int32_t variant = -1;
    std::uint64_t id = 0; ///< the tree's stable id (glTF extras; OBJ/FBX carry it in the name)
};

/// A mesh that instanced trees share (a species' variant), written once by formats with
/// instancing (glTF: EXT_mesh_gpu_instancing).
struct ExportVariant {
    std::string name; ///< "<species>_v<index>"
    std::shared_ptr<const mesh::Mesh> mesh;
};

/// How an OBJ stream is written (`--fsync`, `--compact`).
struct ObjChoices {
    bool fsync = false;   ///< wait for the disk before the OBJ is renamed into place
    bool compact = false; ///< exporter::ObjOptions::compact()
};

/// Writes trees by the output's extension (what `sylva-cli tree`/`forest` and the editor's
/// File ▸ Export write): `.obj` streams batch by batch (plus `<name>.mtl` and
/// the bark/leaf textures, the species' own included, in `textures/` beside it); `.glb` and
/// `.gltf` stream through gltf::ForestGltfWriter (variants once with their instances through
/// EXT_mesh_gpu_instancing in 50 m cells, unique trees as mesh nodes; .glb with the textures
/// embedded, .gltf with them in `textures/`); `.usda` through usd::UsdStageWriter (a PointInstancer
/// per species over its variants, unique trees as meshes; species from the names
/// "<species>_<id>" and "<species>_v<k>" the forest gives; no tiles: the CLI writes those); `.fbx`
/// goes through Assimp with one node per tree (textures embedded). Nothing appears at the path
/// before commit() succeeds.
class TreeExporter {
public:
    /// \param obj how the OBJ stream is written; the other files are small and always
    /// written durably.
    explicit TreeExporter(std::filesystem::path path, ObjChoices obj = {});
    ~TreeExporter();
    /// The variants the following trees' ExportTree::variant index (glTF writes each mesh now).
    void addVariants(const std::vector<ExportVariant>& variants);
    void add(const std::vector<ExportTree>& trees);
    /// Where a long write (the glTF file's final copy) learns to stop; by default never.
    void setProgress(Progress& progress) { mProgress = &progress; }
    /// Finishes the file(s); returns the paths written (main file first).
    /// \throw IoError; Cancelled through setProgress's progress (FBX: see writeScene).
    std::vector<std::filesystem::path> commit();
    /// Also write `<stem>.instances.json` and `.csv` (mesh, position, rotation, scale).
    void setInstanceTables(bool on) { mInstanceTables = on; }
    /// Writes .glb/.gltf through Assimp's exporter (one node per tree, no instancing, the whole
    /// file in memory; quadratic in the file's size) instead of gltf::ForestGltfWriter: for
    /// comparisons (`sylva-cli forest --assimp-gltf`). Call before add().
    void setAssimpGltf(bool on) { mGltf = mGltf && !on; }
    /// Whether the output instances the variants (glTF through our writer): then the trees'
    /// own meshes of instanced trees are not written (ForestOptions::meshInstances can be off).
    bool writesInstances() const { return mGltf; }

private:
    gltf::ForestGltfWriter& gltfWriter();

    std::filesystem::path mPath;
    bool mObj = true;
    bool mGltf = false;
    bool mInstanceTables = false;
    ObjChoices mChoices;
    Progress* mProgress = &noProgress();
    std::unique_ptr<gltf::ForestGltfWriter> mGltfWriter;
    std::unique_ptr<usd::UsdStageWriter> mUsd;     ///< `.usda`
    std::vector<std::uint32_t> mUsdVariantSpecies; ///< per variant of the last addVariants
    std::vector<int> mGltfVariants; ///< the last addVariants list → the writer's variants
    /// Unique trees' meshes already written, by address; the weak pointer tells a mesh still
    /// shared from a new one that reuses a freed mesh's address (meshes are not kept alive).
    std::unordered_map<const mesh::Mesh*, std::pair<std::weak_ptr<const mesh::Mesh>, int>>
        mGltfMeshes;
    std::unique_ptr<ObjStreamWriter> mObjWriter;
    std::vector<std::shared_ptr<const mesh::Mesh>> mKeepAlive;
    std::unordered_map<const mesh::Mesh*, std::size_t> mMeshIndex; ///< into mScene.meshes
    SceneDesc mScene;
    std::vector<Material> mObjMaterials = defaultMaterials();
};

/// \p speciesName as an object name for OBJ/glTF/FBX: letters, digits and '-' kept, anything
/// else '_' ("tree" when empty), as `sylva-cli tree` and the editor name a species' object.
std::string objectNameFor(const std::string& speciesName);

/// Folder of Sylva's shipped resources (textures): $SYLVA_RESOURCES_DIR, the source tree next
/// to the build folder, or the installed share/sylva/resources; empty when none is found.
std::filesystem::path resourcesDir();

} // namespace sylva::exporter
