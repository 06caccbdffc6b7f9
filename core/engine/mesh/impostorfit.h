#pragma once

#include <vector>

#include "engine/mesh/impostor.h"
#include "engine/mesh/mesh.h"

namespace sylva::mesh {

/// How well an impostor stands in for the mesh it replaces on screen (issue 40: a tree is an
/// impostor only where its impostor matches its mesh). The measure is test_lodchain's: from
/// \p views directions around the tree (every other one 20 degrees above the horizon, as
/// silhouetteIoU), the pixels of the \p pixels² square around the impostor's bounding sphere
/// that any of \p reference's triangles overlaps (conservative rasterisation) against the
/// pixels renderImpostor() gives any coverage, each closed by a 1-pixel disc (the gaps between
/// leaves count as crown, as they do for an eye at that size); the mean IoU of the views.
double impostorSilhouetteIoU(const Mesh& reference, const Impostor& impostor, int pixels,
                             int views = 8);

/// Where an impostor may take over from its mesh: the largest tree height on screen, at most
/// \p startHeightPx, where impostorSilhouetteIoU() is at least \p minIoU, searched down in
/// steps of a fifth to \p floorHeightPx. Where no height reaches it (the alder's speckled
/// crown, the date palm's fronds: 0.84-0.88 at best), the height where the IoU is highest:
/// switching later than that would cost meshes without bringing the silhouettes closer.
struct ImpostorSwitch {
    double heightPx = 0.0; ///< the tree's height on screen under which the impostor is drawn
    double iou = 1.0;      ///< impostorSilhouetteIoU() there
    bool met = true;       ///< iou >= minIoU (false: heightPx is where it was best)
    /// Each height tried, largest first, with its IoU.
    std::vector<std::pair<double, double>> tried;
};
/// \p treeHeight: the tree's height (m) that a height on screen refers to (its bounds).
/// \throw InvalidInput for a non-positive height or sizes out of 1..4096 px.
ImpostorSwitch impostorSwitchHeight(const Mesh& reference, const Impostor& impostor,
                                    double treeHeight, double startHeightPx, double minIoU = 0.9,
                                    double floorHeightPx = 24.0, int views = 8);

} // namespace sylva::mesh
