#include "engine/export/treeexport.h"

#include "engine/export/materials.h"
#include "engine/util/atomicfile.h"
#include "engine/util/error.h"

#include <glm/gtc/matrix_transform.hpp>

#include <cctype>
#include <cstdlib>
#include <unistd.h>

namespace sylva::exporter {

namespace fs = std::filesystem;

std::string objectNameFor(const std::string& speciesName) {
    std::string out;
    for (char c : speciesName)
        out += (std::isalnum(static_cast<unsigned char>(c)) || c == '-') ? c : '_';
    return out.empty() ? std::string("tree") : out;
}

fs::path resourcesDir() {
    if (const char* env = std::getenv("SYLVA_RESOURCES_DIR"); env && *env) return env;
    std::error_code ec;
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

TreeExporter::TreeExporter(fs::path path, ObjChoices obj) : mPath(std::move(path)), mChoices(obj) {
    // Like other exporters, write into a folder that does not exist yet (out/forest.obj).
    if (const fs::path dir = mPath.parent_path(); !dir.empty()) {
        std::error_code ec;
        fs::create_directories(dir, ec);
        if (ec) throw IoError("cannot create " + dir.string() + ": " + ec.message());
    }
    std::string ext = mPath.extension().string();
    for (char& c : ext)
        c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    mObj = ext == ".obj";
    if (ext == ".usda") {
        usd::UsdLayerOptions options;
        options.compact = obj.compact;
        options.durability = obj.fsync ? Durability::Durable : Durability::Atomic;
        if (const fs::path res = resourcesDir(); !res.empty())
            options.shippedTextures = res / "textures";
        mObj = false;
        mUsd = std::make_unique<usd::UsdStageWriter>(mPath, std::move(options));
    } else if (mObj) {
        ObjOptions options = obj.compact ? ObjOptions::compact() : ObjOptions{};
        options.mtllib = mPath.stem().string() + ".mtl";
        options.fsync = obj.fsync;
        mObjWriter = std::make_unique<ObjStreamWriter>(mPath, options);
    } else {
        const SceneFormat format = sceneFormatFor(mPath); // rejects unknown extensions first
        mGltf = format == SceneFormat::Glb || format == SceneFormat::Gltf;
    }
}

TreeExporter::~TreeExporter() = default;

gltf::ForestGltfWriter& TreeExporter::gltfWriter() {
    if (!mGltfWriter) {
        gltf::ForestGltfOptions options;
        const fs::path res = resourcesDir();
        if (!res.empty()) options.shippedTextures = res / "textures";
        options.durability = mChoices.fsync ? Durability::Durable : Durability::Atomic;
        mGltfWriter = std::make_unique<gltf::ForestGltfWriter>(
            mPath,
            sceneFormatFor(mPath) == SceneFormat::Glb ? gltf::GltfFormat::Glb
                                                      : gltf::GltfFormat::Gltf,
            *mProgress, options);
    }
    return *mGltfWriter;
}

namespace {
// The species of a forest's tree or variant from its name ("<species>_<id>",
// "<species>_v<index>"), and the variant's index; the whole name when it has no such suffix.
std::string speciesOfName(const std::string& name, const std::string& suffix) {
    const std::size_t n = suffix.size();
    if (name.size() > n && name.compare(name.size() - n, n, suffix) == 0)
        return name.substr(0, name.size() - n);
    return name;
}
std::uint32_t variantIndexOfName(const std::string& name, std::uint32_t fallback) {
    const std::size_t at = name.rfind("_v");
    if (at == std::string::npos || at + 2 >= name.size()) return fallback;
    std::uint32_t k = 0;
    for (std::size_t i = at + 2; i < name.size(); ++i) {
        if (name[i] < '0' || name[i] > '9') return fallback;
        k = k * 10 + static_cast<std::uint32_t>(name[i] - '0');
    }
    return k;
}
} // namespace

void TreeExporter::addVariants(const std::vector<ExportVariant>& variants) {
    if (mUsd) {
        std::vector<usd::UsdVariant> out;
        mUsdVariantSpecies.clear();
        for (std::size_t i = 0; i < variants.size(); ++i) {
            const ExportVariant& v = variants[i];
            if (!v.mesh) throw InvalidInput("variant '" + v.name + "' has no mesh");
            const std::uint32_t k = variantIndexOfName(v.name, static_cast<std::uint32_t>(i));
            // Built by appending: GCC 12 reports a false -Wrestrict on "_v" + std::string&&.
            std::string suffix("_v");
            suffix.append(std::to_string(k));
            const std::uint32_t species = mUsd->speciesIndex(speciesOfName(v.name, suffix));
            mUsdVariantSpecies.push_back(species);
            out.push_back({species, k, v.mesh});
        }
        mUsd->setVariants(std::move(out));
        return;
    }
    mGltfVariants.clear();
    for (const ExportVariant& v : variants) {
        if (!v.mesh) throw InvalidInput("variant '" + v.name + "' has no mesh");
        if (mGltf) mGltfVariants.push_back(gltfWriter().addVariant(v.name, *v.mesh));
    }
}

void TreeExporter::add(const std::vector<ExportTree>& trees) {
    if (mUsd) {
        std::vector<usd::UsdTree> out;
        out.reserve(trees.size());
        for (const ExportTree& t : trees) {
            usd::UsdTree u{t.id, 0, t.variant, t.position, t.rotationY, t.scale, nullptr};
            if (t.variant >= 0 && static_cast<std::size_t>(t.variant) < mUsdVariantSpecies.size()) {
                u.species = mUsdVariantSpecies[static_cast<std::size_t>(t.variant)];
            } else {
                std::string suffix("_");
                suffix.append(std::to_string(t.id));
                u.species = mUsd->speciesIndex(speciesOfName(t.name, suffix));
                u.mesh = t.mesh;
            }
            out.push_back(std::move(u));
        }
        mUsd->add(out, *mProgress);
        return;
    }
    if (mGltf) {
        gltf::ForestGltfWriter& out = gltfWriter();
        for (const ExportTree& t : trees) {
            const glm::quat rotation = glm::angleAxis(t.rotationY, glm::vec3(0, 1, 0));
            if (t.variant >= 0) {
                if (static_cast<std::size_t>(t.variant) >= mGltfVariants.size())
                    throw InvalidInput("tree '" + t.name + "' names variant " +
                                       std::to_string(t.variant) + " of " +
                                       std::to_string(mGltfVariants.size()));
                out.addInstance(mGltfVariants[static_cast<std::size_t>(t.variant)], t.id,
                                t.position, rotation, glm::vec3(t.scale));
                continue;
            }
            auto [it, added] = mGltfMeshes.try_emplace(t.mesh.get(), t.mesh, -1);
            if (!added && it->second.first.expired()) it->second = {t.mesh, -1};
            if (it->second.second < 0) it->second.second = out.addTreeMesh(t.name, *t.mesh);
            out.addTree(t.name, t.id, it->second.second, t.position, rotation, glm::vec3(t.scale));
        }
    }
    if (mObj) {
        std::vector<ObjObject> objects;
        objects.reserve(trees.size());
        for (const ExportTree& t : trees) {
            addMaterialsOf(*t.mesh, mObjMaterials);
            glm::mat4 m = glm::translate(glm::mat4(1.0f), t.position);
            m = glm::rotate(m, t.rotationY, glm::vec3(0, 1, 0));
            m = glm::scale(m, glm::vec3(t.scale));
            objects.push_back({t.name, t.mesh.get(), m});
        }
        mObjWriter->add(objects);
    }
    if ((!mObj && !mGltf) || mInstanceTables) {
        for (const ExportTree& t : trees) {
            // Shared meshes are written once.
            const auto [it, added] = mMeshIndex.try_emplace(t.mesh.get(), mScene.meshes.size());
            if (added) {
                mKeepAlive.push_back(t.mesh);
                mScene.meshes.push_back({t.name, t.mesh.get()});
            }
            if (added) addMaterialsOf(*t.mesh, mScene.materials);
            const std::size_t meshIndex = it->second;
            SceneInstance instance;
            instance.name = t.name;
            instance.mesh = meshIndex;
            instance.position = t.position;
            instance.rotation = glm::angleAxis(t.rotationY, glm::vec3(0, 1, 0));
            instance.scale = glm::vec3(t.scale);
            mScene.instances.push_back(instance);
        }
    }
}

std::vector<fs::path> TreeExporter::commit() {
    mProgress->checkCancelled();
    if (mUsd) return mUsd->commit(*mProgress);
    std::vector<fs::path> written{mPath};
    const SceneFormat sceneFormat = mObj ? SceneFormat::Glb : sceneFormatFor(mPath);
    const fs::path dir = mPath.parent_path().empty() ? fs::path(".") : mPath.parent_path();
    if (mObj) {
        const fs::path mtl = dir / (mPath.stem().string() + ".mtl");
        writeMtlFile(mtl, mObjMaterials);
        mObjWriter->commit();
        written.push_back(mtl);
    } else if (mGltf) {
        written = gltfWriter().commit();
    } else {
        mScene.textureSource = resourcesDir() / "textures";
        writeScene(mPath, mScene, sceneFormat, *mProgress);
    }
    // OBJ and text glTF reference their textures beside them; .glb and .fbx carry them inside.
    if (mObj || sceneFormat == SceneFormat::Gltf) {
        const fs::path res = resourcesDir();
        if (copyTextures(mObj    ? mObjMaterials
                         : mGltf ? gltfWriter().materials()
                                 : mScene.materials,
                         res.empty() ? fs::path() : res / "textures", dir) > 0)
            written.push_back(dir / "textures");
    }
    if (mInstanceTables) {
        const fs::path json = dir / (mPath.stem().string() + ".instances.json");
        const fs::path csv = dir / (mPath.stem().string() + ".instances.csv");
        writeFileAtomically(json, formatInstancesJson(mScene));
        writeFileAtomically(csv, formatInstancesCsv(mScene));
        written.push_back(json);
        written.push_back(csv);
    }
    return written;
}

} // namespace sylva::exporter
