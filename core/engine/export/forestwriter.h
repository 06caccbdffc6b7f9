#pragma once

#include <cstdint>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "engine/mesh/mesh.h"
#include "engine/util/progress.h"

namespace sylva::exporter {

/// A mesh that instanced trees share (a species' variant), written once by formats with
/// instancing (FormatRow::instancing).
struct ExportVariant {
    std::string name; ///< the node or prototype label ("<species>_v<index>"); never read back
    std::shared_ptr<const mesh::Mesh> mesh;
    std::uint32_t species = 0; ///< index into ForestWriterOptions::species
    std::uint32_t index = 0;   ///< the variant's number within its species
};

/// One tree to export: its mesh in its own frame and where it stands.
struct ExportTree {
    std::string name; ///< the object or node label ("<species>_<id>"); never read back
    std::shared_ptr<const mesh::Mesh> mesh;
    glm::vec3 position{0.0f};
    float rotationY = 0.0f; ///< radians about +Y
    float scale = 1.0f;
    /// Index into the last ForestWriter::setVariants list: the tree is an instance of that
    /// variant (its mesh is the variant's); -1: a unique tree.
    std::int32_t variant = -1;
    std::uint64_t id = 0;      ///< the tree's stable id (glTF extras, USD prim; OBJ/FBX: in name)
    std::uint32_t species = 0; ///< index into ForestWriterOptions::species
    /// The distance (m) from the camera its mesh's level of detail was made for (compact USD
    /// writes a far tree coarser); 0: not made for a camera.
    double cameraDistance = 0.0;
};

/// What every format's forest writer is made with; each reads what it needs.
struct ForestWriterOptions {
    /// Species names by ExportTree::species / ExportVariant::species: USD's species scopes (a
    /// tree of a species not listed is refused there); the other formats name by the labels.
    std::vector<std::string> species;
    bool fsync = false;   ///< wait for the disk before the main file is renamed into place
    bool compact = false; ///< OBJ: ObjOptions::compact(); USD: UsdLayerOptions::compact
    /// Formats with tile layers (FormatRow::tileLayers): the 0-based tile, the tile count (> 1:
    /// a layer for `sylva-cli compose`) and what identifies the run.
    int tile = 0;
    int tileCount = 1;
    std::string sceneKey;
    /// .glb/.gltf through Assimp's exporter instead of our streaming writer (comparisons).
    bool assimpGltf = false;
};

/// One format's writer of trees and variants (a folder under engine/export/ each: obj/, gltf/,
/// usd/, fbx/); made by makeForestWriter() from the format table's row. Species and variants
/// arrive as numbers; names are labels only. Nothing appears at the path before commit().
class ForestWriter {
public:
    virtual ~ForestWriter() = default;
    /// The variants the following trees' ExportTree::variant indexes.
    virtual void setVariants(const std::vector<ExportVariant>& variants) = 0;
    virtual void add(const std::vector<ExportTree>& trees) = 0;
    /// Finishes the file(s); returns the paths written (main file first).
    /// \throw IoError; Cancelled through setProgress's progress.
    virtual std::vector<std::filesystem::path> commit() = 0;
    /// Whether instanced trees' own meshes go unused (the variants are written once).
    virtual bool writesInstances() const { return false; }
    /// Where a long write learns to stop; by default never. Call before add().
    void setProgress(Progress& progress) { mProgress = &progress; }

protected:
    Progress& progress() const { return *mProgress; }

private:
    Progress* mProgress = &noProgress();
};

/// The writer of \p path's format (formatFor(): the format table's row, its factory).
/// \throw InvalidInput for an extension no row has; IoError when the folder cannot be made.
std::unique_ptr<ForestWriter> makeForestWriter(const std::filesystem::path& path,
                                               const ForestWriterOptions& options);

} // namespace sylva::exporter
