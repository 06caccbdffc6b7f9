#include "engine/export/fbx/scenetrees.h"

namespace sylva::exporter {

void SceneTrees::add(const std::vector<ExportTree>& trees) {
    for (const ExportTree& t : trees) {
        // Shared meshes are written once.
        const auto [it, added] = mMeshIndex.try_emplace(t.mesh.get(), mScene.meshes.size());
        if (added) {
            mKeepAlive.push_back(t.mesh);
            mScene.meshes.push_back({t.name, t.mesh.get()});
            addMaterialsOf(*t.mesh, mScene.materials);
        }
        SceneInstance instance;
        instance.name = t.name;
        instance.mesh = it->second;
        instance.position = t.position;
        instance.rotation = glm::angleAxis(t.rotationY, glm::vec3(0, 1, 0));
        instance.scale = glm::vec3(t.scale);
        mScene.instances.push_back(instance);
    }
}

} // namespace sylva::exporter
