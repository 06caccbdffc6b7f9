#pragma once

#include <cstdint>
#include <memory>
#include <optional>

#include <QString>

#include "engine/mesh/treemesh.h"
#include "engine/skeleton/skeleton.h"
#include "engine/util/progress.h"

namespace sylva::doc {

/// One tree of a species file as `sylva-cli lods` grows it: the skeleton of the graph's skeleton
/// source and the meshing settings of its tube_mesh output.
struct SpeciesTree {
    std::shared_ptr<const skel::Skeleton> skeleton;
    mesh::TreeMeshSettings settings;
};

/// Loads the species or grammar at \p path and grows it with \p seed (none: the generators'
/// own). The CLI's `lods` and the editor's File ▸ Export LOD chain share it.
/// \throw InvalidInput (no tube_mesh output, no skeleton), IoError, Cancelled.
SpeciesTree growSpeciesTree(const QString& path, std::optional<std::uint64_t> seed,
                            Progress& progress = noProgress());

} // namespace sylva::doc
