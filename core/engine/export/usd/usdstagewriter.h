#pragma once

#include <cstdint>
#include <filesystem>
#include <map>
#include <memory>
#include <set>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "engine/export/materials.h"
#include "engine/mesh/mesh.h"
#include "engine/util/atomicfile.h"
#include "engine/util/progress.h"

namespace sylva::exporter::usd {

/// A species' variant: grown once, written once as a prototype of the species' PointInstancer.
struct UsdVariant {
    std::uint32_t species = 0; ///< index into UsdLayerOptions::species
    std::uint32_t index = 0;   ///< the variant's number within its species (its protoIndex)
    std::shared_ptr<const mesh::Mesh> mesh; ///< in the tree's frame, scale 1
};

/// One tree of the forest: a unique mesh (variant < 0) or an instance of a variant.
struct UsdTree {
    std::uint64_t id = 0; ///< the tree's stable id: prim name `tree_<id>`, or its `ids` entry
    std::uint32_t species = 0;
    /// Index into the list given to UsdStageWriter::setVariants; -1: a unique tree, `mesh`.
    std::int32_t variant = -1;
    glm::vec3 position{0.0f};               ///< metres
    float rotationY = 0.0f;                 ///< radians about +Y
    float scale = 1.0f;                     ///< uniform (size variation times growth stage)
    std::shared_ptr<const mesh::Mesh> mesh; ///< unique trees only
    /// Unique trees: the distance (m) from the camera its mesh's level of detail was made for;
    /// compact layers write a far tree's numbers coarser (see UsdLayerOptions::compact). 0: not
    /// made for a camera, the full compact precision.
    double cameraDistance = 0.0;
};

struct UsdLayerOptions {
    std::vector<std::string> species; ///< names, in the scene's order
    int tile = 0;                     ///< 0-based tile this layer holds
    int tileCount = 1;                ///< > 1: a tile layer, composed by writeRootLayer()
    /// What identifies the run, so that tiles of different runs are not composed together
    /// (the CLI: a hash of the project file and the options that change trees).
    std::string sceneKey;
    /// Mesh numbers: true = positions 0.1 mm, normals 3 and uvs 4 decimals (as the forest's
    /// compact OBJ), and for a unique tree meshed for 100 m or more from the camera 1 mm, 2 and
    /// 3 (from 1 km: positions 1 cm), still under a twentieth of a 4K pixel there; false = the
    /// shortest text that reads back as the same float.
    bool compact = true;
    Durability durability = Durability::Atomic;
    /// Sylva's shipped textures, for materials without a texture of their own.
    std::filesystem::path shippedTextures;
};

/// What a layer holds (for `--stats` and the readers' checks).
struct UsdLayerStats {
    std::size_t uniqueTrees = 0, instances = 0, instancers = 0, prototypes = 0, meshes = 0,
                materials = 0;
};

/// Streams a forest into a `.usda` layer (USD's text form; Debian has no OpenUSD): unique trees
/// are formatted (in parallel, joined in order) and written as they arrive, instance arrays are
/// gathered per species (36 bytes a tree) and written with the prototypes and the materials at
/// commit(). Numbers are formatted without locale, so the bytes are the same on any thread
/// count. The layer goes to a temporary beside \p path and is renamed only by commit(); the
/// species' textures are copied to `textures/` beside it. Stage layout: docs/usd.md.
class UsdStageWriter {
public:
    /// \throw IoError when the file cannot be created.
    UsdStageWriter(std::filesystem::path path, UsdLayerOptions options);
    ~UsdStageWriter();
    UsdStageWriter(const UsdStageWriter&) = delete;
    UsdStageWriter& operator=(const UsdStageWriter&) = delete;

    /// The index of species \p name, added after the known ones when it is new.
    std::uint32_t speciesIndex(const std::string& name);
    /// The variants every instance refers to; call before the first add().
    void setVariants(std::vector<UsdVariant> variants);
    /// Writes the unique trees of a batch and gathers its instances.
    /// \throw InvalidInput for a tree without a mesh or a variant out of range; IoError;
    /// Cancelled through \p progress.
    void add(const std::vector<UsdTree>& trees, Progress& progress = noProgress());
    /// Writes instancers, prototypes and materials, copies the textures and renames the layer
    /// into place. \throw IoError; Cancelled (nothing is left at the path).
    std::vector<std::filesystem::path> commit(Progress& progress = noProgress());

    const UsdLayerStats& stats() const { return mStats; }

private:
    struct Instances {
        std::vector<std::uint64_t> ids;
        std::vector<std::int32_t> protoIndices;
        std::vector<glm::vec3> positions;
        std::vector<float> rotations, scales;
    };
    const std::string& materialPrim(const mesh::Submesh& submesh);
    /// Returns how many Mesh prims it wrote (one per material run with faces).
    std::size_t appendMesh(std::string& out, const mesh::Mesh& mesh, int indent,
                           double cameraDistance = 0.0) const;
    void writeInstancers(Progress& progress);
    void writeMaterials();
    void flush(bool force = false);
    /// Appends \p text (emptied) to the file after everything before it.
    void emit(std::string& text);

    std::filesystem::path mPath;
    UsdLayerOptions mOptions;
    struct Background;
    std::unique_ptr<AtomicFile> mFile;
    std::unique_ptr<Background> mWriter; ///< after mFile: stopped before the file is closed
    std::string mBuffer;
    std::vector<UsdVariant> mVariants;
    std::vector<std::int32_t> mProtoIndex; ///< per variant: its place in its species' prototypes
    std::vector<std::string> mSpeciesPrims;
    std::vector<Instances> mInstances; ///< per species
    std::vector<Material> mMaterials;
    std::map<std::string, std::string> mMaterialPrims; ///< materialName() → prim name
    std::set<std::string> mUsedMaterialPrims;
    UsdLayerStats mStats;
};

/// The prim name of a unique tree (`tree_<id>`), as the stage and the readers' checks use it.
std::string treePrimName(std::uint64_t id);

} // namespace sylva::exporter::usd
