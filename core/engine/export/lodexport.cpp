#include "engine/export/lodexport.h"

#include <system_error>

#include "engine/export/materials.h"
#include "engine/export/objwriter.h"
#include "engine/export/sceneexport.h"
#include "engine/util/error.h"

namespace sylva::exporter {

std::string fileSafeName(const std::string& name) {
    std::string s = name;
    for (char& c : s) {
        const bool ok = (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') ||
                        (c >= '0' && c <= '9') || c == '-' || c == '_';
        if (!ok) c = '_';
    }
    return s;
}

LodChainFiles writeLodChain(const std::filesystem::path& dir, const std::string& species,
                            const std::vector<mesh::LodChainLevel>& chain,
                            const LodExportOptions& options) {
    if (species.empty()) throw InvalidInput("LOD export needs a species name");
    if (chain.empty()) throw InvalidInput("LOD export needs at least one level");
    const std::string base = fileSafeName(species);
    std::error_code ec;
    std::filesystem::create_directories(dir, ec);
    if (ec) throw IoError("cannot create " + dir.string() + ": " + ec.message());

    LodChainFiles files;
    std::vector<Material> materials = defaultMaterials();
    for (const mesh::LodChainLevel& level : chain)
        addMaterialsOf(level.mesh, materials);
    for (std::size_t i = 0; i < chain.size(); ++i) {
        LodFileLevel level;
        level.name = base + "_LOD" + std::to_string(i);
        level.distance = chain[i].distance;
        level.triangles = chain[i].mesh.triangleCount();
        level.vertices = chain[i].mesh.vertexCount();
        if (options.obj) level.objPath = dir / (level.name + ".obj");
        files.levels.push_back(level);
    }
    if (options.obj) {
        files.mtlPath = dir / (base + ".mtl");
        writeMtlFile(files.mtlPath, materials);
        ObjOptions obj;
        obj.mtllib = files.mtlPath.filename().string();
        for (std::size_t i = 0; i < chain.size(); ++i)
            writeObjFile(files.levels[i].objPath, {{files.levels[i].name, &chain[i].mesh}}, obj);
    }
    if (options.glb) {
        SceneDesc scene;
        scene.materials = materials;
        scene.textureSource = options.textureSource;
        for (std::size_t i = 0; i < chain.size(); ++i) {
            scene.meshes.push_back({files.levels[i].name, &chain[i].mesh});
            SceneInstance node;
            node.name = files.levels[i].name;
            node.mesh = i;
            scene.instances.push_back(node);
        }
        files.glbPath = dir / (base + "_LODs.glb");
        writeScene(files.glbPath, scene, SceneFormat::Glb);
    }
    if (!options.textureSource.empty()) copyTextures(materials, options.textureSource, dir);
    return files;
}

LodChainFiles writeLodChain(const std::filesystem::path& dir, const std::string& species,
                            const skel::Skeleton& skeleton, const mesh::TreeMeshSettings& settings,
                            const LodExportOptions& options, Progress& progress) {
    const std::vector<mesh::LodChainLevel> chain =
        mesh::buildLodChain(skeleton, settings, progress);
    progress.checkCancelled();
    return writeLodChain(dir, species, chain, options);
}

} // namespace sylva::exporter
