#include "engine/export/formats.h"

#include <array>
#include <vector>

#include "engine/export/fbx/fbxforestwriter.h"
#include "engine/export/fbx/fbxlodchain.h"
#include "engine/export/gltf/gltfforestwriter.h"
#include "engine/export/gltf/gltflodchain.h"
#include "engine/export/obj/objforestwriter.h"
#include "engine/export/obj/objlodchain.h"
#include "engine/export/usd/usdforestwriter.h"
#include "engine/export/usd/usdlodchainwriter.h"
#include "engine/util/error.h"

namespace sylva::exporter {

namespace {

namespace fs = std::filesystem;

std::unique_ptr<ForestWriter> objWriter(const fs::path& path, const ForestWriterOptions& o) {
    return std::make_unique<ObjForestWriter>(path, o);
}
std::unique_ptr<ForestWriter> usdWriter(const fs::path& path, const ForestWriterOptions& o) {
    return std::make_unique<UsdForestWriter>(path, o);
}
std::unique_ptr<ForestWriter> glbWriter(const fs::path& path, const ForestWriterOptions& o) {
    if (o.assimpGltf) return std::make_unique<AssimpForestWriter>(path, SceneFormat::Glb);
    return std::make_unique<GltfForestWriter>(path, gltf::GltfFormat::Glb, o);
}
std::unique_ptr<ForestWriter> gltfWriter(const fs::path& path, const ForestWriterOptions& o) {
    if (o.assimpGltf) return std::make_unique<AssimpForestWriter>(path, SceneFormat::Gltf);
    return std::make_unique<GltfForestWriter>(path, gltf::GltfFormat::Gltf, o);
}
std::unique_ptr<ForestWriter> fbxWriter(const fs::path& path, const ForestWriterOptions&) {
    return std::make_unique<AssimpForestWriter>(path, SceneFormat::Fbx);
}

// clang-format off
constexpr std::array kFormats{
    //         format        ext      dialog name      inst.  wind                tiles  colours tables embeds forest      LOD chain
    FormatRow{Format::Obj,  ".obj",  "Wavefront OBJ", false, WindSupport::Table, false, true,   true,  false, objWriter,  writeObjLodChain},
    FormatRow{Format::Usda, ".usda", "USD text",      true,  WindSupport::None,  true,  true,   false, false, usdWriter,  writeUsdLodChain},
    FormatRow{Format::Glb,  ".glb",  "glTF binary",   true,  WindSupport::Rig,   false, true,   true,  true,  glbWriter,  writeGltfLodChain},
    FormatRow{Format::Gltf, ".gltf", "glTF",          true,  WindSupport::Rig,   false, true,   true,  false, gltfWriter, nullptr},
    FormatRow{Format::Fbx,  ".fbx",  "FBX binary",    false, WindSupport::Rig,   false, true,   true,  true,  fbxWriter,  writeFbxLodChain},
};
// clang-format on

std::string lowerExtension(const std::filesystem::path& path) {
    std::string ext = path.extension().string();
    for (char& c : ext)
        if (c >= 'A' && c <= 'Z') c = static_cast<char>(c - 'A' + 'a');
    return ext;
}

} // namespace

std::span<const FormatRow> formatTable() {
    return kFormats;
}

const FormatRow& formatRow(Format format) {
    for (const FormatRow& row : kFormats)
        if (row.format == format) return row;
    throw InvalidInput("no row for this format"); // unreachable: every Format has a row
}

const FormatRow* findFormat(const std::filesystem::path& path) {
    const std::string ext = lowerExtension(path);
    for (const FormatRow& row : kFormats)
        if (ext == row.extension) return &row;
    return nullptr;
}

const FormatRow& formatFor(const std::filesystem::path& path) {
    if (const FormatRow* row = findFormat(path)) return *row;
    throw InvalidInput("unknown scene format '" + lowerExtension(path) + "' (use " +
                       extensionList() + ")");
}

bool isFormat(const std::filesystem::path& path, Format format) {
    const FormatRow* row = findFormat(path);
    return row && row->format == format;
}

std::string extensionList(bool (*keep)(const FormatRow&), const char* separator, const char* last,
                          bool dots) {
    std::vector<const char*> kept;
    for (const FormatRow& row : kFormats)
        if (!keep || keep(row)) kept.push_back(row.extension + (dots ? 0 : 1));
    std::string out;
    for (std::size_t i = 0; i < kept.size(); ++i) {
        if (i > 0) out += i + 1 == kept.size() ? last : separator;
        out += kept[i];
    }
    return out;
}

std::string dialogFilter() {
    std::string out;
    for (const FormatRow& row : kFormats) {
        if (!out.empty()) out += ";;";
        out += std::string(row.name) + " (*" + row.extension + ")";
    }
    return out;
}

std::unique_ptr<ForestWriter> makeForestWriter(const fs::path& path,
                                               const ForestWriterOptions& options) {
    return formatFor(path).makeWriter(path, options);
}

} // namespace sylva::exporter
