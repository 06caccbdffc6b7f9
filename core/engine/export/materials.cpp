#include "engine/export/materials.h"

#include "engine/export/objwriter.h"
#include "engine/util/atomicfile.h"
#include "engine/util/error.h"

#include <algorithm>
#include <cctype>
#include <string>
#include <unistd.h>

namespace sylva::exporter {

std::vector<Material> defaultMaterials(const std::string& textureFolder) {
    const std::string prefix = textureFolder.empty() ? std::string() : textureFolder + "/";
    return {
        {"bark", {0.36f, 0.27f, 0.20f}, prefix + "bark.png", false, false},
        {"leaf", {0.22f, 0.45f, 0.14f}, prefix + "leaf.png", true, true},
    };
}

std::string materialName(const mesh::Submesh& submesh) {
    if (submesh.texture.empty()) return submesh.material;
    const std::string stem = std::filesystem::path(submesh.texture).stem().string();
    std::string name;
    for (char c : stem)
        name += (std::isalnum(static_cast<unsigned char>(c)) || c == '-' || c == '_') ? c : '_';
    return name.empty() ? submesh.material : name;
}

void addMaterialsOf(const mesh::Mesh& mesh, std::vector<Material>& materials,
                    const std::string& textureFolder) {
    const std::string prefix = textureFolder.empty() ? std::string() : textureFolder + "/";
    for (const mesh::Submesh& s : mesh.submeshes) {
        if (s.texture.empty()) continue;
        const std::string name = materialName(s);
        if (std::any_of(materials.begin(), materials.end(),
                        [&](const Material& m) { return m.name == name; }))
            continue;
        const bool leaf = s.material == "leaf";
        Material m;
        m.name = name;
        m.diffuse = leaf ? glm::vec3(0.22f, 0.45f, 0.14f) : glm::vec3(0.36f, 0.27f, 0.20f);
        m.diffuseTexture = prefix + std::filesystem::path(s.texture).filename().string();
        m.twoSided = leaf;
        m.alphaMask = leaf;
        m.sourceFile = s.texture;
        materials.push_back(std::move(m));
    }
}

std::filesystem::path textureSourceOf(const Material& material,
                                      const std::filesystem::path& shippedDir) {
    if (material.diffuseTexture.empty()) return {};
    if (!material.sourceFile.empty()) return material.sourceFile;
    if (shippedDir.empty()) return {};
    return shippedDir / std::filesystem::path(material.diffuseTexture).filename();
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
        const std::filesystem::path from = textureSourceOf(m, sourceDir);
        if (from.empty() || !std::filesystem::exists(from)) continue;
        const std::filesystem::path to = exportDir / rel;
        std::error_code ec;
        std::filesystem::create_directories(to.parent_path(), ec);
        // Through a temporary and a rename: the tiles of a farm run copy the same textures into
        // one folder at the same time, and a reader never sees half a PNG.
        std::filesystem::path temp = to;
        temp += ".tmp" + std::to_string(::getpid());
        std::filesystem::copy_file(from, temp, std::filesystem::copy_options::overwrite_existing,
                                   ec);
        if (!ec) std::filesystem::rename(temp, to, ec);
        if (ec) {
            std::error_code ignored;
            std::filesystem::remove(temp, ignored);
            throw IoError("cannot copy texture to " + to.string() + ": " + ec.message());
        }
        ++copied;
    }
    return copied;
}

} // namespace sylva::exporter
