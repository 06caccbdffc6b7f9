#include "engine/export/fbx/fbxforestwriter.h"

#include "engine/util/error.h"

namespace sylva::exporter {

namespace fs = std::filesystem;

AssimpForestWriter::AssimpForestWriter(fs::path path, SceneFormat format)
    : mPath(std::move(path)), mFormat(format) {}

void AssimpForestWriter::setVariants(const std::vector<ExportVariant>& variants) {
    for (const ExportVariant& v : variants)
        if (!v.mesh) throw InvalidInput("variant '" + v.name + "' has no mesh");
}

std::vector<fs::path> AssimpForestWriter::commit() {
    mTrees.scene().textureSource = resourcesDir() / "textures";
    writeScene(mPath, mTrees.scene(), mFormat, progress());
    std::vector<fs::path> written{mPath};
    if (mFormat == SceneFormat::Gltf) { // .glb and .fbx carry their textures inside
        const fs::path dir = mPath.parent_path().empty() ? fs::path(".") : mPath.parent_path();
        const fs::path res = resourcesDir();
        if (copyTextures(mTrees.scene().materials, res.empty() ? fs::path() : res / "textures",
                         dir) > 0)
            written.push_back(dir / "textures");
    }
    return written;
}

} // namespace sylva::exporter
