#pragma once

#include <filesystem>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "engine/export/formats.h"
#include "engine/export/pivotpainter.h"
#include "engine/mesh/mesh.h"
#include "engine/skeleton/skeleton.h"
#include "engine/util/progress.h"
#include "engine/wind/windmodel.h"
#include "engine/wind/windrig.h"

namespace sylva::exporter {

/// One tree of a wind export: its mesh (with Mesh::node; Mesh::wind is derived when missing,
/// once per mesh)
/// and the skeleton it was made from, in the tree's frame, and where it stands.
struct WindExportTree {
    std::string name;
    std::shared_ptr<const mesh::Mesh> mesh;
    std::shared_ptr<const skel::Skeleton> skeleton;
    glm::vec3 position{0.0f};
    float rotationY = 0.0f; ///< radians about +Y
    float scale = 1.0f;
};

struct WindExportOptions {
    wind::WindSettings wind;
    wind::RigSettings rig;
};

/// Writes trees with wind (docs/wind.md) by the output's extension:
/// - `.glb` / `.gltf` (our GltfBuilder): per unique mesh the `_WIND*` vertex attributes, JOINTS_0
///   and WEIGHTS_0; per tree a joint hierarchy under the tree's node, a skin, and a skinned mesh
///   node at the scene's root; one animation "wind" looping over the period (every tree's
///   joints). Trees sharing a mesh share its arrays and its clip's accessors.
/// - `.fbx` (Assimp): per tree the bone nodes, the mesh's skin deformers (clusters) and one
///   animation stack "wind".
/// .glb, .gltf and .fbx also get Unreal's Pivot Painter 2 textures per unique mesh
/// (`<stem>[_<tree>]_pivot_index.exr`, `<stem>[_<tree>]_xaxis_extent.png`) and the element
/// index as a second UV set (glTF TEXCOORD_1, FBX UV channel 1) that addresses them.
/// Every format also gets `<stem>.wind.csv`: the per-vertex channels as a table (object,
/// vertex, rest position, the 32 floats of mesh::WindVertex), the form tools without custom
/// attributes (OBJ, FBX) read them in. Nothing appears before commit() succeeds; the same trees
/// give byte-identical files.
class WindExporter {
public:
    /// \throw InvalidInput for an extension other than .glb, .gltf, .fbx or .obj (.obj: the
    /// caller writes the OBJ; this writes the table only), or settings out of range.
    WindExporter(std::filesystem::path path, WindExportOptions options,
                 Progress& progress = noProgress());
    ~WindExporter();
    void add(const std::vector<WindExportTree>& trees);
    /// Writes the file(s); returns them, main file first.
    std::vector<std::filesystem::path> commit();

    /// The rig, weights and clip of a tree as the export writes them (tests, the Python API).
    struct Prepared {
        std::shared_ptr<const mesh::Mesh> mesh; ///< with Mesh::wind
        wind::Rig rig;
        wind::SkinWeights weights;
        wind::WindClip clip;
        PivotPainterData pivotPainter; ///< Unreal's Pivot Painter 2 textures and UVs
    };
    static Prepared prepare(const WindExportTree& tree, const WindExportOptions& options);
    /// The same with the tree's mesh given with its wind data.
    static Prepared prepare(const WindExportTree& tree, std::shared_ptr<const mesh::Mesh> withWind,
                            const WindExportOptions& options);

private:
    std::vector<std::filesystem::path> writeGltf();
    std::vector<std::filesystem::path> writeFbx();
    void writeTable();
    /// The tree's mesh with Mesh::wind, derived once per mesh (shared by every writer here).
    std::shared_ptr<const mesh::Mesh> windMesh(const WindExportTree& tree);
    /// The Pivot Painter textures of each unique mesh of \p prepared (in the trees' order).
    std::vector<std::filesystem::path>
    writePivotPainterFiles(const std::vector<std::pair<std::string, const Prepared*>>& prepared);

    std::filesystem::path mPath;
    Format mFormat = Format::Obj; ///< the format table's row of mPath
    WindExportOptions mOptions;
    Progress& mProgress;
    std::vector<WindExportTree> mTrees;
    std::map<const mesh::Mesh*, std::shared_ptr<const mesh::Mesh>> mWindMeshes;
};

} // namespace sylva::exporter
