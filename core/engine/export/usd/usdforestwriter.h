#pragma once

#include <memory>

#include "engine/export/forestwriter.h"
#include "engine/export/usd/usdstagewriter.h"

namespace sylva::exporter {

/// A forest as a USD stage through UsdStageWriter: a PointInstancer per species over its
/// variants (by their species and variant numbers), unique trees as meshes; with
/// ForestWriterOptions::tileCount > 1 a tile layer for `sylva-cli compose`.
class UsdForestWriter final : public ForestWriter {
public:
    UsdForestWriter(std::filesystem::path path, const ForestWriterOptions& options);
    void setVariants(const std::vector<ExportVariant>& variants) override;
    void add(const std::vector<ExportTree>& trees) override;
    std::vector<std::filesystem::path> commit() override;
    bool writesInstances() const override { return true; }
    /// What the layer holds (for `--stats`).
    const usd::UsdLayerStats& stats() const { return mStage->stats(); }

private:
    std::unique_ptr<usd::UsdStageWriter> mStage;
};

} // namespace sylva::exporter
