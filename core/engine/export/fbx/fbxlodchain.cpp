#include "engine/export/fbx/fbxlodchain.h"

#include "engine/export/fbx/sceneexport.h"

namespace sylva::exporter {

namespace fs = std::filesystem;

void writeFbxLodChain(const LodChainWrite& w, GameLodFiles& files, std::vector<fs::path>& written) {
    const fs::path& dir = w.dir;
    const std::string& base = w.base;
    const GameLodOptions& options = w.options;
    const mesh::BudgetLodChain& chain = w.chain;
    const std::vector<Material>& materials = w.materials;
    Progress& progress = w.progress;
    // Assimp's FBX exporter writes no FbxLODGroup: the levels are sibling nodes named by
    // the _LOD<i> convention Unity's importer turns into an LOD Group (docs/lods.md).
    SceneDesc scene;
    scene.materials = materials;
    scene.textureSource = options.shippedTextures;
    for (std::size_t i = 0; i < chain.levels.size(); ++i) {
        scene.meshes.push_back({files.levels[i].name, &chain.levels[i].mesh});
        SceneInstance node;
        node.name = files.levels[i].name;
        node.mesh = i;
        scene.instances.push_back(node);
    }
    files.fbx = dir / (base + "_LODs.fbx");
    writeScene(files.fbx, scene, SceneFormat::Fbx);
    written.push_back(files.fbx);
    progress.checkCancelled();
}

} // namespace sylva::exporter
