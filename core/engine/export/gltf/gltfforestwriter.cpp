#include "engine/export/gltf/gltfforestwriter.h"

#include "engine/util/error.h"

namespace sylva::exporter {

namespace fs = std::filesystem;

GltfForestWriter::GltfForestWriter(fs::path path, gltf::GltfFormat format,
                                   const ForestWriterOptions& options)
    : mPath(std::move(path)), mFormat(format), mFsync(options.fsync) {}

GltfForestWriter::~GltfForestWriter() = default;

gltf::ForestGltfWriter& GltfForestWriter::writer() {
    if (!mWriter) {
        gltf::ForestGltfOptions options;
        const fs::path res = resourcesDir();
        if (!res.empty()) options.shippedTextures = res / "textures";
        options.durability = mFsync ? Durability::Durable : Durability::Atomic;
        mWriter = std::make_unique<gltf::ForestGltfWriter>(mPath, mFormat, progress(), options);
    }
    return *mWriter;
}

void GltfForestWriter::setVariants(const std::vector<ExportVariant>& variants) {
    mVariants.clear();
    for (const ExportVariant& v : variants) {
        if (!v.mesh) throw InvalidInput("variant '" + v.name + "' has no mesh");
        mVariants.push_back(writer().addVariant(v.name, *v.mesh));
    }
}

void GltfForestWriter::add(const std::vector<ExportTree>& trees) {
    gltf::ForestGltfWriter& out = writer();
    for (const ExportTree& t : trees) {
        const glm::quat rotation = glm::angleAxis(t.rotationY, glm::vec3(0, 1, 0));
        if (t.variant >= 0) {
            if (static_cast<std::size_t>(t.variant) >= mVariants.size())
                throw InvalidInput("tree '" + t.name + "' names variant " +
                                   std::to_string(t.variant) + " of " +
                                   std::to_string(mVariants.size()));
            out.addInstance(mVariants[static_cast<std::size_t>(t.variant)], t.id, t.position,
                            rotation, glm::vec3(t.scale));
            continue;
        }
        auto [it, added] = mMeshes.try_emplace(t.mesh.get(), t.mesh, -1);
        if (!added && it->second.first.expired()) it->second = {t.mesh, -1};
        if (it->second.second < 0) it->second.second = out.addTreeMesh(t.name, *t.mesh);
        out.addTree(t.name, t.id, it->second.second, t.position, rotation, glm::vec3(t.scale));
    }
}

std::vector<fs::path> GltfForestWriter::commit() {
    std::vector<fs::path> written = writer().commit();
    if (mFormat == gltf::GltfFormat::Gltf) { // .glb carries its textures inside
        const fs::path dir = mPath.parent_path().empty() ? fs::path(".") : mPath.parent_path();
        const fs::path res = resourcesDir();
        if (copyTextures(writer().materials(), res.empty() ? fs::path() : res / "textures", dir) >
            0)
            written.push_back(dir / "textures");
    }
    return written;
}

} // namespace sylva::exporter
