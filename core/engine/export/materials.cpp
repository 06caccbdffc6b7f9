#include "engine/export/materials.h"

#include "engine/export/objwriter.h"
#include "engine/util/atomicfile.h"
#include "engine/util/error.h"

namespace sylva::exporter {

std::vector<Material> defaultMaterials(const std::string& textureFolder) {
    const std::string prefix = textureFolder.empty() ? std::string() : textureFolder + "/";
    return {
        {"bark", {0.36f, 0.27f, 0.20f}, prefix + "bark.png", false, false},
        {"leaf", {0.22f, 0.45f, 0.14f}, prefix + "leaf.png", true, true},
    };
}

namespace {
void appendNumber(std::string& out, double v) {
    char buf[48];
    out.append(buf, formatFixed(buf, v, 4));
}
} // namespace

std::string formatMtl(const std::vector<Material>& materials) {
    std::string out = "# Sylva materials\n";
    for (const Material& m : materials) {
        out += "\nnewmtl " + m.name + "\n";
        out += "Ka 0 0 0\nKd ";
        appendNumber(out, m.diffuse.x);
        out += ' ';
        appendNumber(out, m.diffuse.y);
        out += ' ';
        appendNumber(out, m.diffuse.z);
        out += "\nKs 0.02 0.02 0.02\nNs 10\nd 1\nillum 2\n";
        if (!m.diffuseTexture.empty()) {
            out += "map_Kd " + m.diffuseTexture + "\n";
            if (m.alphaMask) out += "map_d " + m.diffuseTexture + "\n";
        }
    }
    return out;
}

void writeMtlFile(const std::filesystem::path& path, const std::vector<Material>& materials) {
    writeFileAtomically(path, formatMtl(materials));
}

std::size_t copyTextures(const std::vector<Material>& materials,
                         const std::filesystem::path& sourceDir,
                         const std::filesystem::path& exportDir) {
    std::size_t copied = 0;
    for (const Material& m : materials) {
        if (m.diffuseTexture.empty()) continue;
        const std::filesystem::path rel(m.diffuseTexture);
        const std::filesystem::path from = sourceDir / rel.filename();
        if (!std::filesystem::exists(from)) continue;
        const std::filesystem::path to = exportDir / rel;
        std::error_code ec;
        std::filesystem::create_directories(to.parent_path(), ec);
        std::filesystem::copy_file(from, to, std::filesystem::copy_options::overwrite_existing, ec);
        if (ec) throw IoError("cannot copy texture to " + to.string() + ": " + ec.message());
        ++copied;
    }
    return copied;
}

} // namespace sylva::exporter
