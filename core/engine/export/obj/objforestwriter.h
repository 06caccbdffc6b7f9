#pragma once

#include <memory>

#include "engine/export/forestwriter.h"
#include "engine/export/materials.h"
#include "engine/export/obj/objwriter.h"

namespace sylva::exporter {

/// A forest as OBJ: every tree an object (instances merged, no instancing), streamed batch by
/// batch; `<stem>.mtl` and the textures, the species' own included, in `textures/` beside it.
class ObjForestWriter final : public ForestWriter {
public:
    ObjForestWriter(std::filesystem::path path, const ForestWriterOptions& options);
    void setVariants(const std::vector<ExportVariant>& variants) override;
    void add(const std::vector<ExportTree>& trees) override;
    std::vector<std::filesystem::path> commit() override;

private:
    std::filesystem::path mPath;
    std::unique_ptr<ObjStreamWriter> mWriter;
    std::vector<Material> mMaterials = defaultMaterials();
};

} // namespace sylva::exporter
