#include "engine/export/usd/usdcompose.h"

#include "engine/export/usd/usdformat.h"
#include "engine/util/atomicfile.h"
#include "engine/util/error.h"

#include <algorithm>
#include <fstream>
#include <map>

namespace sylva::exporter::usd {

namespace fs = std::filesystem;

namespace {

// The value after `<type> <key> = ` in the header text, up to the end of its line.
std::string headerValue(const std::string& header, const std::string& key) {
    const std::string needle = " " + key + " = ";
    const std::size_t at = header.find(needle);
    if (at == std::string::npos) return {};
    const std::size_t begin = at + needle.size();
    std::string value = header.substr(begin, header.find('\n', begin) - begin);
    if (value.size() >= 2 && value.front() == '"' && value.back() == '"')
        value = value.substr(1, value.size() - 2);
    return value;
}

int headerInt(const std::string& header, const std::string& key, const fs::path& layer) {
    const std::string value = headerValue(header, key);
    try {
        std::size_t used = 0;
        const int v = std::stoi(value, &used);
        if (used == value.size()) return v;
    } catch (const std::exception&) {
    }
    throw InvalidInput(layer.string() + ": not a Sylva tile layer (no " + key +
                       "; write tiles with 'sylva-cli forest --tile i/N -o tile.usda')");
}

} // namespace

TileHeader readTileHeader(const fs::path& layer) {
    std::ifstream in(layer, std::ios::binary);
    if (!in) throw IoError("cannot read " + layer.string());
    std::string header(4096, '\0');
    in.read(header.data(), static_cast<std::streamsize>(header.size()));
    header.resize(static_cast<std::size_t>(in.gcount()));
    if (header.rfind("#usda 1.0", 0) != 0)
        throw InvalidInput(layer.string() + ": not a USD text layer (no '#usda 1.0' line)");
    // Only the layer's metadata block, not prims that might contain the same words.
    header = header.substr(0, header.find("\ndef "));
    TileHeader h;
    h.tile = headerInt(header, "sylvaTile", layer);
    h.tiles = headerInt(header, "sylvaTiles", layer);
    h.scene = headerValue(header, "sylvaScene");
    if (h.tiles < 1 || h.tile < 1 || h.tile > h.tiles)
        throw InvalidInput(layer.string() + ": tile " + std::to_string(h.tile) + " of " +
                           std::to_string(h.tiles) + " is not a tile");
    return h;
}

void writeRootLayer(const fs::path& root, const std::vector<fs::path>& tiles) {
    if (tiles.empty()) throw InvalidInput("no tile layers to compose");
    std::map<int, fs::path> byTile;
    TileHeader first;
    for (const fs::path& tile : tiles) {
        const TileHeader h = readTileHeader(tile);
        if (byTile.empty()) {
            first = h;
        } else if (h.tiles != first.tiles || h.scene != first.scene) {
            throw InvalidInput(tile.string() + " is tile " + std::to_string(h.tile) + "/" +
                               std::to_string(h.tiles) + " of another run than " +
                               tiles.front().string() + " (" + std::to_string(first.tile) + "/" +
                               std::to_string(first.tiles) + ")");
        }
        if (!byTile.emplace(h.tile, tile).second)
            throw InvalidInput("tile " + std::to_string(h.tile) + " is given twice: " +
                               byTile[h.tile].string() + " and " + tile.string());
    }
    std::string missing;
    for (int t = 1; t <= first.tiles; ++t)
        if (!byTile.count(t)) missing += (missing.empty() ? "" : ", ") + std::to_string(t);
    if (!missing.empty())
        throw InvalidInput("tiles missing of " + std::to_string(first.tiles) + ": " + missing);

    const fs::path rootDir = fs::absolute(root).lexically_normal().parent_path();
    std::string out =
        "#usda 1.0\n(\n    customLayerData = {\n        string generator = \"Sylva\"\n";
    if (!first.scene.empty()) out += "        string sylvaScene = " + usdString(first.scene) + "\n";
    out += "        int sylvaTiles = " + std::to_string(first.tiles) + "\n    }\n";
    out += "    defaultPrim = \"Forest\"\n    metersPerUnit = 1\n";
    out += "    subLayers = [\n";
    bool firstLine = true;
    for (const auto& [t, tile] : byTile) {
        std::string rel =
            fs::absolute(tile).lexically_normal().lexically_relative(rootDir).string();
        if (rel.empty()) rel = fs::absolute(tile).string();
        if (rel.find('@') != std::string::npos)
            throw InvalidInput(tile.string() + ": a USD asset path cannot contain '@'");
        out += firstLine ? "        @" : ",\n        @";
        out += rel + "@";
        firstLine = false;
    }
    out += "\n    ]\n    upAxis = \"Y\"\n)\n\n";
    if (const fs::path dir = root.parent_path(); !dir.empty()) {
        std::error_code ec;
        fs::create_directories(dir, ec);
        if (ec) throw IoError("cannot create " + dir.string() + ": " + ec.message());
    }
    writeFileAtomically(root, out);
}

} // namespace sylva::exporter::usd
