#pragma once

#include <filesystem>
#include <memory>
#include <string>
#include <unordered_map>
#include <vector>

#include <glm/glm.hpp>
#include <glm/gtc/quaternion.hpp>

#include "engine/export/objwriter.h"
#include "engine/export/sceneexport.h"
#include "engine/mesh/mesh.h"

namespace sylva::exporter {

/// One tree to export: its mesh in its own frame and where it stands.
struct ExportTree {
    std::string name;
    std::shared_ptr<const mesh::Mesh> mesh;
    glm::vec3 position{0.0f};
    float rotationY = 0.0f; ///< radians about +Y
    float scale = 1.0f;
};

/// How an OBJ stream is written (`--fsync`, `--compact`).
struct ObjChoices {
    bool fsync = false;   ///< wait for the disk before the OBJ is renamed into place
    bool compact = false; ///< exporter::ObjOptions::compact()
};

/// Writes trees by the output's extension (what `sylva-cli tree`/`forest` and the editor's
/// File ▸ Export write): `.obj` streams batch by batch (plus `<name>.mtl` and
/// the bark/leaf textures, the species' own included, in `textures/` beside it); `.glb`,
/// `.gltf` and `.fbx` go through Assimp with one node per tree (.glb and .fbx with the textures
/// embedded, .gltf with them in `textures/`). Nothing appears at the path before commit() succeeds.
class TreeExporter {
public:
    /// \param obj how the OBJ stream is written; the other files are small and always
    /// written durably.
    explicit TreeExporter(std::filesystem::path path, ObjChoices obj = {});
    ~TreeExporter();
    void add(const std::vector<ExportTree>& trees);
    /// Finishes the file(s); returns the paths written (main file first).
    /// \throw IoError; Cancelled through \p progress (glTF/FBX: see writeScene).
    std::vector<std::filesystem::path> commit(Progress& progress = noProgress());
    /// Also write `<stem>.instances.json` and `.csv` (mesh, position, rotation, scale).
    void setInstanceTables(bool on) { mInstanceTables = on; }

private:
    std::filesystem::path mPath;
    bool mObj = true;
    bool mInstanceTables = false;
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
