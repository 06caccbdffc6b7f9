#pragma once

#include <memory>
#include <unordered_map>
#include <utility>

#include "engine/export/forestwriter.h"
#include "engine/export/gltf/forestgltf.h"

namespace sylva::exporter {

/// A forest as glTF through our streaming ForestGltfWriter: each variant once with its instances
/// (EXT_mesh_gpu_instancing in 50 m cells), unique trees as mesh nodes; .glb with the textures
/// embedded, .gltf with them in `textures/`.
class GltfForestWriter final : public ForestWriter {
public:
    GltfForestWriter(std::filesystem::path path, gltf::GltfFormat format,
                     const ForestWriterOptions& options);
    ~GltfForestWriter() override;
    void setVariants(const std::vector<ExportVariant>& variants) override;
    void add(const std::vector<ExportTree>& trees) override;
    std::vector<std::filesystem::path> commit() override;
    bool writesInstances() const override { return true; }

private:
    gltf::ForestGltfWriter& writer(); ///< made on first use, with the progress set by then

    std::filesystem::path mPath;
    gltf::GltfFormat mFormat;
    bool mFsync;
    std::unique_ptr<gltf::ForestGltfWriter> mWriter;
    std::vector<int> mVariants; ///< the last setVariants list → the writer's variants
    /// Unique trees' meshes already written, by address; the weak pointer tells a mesh still
    /// shared from a new one that reuses a freed mesh's address (meshes are not kept alive).
    std::unordered_map<const mesh::Mesh*, std::pair<std::weak_ptr<const mesh::Mesh>, int>> mMeshes;
};

} // namespace sylva::exporter
