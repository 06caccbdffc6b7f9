#pragma once

#include <memory>
#include <unordered_map>
#include <vector>

#include "engine/export/fbx/sceneexport.h"
#include "engine/export/forestwriter.h"

namespace sylva::exporter {

/// Trees gathered as a SceneDesc: each mesh once (by address, kept alive while gathered) with
/// its materials, one instance per tree in the order added. What Assimp's writers and the
/// instance tables read.
class SceneTrees {
public:
    void add(const std::vector<ExportTree>& trees);
    SceneDesc& scene() { return mScene; }

private:
    SceneDesc mScene;
    std::vector<std::shared_ptr<const mesh::Mesh>> mKeepAlive;
    std::unordered_map<const mesh::Mesh*, std::size_t> mMeshIndex; ///< into mScene.meshes
};

} // namespace sylva::exporter
