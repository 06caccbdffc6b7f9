#include "engine/export/usd/usdforestwriter.h"

#include "engine/export/materials.h"
#include "engine/util/error.h"

namespace sylva::exporter {

namespace fs = std::filesystem;

UsdForestWriter::UsdForestWriter(fs::path path, const ForestWriterOptions& options) {
    usd::UsdLayerOptions layer;
    layer.species = options.species;
    layer.tile = options.tile;
    layer.tileCount = options.tileCount;
    layer.sceneKey = options.sceneKey;
    layer.compact = options.compact;
    layer.durability = options.fsync ? Durability::Durable : Durability::Atomic;
    if (const fs::path res = resourcesDir(); !res.empty()) layer.shippedTextures = res / "textures";
    mStage = std::make_unique<usd::UsdStageWriter>(std::move(path), std::move(layer));
}

void UsdForestWriter::setVariants(const std::vector<ExportVariant>& variants) {
    std::vector<usd::UsdVariant> out;
    out.reserve(variants.size());
    for (const ExportVariant& v : variants) {
        if (!v.mesh) throw InvalidInput("variant '" + v.name + "' has no mesh");
        out.push_back({v.species, v.index, v.mesh});
    }
    mStage->setVariants(std::move(out));
}

void UsdForestWriter::add(const std::vector<ExportTree>& trees) {
    std::vector<usd::UsdTree> out;
    out.reserve(trees.size());
    for (const ExportTree& t : trees)
        out.push_back({t.id, t.species, t.variant, t.position, t.rotationY, t.scale,
                       t.variant < 0 ? t.mesh : nullptr, t.cameraDistance});
    mStage->add(out, progress());
}

std::vector<fs::path> UsdForestWriter::commit() {
    return mStage->commit(progress());
}

} // namespace sylva::exporter
