#pragma once

#include <filesystem>
#include <memory>
#include <optional>
#include <string>

#include <QString>

#include "engine/export/lodchainexport.h"
#include "engine/util/progress.h"
#include "ui/generation/exportshown.h"

namespace sylva::ui {

/// What File ▸ Export LOD chain… makes a chain of: a species preview's species (grown again from
/// its file, exactly as `sylva-cli lods <file>` grows it), or the one tree selected in the
/// document (its skeleton and meshing settings as the forest made them: adapted, seeded).
struct LodChainSource {
    std::string name;    ///< the files' stem: the species file's name, or "<species>_tree<id>"
    QString speciesFile; ///< a preview: the species file; else empty
    std::shared_ptr<const skel::Skeleton> skeleton;
    std::shared_ptr<const mesh::TreeMeshSettings> settings;
};

/// The source of \p shown: its species for a preview, else the document's selected tree when
/// exactly one tree is selected and the generation kept what it was made from. nullopt
/// otherwise (nothing to export; the action is then disabled).
std::optional<LodChainSource> lodChainSource(const ShownScene& shown);

/// Writes the chain of \p source into \p dir as `sylva-cli lods` writes it (every file kind,
/// default budgets and impostor, Sylva's shipped textures for materials without their own):
/// exporter::writeTreeLodChain. Runs on the calling thread (seconds: the levels' search and
/// the impostor's 64 views); \p progress reports "grow", "levels", "impostor", "writing" and
/// cancels. \throw InvalidInput, IoError, Cancelled (nothing is left written).
exporter::GameLodFiles exportLodChain(const std::filesystem::path& dir,
                                      const LodChainSource& source,
                                      Progress& progress = noProgress());

} // namespace sylva::ui
