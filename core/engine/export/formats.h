#pragma once

#include <filesystem>
#include <memory>
#include <span>
#include <string>
#include <vector>

namespace sylva::exporter {

class ForestWriter;
struct ForestWriterOptions;
struct GameLodFiles;
struct LodChainWrite;

/// The file formats Sylva writes. A new format is one row of formatTable() (its extension, its
/// dialog name, what it can carry), one folder under engine/export/ with its writers, and its
/// tests (docs/formats.md).
enum class Format { Obj, Usda, Glb, Gltf, Fbx };

/// How a format carries the wind model (docs/wind.md).
enum class WindSupport {
    None,  ///< refused (a USD stage has no skinning of ours)
    Table, ///< the geometry as without wind, plus `<stem>.wind.csv` (the extra any format can ask
           ///< for)
    Rig,   ///< the low-bone rig, the looping clip and Pivot Painter 2 textures, plus the table
};

/// One format: the only place that knows a file extension. The dispatch (TreeExporter,
/// WindExporter, doc::exportProject, the LOD chain), the CLI's usage and checks, the editor's
/// file dialog and the Python docstrings read it.
struct FormatRow {
    Format format;
    const char* extension; ///< lower case, with its dot: ".obj"
    const char* name;      ///< what the file dialog's filter calls it: "Wavefront OBJ"
    bool instancing;       ///< a variant's mesh written once, its trees as instances of it
    WindSupport wind;      ///< what `--wind` writes
    bool tileLayers;       ///< `--tile i/N` writes a layer that `sylva-cli compose` joins
    bool vertexColors;     ///< Mesh::colors (leaf tints) are written
    bool instanceTables;   ///< `--instance-tables` (the `.instances.json`/`.csv` extra) allowed
    bool embedsTextures;   ///< the textures travel inside the file, else copied to textures/
    /// Makes the format's forest writer (its folder: obj/, usd/, gltf/, fbx/).
    std::unique_ptr<ForestWriter> (*makeWriter)(const std::filesystem::path& path,
                                                const ForestWriterOptions& options);
    /// Writes the game LOD chain in the format (`sylva-cli lods`, lodchainexport.h); nullptr:
    /// the format has none.
    void (*lodChain)(const LodChainWrite& write, GameLodFiles& files,
                     std::vector<std::filesystem::path>& written);
};

/// Every format, in the order usage texts and the file dialog list them.
std::span<const FormatRow> formatTable();

/// The row of \p format.
const FormatRow& formatRow(Format format);

/// The row whose extension \p path has (case-insensitive), or nullptr.
const FormatRow* findFormat(const std::filesystem::path& path);

/// The row whose extension \p path has.
/// \throw InvalidInput naming the extensions of formatTable() otherwise.
const FormatRow& formatFor(const std::filesystem::path& path);

/// Whether \p path has \p format's extension (case-insensitive).
bool isFormat(const std::filesystem::path& path, Format format);

/// The extensions of the rows \p keep accepts (every row by default), joined as usage texts and
/// messages write them: ".obj, .usda, .glb, .gltf or .fbx" (\p last before the final one), or
/// with \p dots false and \p separator "," and \p last ",": "obj,usda,glb,gltf,fbx".
std::string extensionList(bool (*keep)(const FormatRow&) = nullptr, const char* separator = ", ",
                          const char* last = " or ", bool dots = true);

/// The file dialog's filter of the whole table: "Wavefront OBJ (*.obj);;USD text (*.usda);;…".
std::string dialogFilter();

} // namespace sylva::exporter
