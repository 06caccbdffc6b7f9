#pragma once

#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include <glm/glm.hpp>
#include <glm/gtc/quaternion.hpp>

#include "engine/export/materials.h"
#include "engine/mesh/mesh.h"
#include "engine/util/progress.h"

struct aiScene;

namespace sylva::exporter {

/// A unique mesh of an exported scene (a species, or one LOD level).
struct SceneMesh {
    std::string name;
    const mesh::Mesh* mesh = nullptr;
};

/// A placed copy of a SceneMesh: position (metres), rotation and scale.
struct SceneInstance {
    std::string name;     ///< node name ("<species>_<instance>")
    std::size_t mesh = 0; ///< index into SceneDesc::meshes
    glm::vec3 position{0.0f};
    glm::quat rotation{1, 0, 0, 0};
    glm::vec3 scale{1.0f};
};

/// Unique meshes once, instances referencing them: glTF nodes reuse one mesh.
struct SceneDesc {
    std::vector<SceneMesh> meshes;
    std::vector<SceneInstance> instances;
    std::vector<Material> materials = defaultMaterials();
    /// Sylva's shipped textures (bark.png, leaf.png), for materials without a sourceFile.
    std::filesystem::path textureSource;
    /// Called with the Assimp scene before it is exported (the wind export adds bones and an
    /// animation): instance i is the root's child i, its meshes the mesh's non-empty submeshes in
    /// order, each with its vertices in the order its triangles first use them.
    std::function<void(aiScene&)> decorate;
    /// The timing of what decorate animates, stated in an FBX (repairAssimpFbxBinary's
    /// FbxRepairOptions): frames per second and the clip's seconds; 0 leaves Assimp's.
    double animationFrameRate = 0.0;
    double animationSeconds = 0.0;
};

enum class SceneFormat {
    Glb,  ///< glTF 2.0 binary (.glb)
    Gltf, ///< glTF 2.0 text with an external .bin (two files)
    /// Autodesk FBX 7.5 binary, the form Blender, Unity and Unreal import. Assimp 5.2.5 writes
    /// it without the null records FBX 7.5 requires (nobody can read that back), so the bytes
    /// are repaired (repairAssimpFbxBinary) before they are written; units: metres.
    Fbx,
    /// Autodesk FBX 7.4 ASCII (Blender does not import ASCII FBX; Maya and Assimp do).
    FbxAscii,
};

/// Assimp's form of a file name's format (formatFor(): .glb, .gltf, .fbx = binary FBX); throws
/// InvalidInput for another extension, and for a format Assimp does not write here (.obj, .usda).
SceneFormat sceneFormatFor(const std::filesystem::path& path);

/// Exports through Assimp's exporter. Each Mesh becomes one Assimp mesh per submesh (bark,
/// leaf), each with its material (materialName) and texture: embedded in .glb and .fbx (read
/// from textureSourceOf; a file that cannot be read stays a reference), referenced by .gltf; every
/// instance is one node that references its mesh's Assimp meshes (shared, not copied). Written to
/// memory first and then atomically to disk, so no half-written file appears. Assimp cannot be
/// interrupted, so its exporter runs on a thread of its own over its own copy of the scene;
/// when \p progress is cancelled, writeScene abandons that thread within 50 ms (it finishes or
/// ends with the process; nothing of it reaches the disk) and throws Cancelled.
/// \throw InvalidInput, IoError, Cancelled
void writeScene(const std::filesystem::path& path, const SceneDesc& scene, SceneFormat format,
                Progress& progress = noProgress());

/// Instance table rows as JSON: {"format":"sylva-instances","format_version":1,"instances":
/// [{"name","mesh","position":[x,y,z],"rotation":[x,y,z,w],"scale":[x,y,z]}...]}.
std::string formatInstancesJson(const SceneDesc& scene);
/// The same as CSV: name,mesh,px,py,pz,qx,qy,qz,qw,sx,sy,sz.
std::string formatInstancesCsv(const SceneDesc& scene);

} // namespace sylva::exporter
