#pragma once

#include "engine/export/fbx/scenetrees.h"

namespace sylva::exporter {

/// A forest through Assimp's exporter (writeScene): `.fbx` (binary FBX 7.5, repaired, textures
/// embedded), and `.glb`/`.gltf` when asked for Assimp's glTF (`--assimp-gltf`, comparisons).
/// One node per tree; trees sharing a mesh share its Assimp meshes; the whole file in memory.
class AssimpForestWriter final : public ForestWriter {
public:
    AssimpForestWriter(std::filesystem::path path, SceneFormat format);
    void setVariants(const std::vector<ExportVariant>& variants) override;
    void add(const std::vector<ExportTree>& trees) override { mTrees.add(trees); }
    std::vector<std::filesystem::path> commit() override;

private:
    std::filesystem::path mPath;
    SceneFormat mFormat;
    SceneTrees mTrees;
};

} // namespace sylva::exporter
