#pragma once

#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "engine/export/exportnames.h"
#include "engine/export/fbx/scenetrees.h"
#include "engine/export/forestwriter.h"
#include "engine/export/formats.h"
#include "engine/export/materials.h"
#include "engine/mesh/mesh.h"

namespace sylva::exporter {

/// How an OBJ stream is written (`--fsync`, `--compact`).
struct ObjChoices {
    bool fsync = false;   ///< wait for the disk before the OBJ is renamed into place
    bool compact = false; ///< exporter::ObjOptions::compact()
};

/// Writes trees in the format of the output's extension (what `sylva-cli tree`/`forest`, Python
/// and the editor's File ▸ Export write): the format table's row (formats.h) makes the
/// format's ForestWriter (obj/, gltf/, usd/, fbx/), and this adds the extras any format may
/// ask for: the folder created, the instance tables. Nothing appears at the path before
/// commit() succeeds.
class TreeExporter {
public:
    /// \param obj how the OBJ stream is written; the other files are small and always
    /// written durably. \throw InvalidInput for an extension the format table lacks.
    explicit TreeExporter(std::filesystem::path path, ObjChoices obj = {});
    /// \p options: species names (USD), precision, durability, tile layer.
    TreeExporter(std::filesystem::path path, ForestWriterOptions options);
    ~TreeExporter();
    /// The variants the following trees' ExportTree::variant index (glTF writes each mesh now).
    void addVariants(const std::vector<ExportVariant>& variants);
    void add(const std::vector<ExportTree>& trees);
    /// Where a long write (the glTF file's final copy) learns to stop; by default never.
    void setProgress(Progress& progress);
    /// Finishes the file(s); returns the paths written (main file first).
    /// \throw IoError; Cancelled through setProgress's progress (FBX: see writeScene).
    std::vector<std::filesystem::path> commit();
    /// Also write `<stem>.instances.json` and `.csv` (mesh, position, rotation, scale).
    /// \throw InvalidInput for a format that holds its instances itself
    /// (FormatRow::instanceTables).
    void setInstanceTables(bool on);
    /// Writes .glb/.gltf through Assimp's exporter (one node per tree, no instancing, the whole
    /// file in memory; quadratic in the file's size) instead of gltf::ForestGltfWriter: for
    /// comparisons (`sylva-cli forest --assimp-gltf`). Call before add().
    void setAssimpGltf(bool on);
    /// Whether the output instances the variants (glTF through our writer, USD): then the trees'
    /// own meshes of instanced trees are not written (ForestOptions::meshInstances can be off).
    bool writesInstances() const { return mWriter->writesInstances(); }
    /// The format's writer (USD's layer statistics).
    ForestWriter& writer() { return *mWriter; }
    const FormatRow& format() const { return mFormat; }

private:
    std::filesystem::path mPath;
    const FormatRow& mFormat;
    ForestWriterOptions mOptions;
    Progress* mProgress = &noProgress();
    std::unique_ptr<ForestWriter> mWriter;
    std::optional<SceneTrees> mTables; ///< the instance tables' rows, when asked for
};

} // namespace sylva::exporter
