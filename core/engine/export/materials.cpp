#include "engine/export/materials.h"

#include <cstdlib>

#include "engine/export/obj/objwriter.h"
#include "engine/util/atomicfile.h"
#include "engine/util/error.h"

#include <algorithm>
#include <cctype>
#include <string>
#include <unistd.h>

namespace sylva::exporter {

std::vector<Material> defaultMaterials(const std::string& textureFolder) {
    const std::string prefix = textureFolder.empty() ? std::string() : textureFolder + "/";
    std::vector<Material> out{
        {"bark", {0.36f, 0.27f, 0.20f}, prefix + "bark.png", false, false},
        {"leaf", {0.22f, 0.45f, 0.14f}, prefix + "leaf.png", true, true},
    };
    for (Material& m : out) {
        m.normalTexture = prefix + m.name + "_normal.png";
        m.roughnessTexture = prefix + m.name + "_roughness.png";
    }
    return out;
}

const std::string& texturePath(const Material& m, TextureSlot slot) {
    switch (slot) {
    case TextureSlot::Normal:
        return m.normalTexture;
    case TextureSlot::Roughness:
        return m.roughnessTexture;
    case TextureSlot::Diffuse:
        break;
    }
    return m.diffuseTexture;
}

std::string& texturePath(Material& m, TextureSlot slot) {
    return const_cast<std::string&>(texturePath(static_cast<const Material&>(m), slot));
}

std::string companionTexture(const std::string& texture, const std::string& kind) {
    if (texture.empty()) return {};
    const std::filesystem::path file(texture);
    std::string stem = file.stem().string();
    std::error_code ec;
    for (int attempt = 0; attempt < 2; ++attempt) {
        std::filesystem::path candidate = file;
        candidate.replace_filename(stem + "_" + kind + file.extension().string());
        if (std::filesystem::is_regular_file(candidate, ec)) return candidate.string();
        // A season's leaf texture uses its summer leaf's maps.
        bool stripped = false;
        for (const char* season : {"_spring", "_summer", "_autumn", "_winter"}) {
            const std::string suffix(season);
            if (stem.size() > suffix.size() &&
                stem.compare(stem.size() - suffix.size(), suffix.size(), suffix) == 0) {
                stem.resize(stem.size() - suffix.size());
                stripped = true;
                break;
            }
        }
        if (!stripped) break;
    }
    return {};
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
        if (std::string n = companionTexture(s.texture, "normal"); !n.empty()) {
            m.normalTexture = prefix + std::filesystem::path(n).filename().string();
            m.normalSourceFile = std::move(n);
        }
        if (std::string r = companionTexture(s.texture, "roughness"); !r.empty()) {
            m.roughnessTexture = prefix + std::filesystem::path(r).filename().string();
            m.roughnessSourceFile = std::move(r);
        }
        materials.push_back(std::move(m));
    }
}

std::filesystem::path textureSourceOf(const Material& material,
                                      const std::filesystem::path& shippedDir, TextureSlot slot) {
    const std::string& path = texturePath(material, slot);
    if (path.empty()) return {};
    const std::string& source = slot == TextureSlot::Normal      ? material.normalSourceFile
                                : slot == TextureSlot::Roughness ? material.roughnessSourceFile
                                                                 : material.sourceFile;
    if (!source.empty()) return source;
    if (shippedDir.empty()) return {};
    return shippedDir / std::filesystem::path(path).filename();
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
        if (!m.normalTexture.empty()) {
            out += "norm " + m.normalTexture + "\n";
            out += "map_Bump " + m.normalTexture + "\n";
        }
        if (!m.roughnessTexture.empty()) out += "map_Pr " + m.roughnessTexture + "\n";
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
    for (const Material& m : materials)
        for (TextureSlot slot : kTextureSlots) {
            if (texturePath(m, slot).empty()) continue;
            const std::filesystem::path rel(texturePath(m, slot));
            const std::filesystem::path from = textureSourceOf(m, sourceDir, slot);
            if (from.empty() || !std::filesystem::exists(from)) continue;
            const std::filesystem::path to = exportDir / rel;
            std::error_code ec;
            std::filesystem::create_directories(to.parent_path(), ec);
            // Through a temporary and a rename: the tiles of a farm run copy the same textures
            // into one folder at the same time, and a reader never sees half a PNG.
            std::filesystem::path temp = to;
            temp += ".tmp" + std::to_string(::getpid());
            std::filesystem::copy_file(from, temp,
                                       std::filesystem::copy_options::overwrite_existing, ec);
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

std::filesystem::path resourcesDir() {
    if (const char* env = std::getenv("SYLVA_RESOURCES_DIR"); env && *env) return env;
    std::error_code ec;
    namespace fs = std::filesystem;
    const fs::path exe = fs::read_symlink("/proc/self/exe", ec);
    if (!ec) {
        // build/<preset>/app/cli/sylva-cli or <build>/app/cli/sylva-cli → <source>/resources;
        // <prefix>/bin → <prefix>/share/sylva/resources
        for (const fs::path& candidate :
             {exe.parent_path() / "../../../../resources", exe.parent_path() / "../../../resources",
              exe.parent_path() / "../share/sylva/resources"}) {
            if (fs::exists(candidate / "textures", ec)) return fs::weakly_canonical(candidate, ec);
        }
    }
    return {};
}

} // namespace sylva::exporter
